import { test } from 'node:test';
import assert from 'node:assert/strict';
import { compact, feedrate, fixedDecimal, humanDuration, mm } from '#strata/gcode/format.js';

test('fixedDecimal writes exact decimals without trailing zeros', () => {
  assert.equal(fixedDecimal(10500, 1000), '10.5');
  assert.equal(fixedDecimal(10000, 1000), '10');
  assert.equal(fixedDecimal(1, 1000), '0.001');
  assert.equal(fixedDecimal(-1, 1000), '-0.001');
  assert.equal(fixedDecimal(-0, 1000), '0');
  assert.equal(fixedDecimal(0, 100000), '0');
  assert.equal(fixedDecimal(123456, 100000), '1.23456');
  assert.equal(fixedDecimal(-500010, 100000), '-5.0001');
  assert.equal(fixedDecimal(12, 1), '12');
});

test('mm rounds to the micrometre; compact to the given decimals', () => {
  assert.equal(mm(0.2), '0.2');
  assert.equal(mm(0.1 + 0.2), '0.3');
  assert.equal(mm(12.3456), '12.346');
  assert.equal(mm(-0.0001), '0');
  assert.equal(compact(200), '200');
  assert.equal(compact(1.23456789), '1.23457');
  assert.equal(compact(1e-9), '0');
  assert.equal(compact(0.25, 1), '0.3');
});

test('feedrate is whole mm/min; durations read like 1h 2m 3s', () => {
  assert.equal(feedrate(45), 2700);
  assert.equal(feedrate(33.3333), 2000);
  assert.equal(humanDuration(3723.4), '1h 2m 3s');
  assert.equal(humanDuration(125), '2m 5s');
  assert.equal(humanDuration(9), '9s');
});
