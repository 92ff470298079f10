import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area } from '#strata/geometry/clip.js';
import { disc, square } from '../geometry/test-shapes.js';
import { VASE_SPECK_MM2, vaseOutline } from '#strata/regions/layer-regions.js';

const ring = (r: number, hole: number) => ({
  outer: disc(0, 0, r).outer,
  holes: [disc(0, 0, hole).outer.slice().reverse()],
});

test('vaseOutline: holes dropped, an island inside a hole goes with it', () => {
  const { kept, droppedMm2 } = vaseOutline([ring(15_000, 13_000), disc(0, 0, 5_000)]);
  assert.equal(droppedMm2, 0);
  assert.equal(kept.length, 1);
  assert.equal(kept[0].holes.length, 0);
  assert.ok(Math.abs(area(kept) - area([disc(0, 0, 15_000)])) < 1);
});

test('vaseOutline: specks beside the largest island dropped and measured, islands of size kept', () => {
  const speck = square(20_000, 0, 800); // 0.64 mm²
  const post = square(20_000, 5_000, 2_000); // 4 mm²
  const { kept, droppedMm2 } = vaseOutline([disc(0, 0, 10_000), speck, post]);
  assert.equal(kept.length, 2);
  assert.ok(Math.abs(droppedMm2 - 0.64) < 1e-9);
  assert.ok(0.64 < VASE_SPECK_MM2);
  // the largest island is kept however small
  assert.deepEqual(vaseOutline([speck]).kept, [speck]);
  assert.deepEqual(vaseOutline([]), { kept: [], droppedMm2: 0 });
});
