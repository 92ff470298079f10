import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import type { InfillModelInput, InfillResult } from '#strata/infill/types.js';
import { PATTERNS } from '#strata/infill/registry.js';
import { generateInfill } from '#strata/infill/generate.js';
import { pathLengthUm } from '#strata/infill/measure.js';
import { square, testParams, SHAPE_CENTRE } from '../test-shapes.js';
import {
  LIGHTNING_OVERHANG_DEG,
  LIGHTNING_STRAIGHTEN_DEG,
  lightningRadius,
} from '#strata/infill/patterns/lightning.js';

const c = SHAPE_CENTRE;
const LAYERS = 60;
const PATCH_LAYER = 40;
const H = 0.2;

function rect(x0: number, y0: number, x1: number, y1: number): ExPolygon[] {
  return [
    {
      outer: [
        { x: x0, y: y0 },
        { x: x1, y: y0 },
        { x: x1, y: y1 },
        { x: x0, y: y1 },
      ],
      holes: [],
    },
  ];
}

function model(need: (i: number) => ExPolygon[]): InfillModelInput {
  const region = square();
  const layers = Array.from({ length: LAYERS }, (_, i) => ({
    layerIndex: i,
    zMm: H * (i + 1),
    layerHeightMm: H,
    region,
  }));
  return { layers, supportNeeded: layers.map((_, i) => need(i)) };
}

function distToSegments(p: Pt, lines: readonly Pt[][]): number {
  let best = Infinity;
  for (const l of lines) {
    for (let i = 1; i < l.length; i++) {
      const a = l[i - 1],
        b = l[i];
      const ux = b.x - a.x,
        uy = b.y - a.y,
        l2 = ux * ux + uy * uy;
      const t = l2 > 0 ? Math.max(0, Math.min(1, ((p.x - a.x) * ux + (p.y - a.y) * uy) / l2)) : 0;
      best = Math.min(best, Math.hypot(a.x + t * ux - p.x, a.y + t * uy - p.y));
    }
  }
  return best;
}

function points(lines: readonly Pt[][]): Pt[] {
  return lines.flat();
}

// a 6 × 4 mm patch of top skin in the middle-left of a 30 mm square, at layer 40 of 60
const patch = rect(c.x - 9_000, c.y - 2_000, c.x - 3_000, c.y + 2_000);
const params = testParams(0.2);
const R = lightningRadius(params);
const patchModel = model((i) => (i === PATCH_LAYER ? patch : []));
const prepared = PATTERNS.lightning.prepare!(patchModel, params) as Pt[][][];
const results: InfillResult[] = patchModel.layers.map((l, i) => generateInfill('lightning', l, params, prepared[i]));

test('lightning prints nothing where no top surface needs support', () => {
  for (let i = PATCH_LAYER + 1; i < LAYERS; i++) assert.equal(pathLengthUm(results[i]), 0, `layer ${i}`);
});

test('lightning supports every point of the skin patch (within 1.35 radii of a branch or the wall)', () => {
  const lines = results[PATCH_LAYER].lines;
  assert.ok(lines.length > 0);
  for (let x = c.x - 9_000; x <= c.x - 3_000; x += 250) {
    for (let y = c.y - 2_000; y <= c.y + 2_000; y += 250) {
      const wall = x - (c.x - 15_000);
      const d = Math.min(distToSegments({ x, y }, lines), wall);
      assert.ok(d <= 1.35 * R + 1, `(${x}, ${y}) is ${d} µm from support`);
    }
  }
});

test('lightning is confined to the patch support cone: it shrinks going down, each layer within the overhang angle', () => {
  const prune = H * 1000 * Math.tan((LIGHTNING_OVERHANG_DEG * Math.PI) / 180);
  const straighten = H * 1000 * Math.tan((LIGHTNING_STRAIGHTEN_DEG * Math.PI) / 180);
  let last = Infinity;
  for (let i = PATCH_LAYER; i >= 0; i--) {
    const len = pathLengthUm(results[i]);
    assert.ok(len <= last + 1, `layer ${i} grows: ${len} > ${last}`);
    last = len;
    if (i < PATCH_LAYER && len > 0) {
      // what is printed here lies under what is printed above (within one layer's overhang)
      for (const p of points(results[i].lines)) {
        const d = distToSegments(p, results[i + 1].lines);
        assert.ok(d <= prune + straighten + 2, `layer ${i}: (${p.x}, ${p.y}) is ${d} µm from the layer above`);
      }
    }
    // and near the patch: within the reach of its branches to the wall (the patch's left edge is 6 mm in)
    for (const p of points(results[i].lines))
      assert.ok(p.x <= c.x - 3_000 + R && Math.abs(p.y - c.y) <= 2_000 + 2 * R, `layer ${i}: (${p.x}, ${p.y})`);
  }
  // the cone closes towards the wall: 40 layers down, the tips have retracted by 40 prune steps at least
  const top = pathLengthUm(results[PATCH_LAYER]),
    bottom = pathLengthUm(results[0]);
  assert.ok(bottom <= top - PATCH_LAYER * prune && bottom < 0.5 * top, `${bottom} vs ${top}`);
});

test('lightning uses much less material than grid under a full top skin', () => {
  const full = model((i) => (i === LAYERS - 1 ? square() : []));
  const prep = PATTERNS.lightning.prepare!(full, params);
  let lightning = 0,
    grid = 0;
  full.layers.forEach((l, i) => {
    lightning += pathLengthUm(generateInfill('lightning', l, params, prep[i]));
    grid += pathLengthUm(generateInfill('grid', l, params));
  });
  assert.ok(lightning < 0.35 * grid, `lightning ${lightning} vs grid ${grid}`);
});

test('lightning branches stay inside a region with holes and follow a shrinking region', () => {
  const region = (i: number): ExPolygon[] => {
    const shrink = i * 100;
    return [
      {
        outer: rect(c.x - 15_000 + shrink, c.y - 15_000, c.x + 15_000 - shrink, c.y + 15_000)[0].outer,
        holes: [
          [
            { x: c.x - 3_000, y: c.y - 3_000 },
            { x: c.x - 3_000, y: c.y + 3_000 },
            { x: c.x + 3_000, y: c.y + 3_000 },
            { x: c.x + 3_000, y: c.y - 3_000 },
          ],
        ],
      },
    ];
  };
  const layers = Array.from({ length: 30 }, (_, i) => ({
    layerIndex: i,
    zMm: H * (i + 1),
    layerHeightMm: H,
    region: region(i),
  }));
  const m: InfillModelInput = { layers, supportNeeded: layers.map((l, i) => (i === 29 ? l.region : [])) };
  const prep = PATTERNS.lightning.prepare!(m, params);
  for (let i = 0; i < 30; i++) {
    const r = generateInfill('lightning', layers[i], params, prep[i]);
    for (const p of points(r.lines)) {
      const inHole = Math.abs(p.x - c.x) < 3_000 - 2 && Math.abs(p.y - c.y) < 3_000 - 2;
      const outside = Math.abs(p.x - c.x) > 15_000 - i * 100 + 2;
      assert.ok(!inHole && !outside, `layer ${i}: (${p.x}, ${p.y})`);
    }
  }
});
