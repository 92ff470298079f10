import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  formatMiB,
  formatRatio,
  formatSeconds,
  formatTriangles,
  markdownTable,
  median,
  medianOfRatios,
} from './stats.js';

test('median of odd and even counts, unsorted input, empty list', () => {
  assert.equal(median([3, 1, 2]), 2);
  assert.equal(median([4, 1, 3, 2]), 2.5);
  assert.equal(median([7]), 7);
  assert.equal(median([]), null);
  const input = [3, 1, 2];
  median(input);
  assert.deepEqual(input, [3, 1, 2], 'input not sorted in place');
});

test('medianOfRatios pairs run i with run i, not median with median', () => {
  // the machine slowed down in rounds 2 and 3: both slicers took longer there
  const strata = [1.0, 2.0, 2.2, 1.1, 1.05];
  const cura = [2.0, 3.0, 3.3, 2.0, 2.1];
  // per round: 0.5, 0.667, 0.667, 0.55, 0.5 → median 0.55; median over median would be 1.1 / 2.1 = 0.524
  assert.equal(medianOfRatios(strata, cura), 0.55);
  assert.notEqual(medianOfRatios(strata, cura), median(strata)! / median(cura)!);
  // missing values and zero divisors drop their pair; unequal lengths use the common pairs
  assert.equal(medianOfRatios([1, null, 3, 9], [2, 2, 0]), 0.5);
  assert.equal(medianOfRatios([1], []), null);
  assert.equal(medianOfRatios([null], [1]), null);
});

test('markdownTable: header, alignment row, padded cells, escaped pipes', () => {
  const text = markdownTable(
    ['model', 'time'],
    [
      ['cube', '0.10 s'],
      ['a|b', '12.34 s'],
    ],
  );
  assert.equal(
    text,
    ['| model |    time |', '|:------|--------:|', '| cube  |  0.10 s |', '| a\\|b  | 12.34 s |'].join('\n'),
  );
  const left = markdownTable(['a', 'b'], [['×', 'yy']], ['left', 'left']);
  assert.equal(
    left,
    ['| a   | b   |', '|:----|:----|', '| ×   | yy  |'].join('\n'),
    'width counts characters, not UTF-16 units or bytes',
  );
});

test('number formatting', () => {
  assert.equal(formatSeconds(1.666), '1.67 s');
  assert.equal(formatSeconds(12.34), '12.3 s');
  assert.equal(formatSeconds(null), '–');
  assert.equal(formatMiB(159.4), '159 MiB');
  assert.equal(formatMiB(null), '–');
  assert.equal(formatRatio(1.29), '1.29×');
  assert.equal(formatRatio(null), '–');
  assert.equal(formatTriangles(136), '136');
  assert.equal(formatTriangles(5856), '5,856');
  assert.equal(formatTriangles(69451), '69 k');
  assert.equal(formatTriangles(225154), '225 k');
  assert.equal(formatTriangles(900616), '901 k');
  assert.equal(formatTriangles(1_234_567), '1.23 M');
  assert.equal(formatTriangles(null), '?');
});
