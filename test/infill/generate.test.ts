import { test } from 'node:test';
import assert from 'node:assert/strict';
import { generateInfill } from '#strata/infill/generate.js';
import { lineDensity } from '#strata/infill/measure.js';
import { PATTERN_IDS } from '#strata/infill/types.js';
import { TEST_SHAPES, testParams, SHAPE_CENTRE } from './test-shapes.js';
import type { ExPolygon } from '#strata/geometry/types.js';

function rect(x0: number, y0: number, w: number, h: number): ExPolygon {
  return {
    outer: [
      { x: x0, y: y0 },
      { x: x0 + w, y: y0 },
      { x: x0 + w, y: y0 + h },
      { x: x0, y: y0 + h },
    ],
    holes: [],
  };
}

test('output is integer micrometres, and the first path starts near the given start point', () => {
  const region = TEST_SHAPES['disc with hole']();
  for (const id of PATTERN_IDS) {
    const start = { x: SHAPE_CENTRE.x + 16_000, y: SHAPE_CENTRE.y };
    const r = generateInfill(
      id,
      { layerIndex: 2, zMm: 0.6, layerHeightMm: 0.2, region },
      testParams(0.2),
      undefined,
      start,
    );
    for (const p of [...r.lines.flat(), ...r.loops.flat()])
      assert.ok(Number.isInteger(p.x) && Number.isInteger(p.y), id);
    const first = r.loops[0]?.[0] ?? r.lines[0][0];
    let nearest = Infinity;
    for (const l of r.lines)
      for (const q of [l[0], l[l.length - 1]]) nearest = Math.min(nearest, Math.hypot(q.x - start.x, q.y - start.y));
    for (const l of r.loops) for (const q of l) nearest = Math.min(nearest, Math.hypot(q.x - start.x, q.y - start.y));
    assert.ok(Math.hypot(first.x - start.x, first.y - start.y) <= nearest + 1, id);
  }
});

test('an unknown pattern id is an error', () => {
  assert.throws(() =>
    generateInfill(
      'nope' as never,
      { layerIndex: 0, zMm: 0.2, layerHeightMm: 0.2, region: TEST_SHAPES.square() },
      testParams(0.2),
    ),
  );
});

test('small, fragmented regions get the set density of lines: connectors on the edge do not thin them', () => {
  // a few lines per piece and long connectors between them, as in Benchy's hull and cabin walls
  const c = SHAPE_CENTRE;
  const regions = {
    'four 5 mm strips': [0, 1, 2, 3].map((k) => rect(c.x - 15_000 + k * 8_000, c.y - 15_000, 5_000, 30_000)),
    'nine 8 mm squares': [0, 1, 2].flatMap((i) =>
      [0, 1, 2].map((j) => rect(c.x - 15_000 + i * 11_000, c.y - 15_000 + j * 11_000, 8_000, 8_000)),
    ),
  };
  for (const [name, region] of Object.entries(regions)) {
    for (const id of ['grid', 'lines', 'triangles', 'hexagons'] as const) {
      const params = testParams(0.2);
      const r = generateInfill(id, { layerIndex: 7, zMm: 1.4, layerHeightMm: 0.2, region }, params);
      const d = lineDensity(r, region, params.lineWidthUm);
      assert.ok(Math.abs(d - 0.2) <= 0.01, `${id} on ${name}: ${d.toFixed(4)}`);
    }
  }
});
