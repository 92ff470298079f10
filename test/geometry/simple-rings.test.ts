import { test } from 'node:test';
import assert from 'node:assert/strict';
import { islandsIfSimple } from '#strata/geometry/simple-rings.js';
import type { ExPolygon, Polygon } from '#strata/geometry/types.js';

const sq = (x0: number, y0: number, s: number): Polygon => [
  { x: x0, y: y0 },
  { x: x0 + s, y: y0 },
  { x: x0 + s, y: y0 + s },
  { x: x0, y: y0 + s },
];
const cw = (r: Polygon): Polygon => [...r].reverse();

test('simple, well-nested rings come back as the islands, without repeated or collinear points', () => {
  const areas: ExPolygon[] = [
    { outer: sq(0, 0, 1000), holes: [cw(sq(400, 400, 100))] },
    { outer: sq(2000, 0, 100), holes: [] },
  ];
  const outer = [
    { x: 0, y: 0 },
    { x: 500, y: 0 },
    { x: 1000, y: 0 },
    { x: 1000, y: 1000 },
    { x: 1000, y: 1000 },
    { x: 0, y: 1000 },
  ];
  const r = islandsIfSimple([outer, cw(sq(400, 400, 100)), sq(2000, 0, 100)], areas);
  assert.ok(r);
  assert.equal(r.length, 2);
  assert.deepEqual(r[0].outer, sq(0, 0, 1000));
  assert.equal(r[0].holes.length, 1);
});

test('crossing or touching rings, a flipped ring, a spike or lost nesting need the union', () => {
  const one: ExPolygon[] = [{ outer: sq(0, 0, 1000), holes: [] }];
  const bowtie: Polygon = [
    { x: 0, y: 0 },
    { x: 1000, y: 1000 },
    { x: 1000, y: 0 },
    { x: 0, y: 1000 },
  ];
  assert.equal(islandsIfSimple([bowtie], one), null);
  assert.equal(islandsIfSimple([cw(sq(0, 0, 1000))], one), null);
  const spike: Polygon = [
    { x: 0, y: 0 },
    { x: 1000, y: 0 },
    { x: 2000, y: 0 },
    { x: 1000, y: 0 },
    { x: 1000, y: 1000 },
  ];
  assert.equal(islandsIfSimple([spike], one), null);
  const two: ExPolygon[] = [one[0], { outer: sq(3000, 0, 100), holes: [] }];
  assert.equal(islandsIfSimple([sq(0, 0, 1000), sq(1000, 0, 100)], two), null, 'touching islands');
  assert.equal(islandsIfSimple([sq(0, 0, 1000), sq(100, 100, 100)], two), null, 'island swallowed by another');
  const holed: ExPolygon[] = [{ outer: sq(0, 0, 1000), holes: [cw(sq(100, 100, 100))] }];
  assert.equal(islandsIfSimple([sq(0, 0, 1000), cw(sq(-100, -100, 1200))], holed), null, 'hole grown past its outer');
});
