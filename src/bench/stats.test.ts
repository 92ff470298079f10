import { test } from 'node:test';
import assert from 'node:assert/strict';
import { formatCount, formatMiB, formatRatio, formatSeconds, formatTable, median } from './stats.js';

test('median of odd and even counts, unsorted input, empty list', () => {
  assert.equal(median([3, 1, 2]), 2);
  assert.equal(median([4, 1, 3, 2]), 2.5);
  assert.equal(median([7]), 7);
  assert.equal(median([]), null);
  const input = [3, 1, 2];
  median(input);
  assert.deepEqual(input, [3, 1, 2], 'input not sorted in place');
});

test('formatTable pads columns, right-aligns numbers by default', () => {
  const text = formatTable(['model', 'time'], [['cube', '0.10'], ['benchy', '12.34']]);
  assert.equal(text, ['model    time', '------  -----', 'cube     0.10', 'benchy  12.34'].join('\n'));
  const left = formatTable(['a', 'b'], [['x', 'yy']], ['left', 'left']);
  assert.equal(left, ['a  b', '-  --', 'x  yy'].join('\n'));
});

test('number formatting', () => {
  assert.equal(formatSeconds(2.266), '2.27');
  assert.equal(formatSeconds(null), '-');
  assert.equal(formatMiB(59.4), '59');
  assert.equal(formatRatio(1, 2), '0.50x');
  assert.equal(formatRatio(null, 2), '-');
  assert.equal(formatRatio(1, 0), '-');
  assert.equal(formatCount(225154), '225,154');
  assert.equal(formatCount(136), '136');
  assert.equal(formatCount(null), '-');
});
