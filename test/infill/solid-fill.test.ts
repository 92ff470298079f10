import { test } from 'node:test';
import assert from 'node:assert/strict';
import { solidFill } from '#strata/infill/solid-fill.js';
import { measuredDensity } from '#strata/infill/measure.js';
import { TEST_SHAPES, SHAPE_CENTRE } from './test-shapes.js';

test('solid fill covers the region and is one zig-zag in a convex region', () => {
  const region = TEST_SHAPES.square();
  const lines = solidFill(region, 45, 450, SHAPE_CENTRE);
  assert.equal(lines.length, 1);
  const d = measuredDensity({ lines, loops: [] }, region, 450);
  assert.ok(d > 0.97, `${d}`);
  assert.ok(solidFill(region, 45, 450, SHAPE_CENTRE, { connect: false }).length > 50);
});
