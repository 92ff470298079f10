import { test } from 'node:test';
import assert from 'node:assert/strict';
import { generateInfill } from '#strata/infill/generate.js';
import { testParams, SHAPE_CENTRE } from '../test-shapes.js';

test('spiral: one unbroken line in a disc, few pieces in a square', () => {
  const c = SHAPE_CENTRE;
  const disc = [
    {
      outer: Array.from({ length: 200 }, (_, i) => ({
        x: Math.round(c.x + 15_000 * Math.cos((2 * Math.PI * i) / 200)),
        y: Math.round(c.y + 15_000 * Math.sin((2 * Math.PI * i) / 200)),
      })),
      holes: [],
    },
  ];
  const r = generateInfill('spiral', { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region: disc }, testParams(0.2));
  assert.equal(r.lines.length, 1);
  const first = r.lines[0][0],
    last = r.lines[0][r.lines[0].length - 1];
  const rf = Math.hypot(first.x - c.x, first.y - c.y),
    rl = Math.hypot(last.x - c.x, last.y - c.y);
  assert.ok(Math.min(rf, rl) < 1_000 && Math.max(rf, rl) > 14_000, `${rf} ${rl}`);
});
