import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chooseSeam } from '#strata/plan/seam.js';
import type { Polygon } from '#strata/geometry/types.js';

const circle = (n: number, r: number): Polygon =>
  Array.from({ length: n }, (_, i) => ({
    x: Math.round(r * Math.cos((2 * Math.PI * i) / n)),
    y: Math.round(r * Math.sin((2 * Math.PI * i) / n)),
  }));
const square: Polygon = [
  { x: 0, y: 0 },
  { x: 10000, y: 0 },
  { x: 10000, y: 10000 },
  { x: 0, y: 10000 },
];

test('rear seam is the vertex with the largest Y', () => {
  const c = circle(72, 10000);
  assert.equal(c[chooseSeam(c, 'rear', { x: 0, y: 0 }, 1, 0, 0)].y, 10000);
});

test('aligned seam picks a sharp corner at the rear, the same on every layer', () => {
  const i = chooseSeam(square, 'aligned', { x: 0, y: 0 }, 1, 0, 0);
  assert.equal(square[i].y, 10000);
  assert.equal(chooseSeam(square, 'aligned', { x: 99999, y: -5 }, 1, 7, 3), i);
});

test('nearest seam follows the nozzle; random seam is seeded and deterministic', () => {
  assert.deepEqual(square[chooseSeam(square, 'nearest', { x: 9000, y: 500 }, 1, 0, 0)], { x: 10000, y: 0 });
  const c = circle(100, 10000);
  const a = [0, 1, 2, 3, 4].map((l) => chooseSeam(c, 'random', { x: 0, y: 0 }, 42, l, 0));
  const b = [0, 1, 2, 3, 4].map((l) => chooseSeam(c, 'random', { x: 0, y: 0 }, 42, l, 0));
  assert.deepEqual(a, b);
  assert.ok(new Set(a).size > 1);
});
