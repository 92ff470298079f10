import { test } from 'node:test';
import assert from 'node:assert/strict';
import { rect } from '../geometry/test-shapes.js';
import { flagOverAir, indexArea } from './over-air.js';

const air = indexArea([rect(10_000, -5_000, 20_000, 5_000)]);

test('a line across an area over air is split exactly at its edges, the middle run flagged', () => {
  const f = flagOverAir([{ x: 0, y: 0 }, { x: 30_000, y: 0 }], false, air)!;
  assert.deepEqual(f.points, [{ x: 0, y: 0 }, { x: 10_000, y: 0 }, { x: 20_000, y: 0 }, { x: 30_000, y: 0 }]);
  assert.deepEqual([...f.flags], [0, 1, 0]);
});

test('a loop keeps its shape: flags per edge, the closing edge included', () => {
  // a square loop whose right side runs through the area
  const loop = [{ x: 15_000, y: -2_000 }, { x: 15_000, y: 2_000 }, { x: 0, y: 2_000 }, { x: 0, y: -2_000 }];
  const f = flagOverAir(loop, true, air)!;
  assert.equal(f.flags.length, f.points.length, 'one flag per edge of a closed path');
  // edge 0 (inside), then the top edge leaves the area at x = 10 mm, the left side is outside, the bottom comes back in
  assert.deepEqual(f.points, [{ x: 15_000, y: -2_000 }, { x: 15_000, y: 2_000 }, { x: 10_000, y: 2_000 }, { x: 0, y: 2_000 }, { x: 0, y: -2_000 }, { x: 10_000, y: -2_000 }]);
  assert.deepEqual([...f.flags], [1, 1, 0, 0, 0, 1]);
});

test('paths clear of the area are left alone', () => {
  assert.equal(flagOverAir([{ x: 0, y: 10_000 }, { x: 30_000, y: 10_000 }], false, air), null);
  assert.equal(flagOverAir([{ x: 0, y: 0 }, { x: 5_000, y: 0 }], false, air), null);
  assert.equal(flagOverAir([{ x: 0, y: 0 }, { x: 5_000, y: 0 }], false, indexArea([])), null);
});
