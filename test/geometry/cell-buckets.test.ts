import { test } from 'node:test';
import assert from 'node:assert/strict';
import { bucketByCell } from '#strata/geometry/cell-buckets.js';

test('ids are grouped by cell, each cell in id order, empty cells empty', () => {
  const { start, items } = bucketByCell(Int32Array.from([2, 0, 2, 3, 0, 2]), 5);
  assert.deepEqual([...start], [0, 2, 2, 5, 6, 6]);
  assert.deepEqual([...items], [1, 4, 0, 2, 5, 3]);
  const none = bucketByCell(new Int32Array(0), 3);
  assert.deepEqual([...none.start], [0, 0, 0, 0]);
  assert.equal(none.items.length, 0);
});
