import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CoverWindows, skinAreas } from '#strata/regions/skin-areas.js';
import { area, intersection } from '#strata/geometry/clip.js';
import type { ExPolygon } from '#strata/geometry/types.js';

const sq = (x0: number, y0: number, s: number): ExPolygon => ({
  outer: [
    { x: x0, y: y0 },
    { x: x0 + s, y: y0 },
    { x: x0 + s, y: y0 + s },
    { x: x0, y: y0 + s },
  ],
  holes: [],
});

test('cover windows equal the brute-force intersection of every window, for any count', () => {
  // squares sliding by 1 mm per layer
  const sections = Array.from({ length: 12 }, (_, i) => [sq(i * 1000, 0, 10000)]);
  for (const count of [1, 2, 3, 4, 5]) {
    const w = new CoverWindows((i) => sections[i] ?? [], count, sections.length);
    for (let a = -2; a < sections.length; a++) {
      let brute: ExPolygon[] | null = null;
      if (a >= 0 && a + count <= sections.length) {
        for (let k = a; k < a + count; k++) brute = brute === null ? sections[k] : intersection(brute, sections[k]);
      }
      assert.equal(Math.round(area(w.window(a))), Math.round(area(brute ?? [])), `count ${count}, window ${a}`);
    }
  }
});

test('top skin where the layers above lack material, none where it is covered, bottom wins over top', () => {
  const inner = [sq(0, 0, 10000)];
  const half = [sq(0, 0, 5000)];
  const full = [sq(-1000, -1000, 12000)];
  const covered = skinAreas(inner, full, full, 4, 4, 400);
  assert.equal(covered.top.length + covered.bottom.length, 0);
  const top = skinAreas(inner, half, full, 4, 4, 400);
  assert.equal(Math.round(area(top.top)), 100e6 - 25e6);
  assert.equal(top.bottom.length, 0);
  const both = skinAreas(inner, [], [], 4, 4, 400);
  assert.equal(both.top.length, 0);
  assert.equal(Math.round(area(both.bottom)), 100e6);
});
