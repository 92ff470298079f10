import { test } from 'node:test';
import assert from 'node:assert/strict';
import { AreaIndex } from '#strata/geometry/area-index.js';
import { drawLayer, type Disc } from '#strata/support/tree-draw.js';

function draw(discs: Disc[]) {
  const steps = drawLayer({
    discs,
    roof: [],
    base: null,
    roofReachUm: 0,
    collision: [],
    gapBelow: [],
    gapIndex: () => new AreaIndex([]),
    widthUm: 400,
  });
  for (;;) {
    const s = steps.next();
    if (s.done) return s.value;
  }
}

test('a branch inside a wider one of its cluster is drawn as the wider circle, and known as that circle', () => {
  // the narrow disc comes first: the area and the circle the paths are drawn from must both be the wide one's
  const inner: Disc = { x: 300, y: 0, r: 500, clear: true };
  const outer: Disc = { x: 0, y: 0, r: 1500, clear: true };
  const { areas, circles } = draw([inner, outer]);
  assert.equal(areas.length, 1);
  const c = circles[0];
  assert.ok(c, 'a lone circle');
  assert.deepEqual([c.x, c.y, c.r], [0, 0, 1500]);
  const far = Math.max(...areas[0].outer.map((p) => Math.hypot(p.x, p.y)));
  assert.ok(far > 1400 && far <= 1501, `the area reaches the wide circle (${far} µm)`);
});

test('lone and overlapping branches: one area each, circles only for the lone ones', () => {
  const { areas, circles } = draw([
    { x: 0, y: 0, r: 800, clear: true },
    { x: 10000, y: 0, r: 800, clear: true },
    { x: 11000, y: 0, r: 800, clear: true },
  ]);
  assert.equal(areas.length, 2);
  const lone = circles.filter((c) => c !== null);
  assert.equal(lone.length, 1);
  assert.deepEqual([lone[0].x, lone[0].y, lone[0].r], [0, 0, 800]);
});
