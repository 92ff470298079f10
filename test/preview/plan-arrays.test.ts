import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Slicer } from '#strata/api/slicer.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import { FEATURE_TYPES } from '#strata/plan/types.js';
import {
  planToArrays,
  RETRACTION_STRIDE,
  SEGMENT_STRIDE,
  TRAVEL_STRIDE,
  transferList,
} from '#strata/preview/plan-arrays.js';

const cube = readFileSync(fileURLToPath(new URL('../../../examples/calibration-cube.stl', import.meta.url)));

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
          const p = s.points[k],
            q = s.points[(k + 1) % s.points.length];
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
      for (const [x, y] of [
        [x0, y0],
        [x1, y1],
      ])
        assert.ok(x >= b.minX - 1e-3 && x <= b.maxX + 1e-3 && y >= b.minY - 1e-3 && y <= b.maxY + 1e-3);
      length += Math.hypot(x1 - x0, y1 - y0);
    }
  }
  assert.ok(Math.abs(length - planLength) < 1e-3 * planLength, `lengths ${length} vs ${planLength}`);
  const byFeature = a.featureLengthMm.reduce((s, v) => s + v, 0);
  assert.ok(Math.abs(byFeature - planLength) < 1e-3 * planLength);
  assert.ok(
    a.featureLengthMm[FEATURE_TYPES.indexOf('WALL-OUTER')] > 0 && a.featureLengthMm[FEATURE_TYPES.indexOf('FILL')] > 0,
  );
  assert.ok(a.layerTravels[n] > n, 'travels between paths');
  assert.ok(a.layerRetractions[n] > 0, 'retractions marked');
  const buffers = transferList(a);
  assert.equal(new Set(buffers).size, buffers.length, 'each array has its own buffer');
});

test("each segment has its speed and fan, each layer its time; moves number each layer's extrusion segments and travels in order", async () => {
  // no slowing down for the layer time: each feature at its own speed
  const slicer = new Slicer({ threads: 1, minLayerTime: 0 });
  const { plan, stats } = await slicer.slicePlan(cube);
  const estimate = estimatePlan(plan, slicer.config);
  const a = planToArrays(plan, estimate.layerSeconds);
  const segments = a.segments.length / SEGMENT_STRIDE,
    travels = a.travels.length / TRAVEL_STRIDE,
    retractions = a.retractions.length / RETRACTION_STRIDE;
  assert.equal(a.segmentSpeed.length, segments);
  assert.equal(a.segmentFan.length, segments);
  assert.equal(a.segmentMove.length, segments);
  assert.equal(a.travelMove.length, travels);
  assert.equal(a.retractionMove.length, retractions);
  for (const v of a.segmentSpeed) assert.ok(v > 0 && v < 1000, `speed ${v}`);
  for (const v of a.segmentFan) assert.ok(v >= 0 && v <= 1, `fan ${v}`);
  const fill = FEATURE_TYPES.indexOf('FILL'),
    outer = FEATURE_TYPES.indexOf('WALL-OUTER');
  const speedOf = (f: number) =>
    a.segmentSpeed[
      [...Array(segments).keys()].find(
        (i) => a.segments[i * SEGMENT_STRIDE + 7] === f && a.segments[i * SEGMENT_STRIDE + 8] > 2,
      )!
    ];
  assert.equal(speedOf(fill), slicer.config.infillSpeed);
  assert.equal(speedOf(outer), slicer.config.perimeterSpeed);
  const total = a.layerSeconds.reduce((s, v) => s + v, 0);
  assert.ok(
    Math.abs(total - stats.printTimeSeconds) < 0.01 * stats.printTimeSeconds,
    `layer times ${total} s, print ${stats.printTimeSeconds} s`,
  );
  for (let li = 0; li < a.layerZ.length; li++) {
    // the layer's moves are 0..n-1, each once, each array's in increasing order
    const seen = new Uint8Array(a.layerMoves[li]);
    for (const [moves, from, to] of [
      [a.segmentMove, a.layerSegments[li], a.layerSegments[li + 1]],
      [a.travelMove, a.layerTravels[li], a.layerTravels[li + 1]],
    ] as const) {
      for (let k = from; k < to; k++) {
        assert.ok(moves[k] < a.layerMoves[li] && !seen[moves[k]]++, `layer ${li}: move ${moves[k]}`);
        if (k > from) assert.ok(moves[k] > moves[k - 1]);
      }
    }
    assert.ok(
      seen.every((v) => v === 1),
      `layer ${li}: every move is a segment or a travel`,
    );
    // a retraction comes just before its travel
    for (let k = a.layerRetractions[li]; k < a.layerRetractions[li + 1]; k++) {
      const t = [...a.travelMove.subarray(a.layerTravels[li], a.layerTravels[li + 1])].indexOf(a.retractionMove[k]);
      assert.ok(t >= 0, `layer ${li}: a retraction before travel move ${a.retractionMove[k]}`);
    }
  }
  assert.deepEqual(
    [...planToArrays(plan).layerSeconds].filter((v) => v !== 0),
    [],
    'no estimate: zeros',
  );
});
