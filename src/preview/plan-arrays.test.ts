import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Slicer } from '../api/slicer.js';
import { FEATURE_TYPES } from '../plan/types.js';
import { planToArrays, RETRACTION_STRIDE, SEGMENT_STRIDE, TRAVEL_STRIDE, transferList } from './plan-arrays.js';

const cube = readFileSync(fileURLToPath(new URL('../../examples/calibration-cube.stl', import.meta.url)));

test('preview arrays hold every extrusion of the plan, by layer, inside the printed bounds', async () => {
  const { plan, stats } = await new Slicer({ threads: 1 }).slicePlan(cube);
  const a = planToArrays(plan);
  const n = plan.layers.length;
  assert.equal(a.layerZ.length, n);
  assert.equal(n, stats.layers);
  for (const [offsets, data, stride] of [
    [a.layerSegments, a.segments, SEGMENT_STRIDE],
    [a.layerTravels, a.travels, TRAVEL_STRIDE],
    [a.layerRetractions, a.retractions, RETRACTION_STRIDE],
  ] as const) {
    assert.equal(offsets.length, n + 1);
    assert.equal(offsets[n] * stride, data.length);
    for (let i = 0; i < n; i++) assert.ok(offsets[i] <= offsets[i + 1], 'offsets grow');
  }
  // every segment sits on its layer's Z, inside the plan's bounds, with a known feature
  let planLength = 0;
  for (const l of plan.layers)
    for (const s of l.steps)
      if (s.kind === 'extrude')
        for (let k = 0; k < (s.closed ? s.points.length : s.points.length - 1); k++) {
          const p = s.points[k], q = s.points[(k + 1) % s.points.length];
          planLength += Math.hypot(q.x - p.x, q.y - p.y) / 1000;
        }
  const b = plan.bounds;
  let length = 0;
  for (let li = 0; li < n; li++) {
    for (let s = a.layerSegments[li]; s < a.layerSegments[li + 1]; s++) {
      const o = s * SEGMENT_STRIDE;
      const [x0, y0, x1, y1, z, width, height, f, layer] = a.segments.subarray(o, o + SEGMENT_STRIDE);
      assert.equal(layer, li);
      assert.equal(z, a.layerZ[li]);
      assert.ok(width > 0 && width < 1 && height > 0.1 && height < 0.3, `bead ${width} × ${height}`);
      assert.ok(Number.isInteger(f) && f >= 0 && f < FEATURE_TYPES.length);
      for (const [x, y] of [[x0, y0], [x1, y1]]) assert.ok(x >= b.minX - 1e-3 && x <= b.maxX + 1e-3 && y >= b.minY - 1e-3 && y <= b.maxY + 1e-3);
      length += Math.hypot(x1 - x0, y1 - y0);
    }
  }
  assert.ok(Math.abs(length - planLength) < 1e-3 * planLength, `lengths ${length} vs ${planLength}`);
  const byFeature = a.featureLengthMm.reduce((s, v) => s + v, 0);
  assert.ok(Math.abs(byFeature - planLength) < 1e-3 * planLength);
  assert.ok(a.featureLengthMm[FEATURE_TYPES.indexOf('WALL-OUTER')] > 0 && a.featureLengthMm[FEATURE_TYPES.indexOf('FILL')] > 0);
  assert.ok(a.layerTravels[n] > n, 'travels between paths');
  assert.ok(a.layerRetractions[n] > 0, 'retractions marked');
  const buffers = transferList(a);
  assert.equal(new Set(buffers).size, buffers.length, 'each array has its own buffer');
});
