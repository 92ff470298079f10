import { test } from 'node:test';
import assert from 'node:assert/strict';
import { fuzzyLoop, fuzzyWalls } from '#strata/paths/fuzzy-skin.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import type { Pt } from '#strata/geometry/types.js';
import type { WallSet } from '#strata/regions/types.js';

/** A circle of radius r µm through n points, counter-clockwise (or clockwise: a hole). */
const circle = (r: number, n: number, clockwise = false): Pt[] =>
  Array.from({ length: n }, (_, i) => {
    const a = ((clockwise ? -1 : 1) * 2 * Math.PI * i) / n;
    return { x: Math.round(r * Math.cos(a)), y: Math.round(r * Math.sin(a)) };
  });
const radii = (loop: readonly Pt[]) => loop.map((p) => Math.hypot(p.x, p.y));

test('a fuzzy loop: points about the point distance apart, each moved in or out by up to the thickness, all of it used', () => {
  const R = 10_000,
    t = 300,
    spacing = 800;
  const loop = circle(R, 360);
  const out = fuzzyLoop(loop, null, t, spacing, 12345)!;
  const length = 2 * Math.PI * R;
  // gaps of ¾ to 1¼ of the distance: about length / spacing points
  assert.ok(
    out.points.length > (length / spacing) * 0.85 && out.points.length < (length / spacing) * 1.15,
    `${out.points.length} points`,
  );
  const r = radii(out.points);
  const dev = r.map((x) => x - R);
  const sag = R * (1 - Math.cos(Math.PI / 360)); // the chords' distance inside the circle
  for (const d of dev) assert.ok(d <= t + 1 && d >= -t - sag - 1, `deviation ${d} µm within ±${t}`);
  assert.ok(Math.max(...dev) > 0.85 * t && Math.min(...dev) < -0.85 * t, 'the whole thickness is used, both ways');
  const mean = dev.reduce((a, b) => a + b, 0) / dev.length;
  assert.ok(Math.abs(mean) < 0.15 * t, `in and out alike: mean ${mean.toFixed(0)} µm`);
  for (let i = 0; i < out.points.length; i++) {
    const a = out.points[i],
      b = out.points[(i + 1) % out.points.length];
    assert.ok(Math.hypot(b.x - a.x, b.y - a.y) < 1.25 * spacing + 2 * t + 2, 'no gap wider than the spacing allows');
  }
  assert.deepEqual(fuzzyLoop(loop, null, t, spacing, 12345), out, 'the same seed, the same texture');
  assert.notDeepEqual(fuzzyLoop(loop, null, t, spacing, 54321), out);
});

test('a fuzzy loop keeps the widths of a variable-width wall along it', () => {
  const loop: Pt[] = [
    { x: 0, y: 0 },
    { x: 10_000, y: 0 },
    { x: 10_000, y: 10_000 },
    { x: 0, y: 10_000 },
  ];
  const widths = Float64Array.from([0.4, 0.6, 0.6, 0.4]);
  const out = fuzzyLoop(loop, widths, 100, 500, 7)!;
  assert.equal(out.widths!.length, out.points.length);
  for (let i = 0; i < out.points.length; i++) {
    const p = out.points[i];
    // along the bottom edge the width grows from 0.4 to 0.6, along the right edge it stays 0.6
    if (Math.abs(p.y) <= 100 && p.x > 0 && p.x < 10_000)
      assert.ok(Math.abs(out.widths![i] - (0.4 + (0.2 * p.x) / 10_000)) < 0.01, `${p.x}: ${out.widths![i]}`);
    if (Math.abs(p.x - 10_000) <= 100 && p.y > 100 && p.y < 9_900) assert.ok(Math.abs(out.widths![i] - 0.6) < 1e-9);
  }
});

test('fuzzyWalls: the outer wall only, holes with `all`, never on the first layer, seeded by the layer and the loop', () => {
  const outer = circle(10_000, 200);
  const hole = circle(3_000, 60, true);
  const set = (wall: number): WallSet => ({ role: 'wall', wall, closed: true, paths: [outer, hole], widths: null });
  const off = resolveConfig({});
  const outerOnly = resolveConfig({ fuzzySkin: 'outer' });
  const all = resolveConfig({ fuzzySkin: 'all' });
  const s0 = set(0);
  assert.equal(fuzzyWalls(s0, off, 5), s0, 'off: the set as it is');
  assert.equal(fuzzyWalls(s0, all, 0), s0, 'the first layer stays smooth');
  const s1 = set(1);
  assert.equal(fuzzyWalls(s1, all, 5), s1, 'inner walls stay smooth');
  const gap: WallSet = { ...s0, role: 'wall-gap' };
  assert.equal(fuzzyWalls(gap, all, 5), gap);
  const a = fuzzyWalls(s0, outerOnly, 5);
  assert.notEqual(a.paths[0], outer);
  assert.equal(a.paths[1], hole, 'outer: holes stay smooth');
  assert.deepEqual(s0.paths, [outer, hole], "the regions' own arrays are left as they were");
  const b = fuzzyWalls(s0, all, 5);
  assert.notEqual(b.paths[1], hole, 'all: holes too');
  assert.deepEqual(fuzzyWalls(set(0), all, 5), b, 'the same layer and wall: the same texture');
  assert.notDeepEqual(fuzzyWalls(set(0), all, 6).paths[0], b.paths[0], 'another layer: another texture');
});
