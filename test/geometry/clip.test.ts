import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area, difference, intersection } from '#strata/geometry/clip.js';
import { square } from './test-shapes.js';

test('difference ignores clip islands far from the subject and still cuts the ones that touch it', () => {
  const a = [square(0, 0, 1000)];
  const far = square(5000, 5000, 1000);
  const near = square(500, 500, 1000);
  assert.equal(area(difference(a, [far])), 1000 * 1000);
  assert.equal(area(difference(a, [far, near, far])), 1000 * 1000 - 500 * 500);
});

test('intersection of islands with disjoint bounds is empty; touching ones keep their overlap', () => {
  const a = [square(0, 0, 1000), square(10000, 0, 1000)];
  assert.deepEqual(intersection(a, [square(5000, 5000, 100)]), []);
  const r = intersection(a, [square(10500, 0, 1000), square(20000, 0, 10)]);
  assert.equal(r.length, 1);
  assert.equal(area(r), 500 * 1000);
});
