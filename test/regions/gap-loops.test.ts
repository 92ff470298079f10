import { test } from 'node:test';
import assert from 'node:assert/strict';
import { gapLoops, loopBeads } from '#strata/regions/gap-loops.js';
import { area, difference, opening, strokeArea, union } from '#strata/geometry/clip.js';
import type { ExPolygon } from '#strata/geometry/types.js';

const W = 400;
const rect = (x0: number, y0: number, x1: number, y1: number): ExPolygon => ({
  outer: [
    { x: x0, y: y0 },
    { x: x1, y: y0 },
    { x: x1, y: y1 },
    { x: x0, y: y1 },
  ],
  holes: [],
});

/** Share of `judged` (default: all of `region`) that the gap loops of `region` leave bare. */
function bareShare(region: ExPolygon[], judged = region): number {
  let bare = judged;
  for (const g of gapLoops(region, W)) bare = difference(bare, strokeArea([], [g.loop], g.widthUm));
  return area(opening(bare, 10)) / area(judged);
}

test('a strip with a hairline sliver attached is filled edge to edge (the sliver does not shrink its width)', () => {
  // the middle of a thin rib between its outer walls, joined by a 60 µm sliver to the rest of the part
  const gap = union([rect(0, 0, 5_000, 750)], [rect(5_000, 300, 25_000, 360)]);
  assert.equal(gap.length, 1);
  const strip = [rect(0, 0, 5_000, 750)];
  assert.ok(bareShare(gap, strip) < 0.01, `${bareShare(gap, strip)}`);
  for (const g of gapLoops(gap, W)) assert.ok(Math.abs(g.widthUm - 375) < 10, `bead ${g.widthUm}`);
});

test('a wedge gets more loops towards its wide end', () => {
  const wedge: ExPolygon = {
    outer: [
      { x: 0, y: 0 },
      { x: 6_000, y: 0 },
      { x: 0, y: 600 },
    ],
    holes: [],
  };
  const loops = gapLoops([wedge], W);
  assert.ok(loops.length >= 2, `${loops.length} loops`);
  // what stays bare is mostly its tip, thinner than 0.3 line widths (4 % of it); one loop would leave 15 %
  assert.ok(bareShare([wedge]) < 0.1, `${bareShare([wedge])}`);
});

test('hairlines and pieces wider than two line widths get nothing', () => {
  assert.deepEqual(gapLoops([rect(0, 0, 10_000, 100)], W), []);
  assert.deepEqual(gapLoops([rect(0, 0, 10_000, 1_000)], W), []);
});

test('loopBeads covers what strokeArea does along loops (a square, and a C whose bead closes over its mouth)', () => {
  const square = rect(0, 0, 3000, 2000).outer;
  // a C: 3 mm square less a 1 mm slot from the right, its mouth 150 µm wide (narrower than the bead)
  const c = [
    { x: 10_000, y: 0 },
    { x: 13_000, y: 0 },
    { x: 13_000, y: 1425 },
    { x: 11_000, y: 1425 },
    { x: 11_000, y: 1575 },
    { x: 13_000, y: 1575 },
    { x: 13_000, y: 3000 },
    { x: 10_000, y: 3000 },
  ];
  for (const loops of [[square], [c], [square, c]]) {
    const beads = loopBeads(loops, 300);
    const stroke = strokeArea([], loops, 300, 'miter');
    const a = area(beads),
      b = area(stroke);
    assert.ok(Math.abs(a - b) < 1e-3 * b, `areas ${a} vs ${b}`);
    assert.ok(area(difference(stroke, beads)) < 1e-3 * b && area(difference(beads, stroke)) < 1e-3 * b);
  }
});
