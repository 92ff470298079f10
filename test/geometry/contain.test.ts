import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ringInside } from '#strata/geometry/contain.js';
import { difference } from '#strata/geometry/clip.js';
import type { ExPolygon, Polygon } from '#strata/geometry/types.js';

const sq = (x0: number, y0: number, s: number): Polygon => [
  { x: x0, y: y0 },
  { x: x0 + s, y: y0 },
  { x: x0 + s, y: y0 + s },
  { x: x0, y: y0 + s },
];
const hole = (x0: number, y0: number, s: number): Polygon => sq(x0, y0, s).reverse();
const island = (outer: Polygon, ...holes: Polygon[]): ExPolygon => ({ outer, holes });

test('a ring well inside an island, or inside its second island, is inside', () => {
  const areas = [island(sq(0, 0, 1000)), island(sq(5000, 0, 1000))];
  assert.equal(ringInside(sq(100, 100, 500), areas), true);
  assert.equal(ringInside(sq(5100, 100, 500), areas), true);
});

test('touching, crossing or sticking out is not inside', () => {
  const areas = [island(sq(0, 0, 1000))];
  assert.equal(ringInside(sq(0, 100, 500), areas), false); // shares an edge line
  assert.equal(ringInside(sq(500, 500, 500), areas), false); // corner on the boundary
  assert.equal(ringInside(sq(800, 100, 500), areas), false); // crosses
  assert.equal(ringInside(sq(-100, -100, 1200), areas), false); // encloses
  assert.equal(ringInside(sq(2000, 0, 100), areas), false); // outside
});

test('a hole of the area inside the ring, or the ring inside a hole, is not inside', () => {
  const areas = [island(sq(0, 0, 1000), hole(400, 400, 100))];
  assert.equal(ringInside(sq(100, 100, 800), areas), false);
  assert.equal(ringInside(sq(420, 420, 50), areas), false);
  assert.equal(ringInside(sq(100, 100, 200), areas), true);
});

test('difference drops subject islands inside the clip and keeps the rest', () => {
  const clip = [island(sq(0, 0, 1000))];
  assert.deepEqual(difference([island(sq(100, 100, 500))], clip), []);
  const r = difference([island(sq(100, 100, 500)), island(sq(3000, 0, 100))], clip);
  assert.equal(r.length, 1);
});
