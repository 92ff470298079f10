import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { clipLines } from '#strata/geometry/clip.js';
import { clipPolylines } from '#strata/infill/clip-polylines.js';
import { indexRegion, regionGeom, pointInside, nearestBoundary } from '#strata/infill/region-index.js';
import type { Piece } from '#strata/infill/piece.js';
import { TEST_SHAPES, hull, SHAPE_CENTRE } from './test-shapes.js';

function len(l: readonly Pt[]): number {
  let s = 0;
  for (let i = 1; i < l.length; i++) s += Math.hypot(l[i].x - l[i - 1].x, l[i].y - l[i - 1].y);
  return s;
}

/** Deterministic pseudo-random wiggly polylines across the shapes (a tiny LCG). */
function wiggles(seed: number, count: number): Pt[][] {
  let s = seed;
  const rnd = () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
  const out: Pt[][] = [];
  for (let k = 0; k < count; k++) {
    const pts: Pt[] = [];
    let x = SHAPE_CENTRE.x - 40_000 + rnd() * 80_000,
      y = SHAPE_CENTRE.y - 30_000 + rnd() * 60_000;
    for (let i = 0; i < 60; i++) {
      pts.push({ x: Math.round(x), y: Math.round(y) });
      x += (rnd() - 0.5) * 4_000;
      y += (rnd() - 0.5) * 4_000;
    }
    out.push(pts);
  }
  return out;
}

const shapes = { ...TEST_SHAPES, hull: () => hull(5) };

for (const [name, make] of Object.entries(shapes)) {
  test(`polyline clipper agrees with the facade's clipLines on ${name}`, () => {
    const region = make();
    const ix = indexRegion(regionGeom(region));
    const lines = wiggles(name.length * 7919, 200);
    const pieces: Piece[] = [];
    clipPolylines(ix, lines, pieces);
    const mine = pieces.map((p) => len(p.pts)).reduce((a, b) => a + b, 0);
    const theirs = clipLines(lines, region)
      .map(len)
      .reduce((a, b) => a + b, 0);
    assert.ok(Math.abs(mine - theirs) <= 1e-4 * theirs + 50, `${mine} vs ${theirs}`);
    for (const p of pieces) {
      // every piece is inside, its cut ends are on the boundary
      const m = p.pts[Math.floor(p.pts.length / 2)];
      const n = nearestBoundary(ix, m.x, m.y, 2);
      assert.ok(n || pointInside(ix, m.x, m.y));
      for (const [pt, a] of [
        [p.pts[0], p.a0],
        [p.pts[p.pts.length - 1], p.a1],
      ] as const) {
        if (a) assert.ok(nearestBoundary(ix, pt.x, pt.y, 1.5), `anchored end ${pt.x},${pt.y} on the boundary`);
      }
    }
  });
}

test('a polyline wholly inside stays one piece; one wholly outside vanishes', () => {
  const region = TEST_SHAPES.square();
  const ix = indexRegion(regionGeom(region));
  const c = SHAPE_CENTRE;
  const inside = [
    { x: c.x - 5_000, y: c.y },
    { x: c.x, y: c.y + 3_000 },
    { x: c.x + 5_000, y: c.y },
  ];
  const outside = [
    { x: c.x + 20_000, y: c.y },
    { x: c.x + 25_000, y: c.y + 3_000 },
  ];
  const pieces: Piece[] = [];
  clipPolylines(ix, [inside, outside], pieces);
  assert.equal(pieces.length, 1);
  assert.deepEqual(pieces[0].pts, inside);
  assert.equal(pieces[0].a0, null);
  assert.equal(pieces[0].a1, null);
});
