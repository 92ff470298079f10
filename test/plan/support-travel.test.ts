import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { ExPolygon } from '#strata/geometry/types.js';
import { PartGuard } from '#strata/plan/support-travel.js';

const square = (x0: number, y0: number, s: number) => [
  { x: x0, y: y0 },
  { x: x0 + s, y: y0 },
  { x: x0 + s, y: y0 + s },
  { x: x0, y: y0 + s },
];
const island = (x0: number, y0: number, s: number, hole?: [number, number, number]): ExPolygon => ({
  outer: square(x0, y0, s),
  holes: hole ? [square(...hole).reverse()] : [],
});

test('a travel is clear only when it neither crosses an island of either layer nor lies over one', () => {
  // this layer: a ring (a square with a square hole); the layer below: a square that overlaps the ring
  const here = [island(0, 0, 10000, [3000, 3000, 4000])];
  const below = [island(2000, 2000, 6000)];
  const guard = new PartGuard([here, below]);
  const at = (x: number, y: number) => ({ x, y });
  assert.equal(guard.clear(at(-5000, -5000), at(-1000, 20000)), true, 'beside both');
  assert.equal(guard.clear(at(-5000, 5000), at(15000, 5000)), false, 'across both');
  assert.equal(guard.clear(at(500, 500), at(1500, 500)), false, 'along the ring, crossing no edge');
  // the two layers overlap: a line over both, or in the hole of this one and over the one below, is over the
  // part (an even-odd test over both layers' rings at once would call the first clear)
  assert.equal(guard.clear(at(4000, 4000), at(6000, 6000)), false, 'in the hole, over the layer below');
  assert.equal(guard.clear(at(2300, 2300), at(2700, 2500)), false, 'over both layers at once');
  assert.equal(new PartGuard([here]).clear(at(4000, 4000), at(6000, 6000)), true, 'in the hole, nothing below');
  assert.equal(new PartGuard([[], []]).clear(at(0, 0), at(10000, 10000)), true, 'no islands');
});
