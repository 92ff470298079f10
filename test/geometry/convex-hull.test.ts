import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ringArea } from '#strata/geometry/clip.js';
import { convexHull } from '#strata/geometry/convex-hull.js';

test('the hull of a square with points inside and on its sides is the square, counter-clockwise', () => {
  const pts = [
    { x: 5, y: 5 },
    { x: 0, y: 0 },
    { x: 10, y: 0 },
    { x: 5, y: 0 },
    { x: 10, y: 10 },
    { x: 2, y: 7 },
    { x: 0, y: 10 },
    { x: 0, y: 4 },
  ];
  const hull = convexHull(pts);
  assert.deepEqual(hull, [
    { x: 0, y: 0 },
    { x: 10, y: 0 },
    { x: 10, y: 10 },
    { x: 0, y: 10 },
  ]);
  assert.equal(ringArea(hull), 100);
});

test('an L shape: the hull closes its notch', () => {
  const l = [
    { x: 0, y: 0 },
    { x: 20, y: 0 },
    { x: 20, y: 5 },
    { x: 5, y: 5 },
    { x: 5, y: 20 },
    { x: 0, y: 20 },
  ];
  const hull = convexHull(l);
  assert.equal(hull.length, 5);
  assert.equal(ringArea(hull), 20 * 5 + 15 * 5 + (15 * 15) / 2);
  assert.ok(!hull.some((p) => p.x === 5 && p.y === 5), 'the notch corner is inside');
});

test('fewer than three points, or all on a line', () => {
  assert.deepEqual(convexHull([]), []);
  assert.deepEqual(convexHull([{ x: 1, y: 2 }]), [{ x: 1, y: 2 }]);
  assert.deepEqual(
    convexHull([
      { x: 0, y: 0 },
      { x: 1, y: 1 },
      { x: 2, y: 2 },
    ]),
    [
      { x: 0, y: 0 },
      { x: 2, y: 2 },
    ],
  );
});
