/**
 * Properties every registered pattern must have, checked by iterating the registry: a pattern added to
 * PATTERN_IDS is tested here the day it is added. Density is the lines' length × width inside the region,
 * leaving out the connectors on its edge, as the G-code analyser measures it (measure.ts lineDensity);
 * 'volume' patterns are averaged over one Z period, 'support' patterns (lightning) report their figure
 * instead (lightning.test.ts checks what they must do).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import { clipLinesOutside, offset } from '#strata/geometry/clip.js';
import {
  PATTERN_IDS,
  type InfillLayerInput,
  type InfillPattern,
  type InfillResult,
  type PatternId,
} from '#strata/infill/types.js';
import { loadCustomInfill, PATTERNS, regionPattern } from '#strata/infill/registry.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { generateInfill } from '#strata/infill/generate.js';
import { lineDensity } from '#strata/infill/measure.js';
import { TEST_SHAPES, testParams } from './test-shapes.js';

const DENSITIES = [0.1, 0.2, 0.4];
const TOLERANCE = 0.1;
const W = 450;

function layerAt(region: ExPolygon[], z: number, layerIndex = 7): InfillLayerInput {
  return { layerIndex, zMm: z, layerHeightMm: 0.2, region };
}

function allPaths(r: InfillResult): Pt[][] {
  return [...r.lines, ...r.loops.map((l) => [...l, l[0]])];
}

function outsideLength(r: InfillResult, region: ExPolygon[], grow: number): number {
  const out = clipLinesOutside(allPaths(r), offset(region, grow));
  let len = 0;
  for (const l of out) for (let i = 1; i < l.length; i++) len += Math.hypot(l[i].x - l[i - 1].x, l[i].y - l[i - 1].y);
  return len;
}

function segmentProblems(r: InfillResult): { zero: number; dup: number } {
  const seen = new Set<string>();
  let zero = 0,
    dup = 0;
  const seg = (a: Pt, b: Pt) => {
    if (a.x === b.x && a.y === b.y) {
      zero++;
      return;
    }
    const k = a.x < b.x || (a.x === b.x && a.y < b.y) ? `${a.x},${a.y},${b.x},${b.y}` : `${b.x},${b.y},${a.x},${a.y}`;
    if (seen.has(k)) dup++;
    seen.add(k);
  };
  for (const l of r.lines) for (let i = 1; i < l.length; i++) seg(l[i - 1], l[i]);
  for (const l of r.loops) for (let i = 0; i < l.length; i++) seg(l[i], l[(i + 1) % l.length]);
  return { zero, dup };
}

test('the registry has one module per pattern id, under its own id', () => {
  assert.deepEqual(Object.keys(PATTERNS).sort(), [...PATTERN_IDS].sort());
  for (const id of PATTERN_IDS) assert.equal(PATTERNS[id].id, id);
});

for (const id of PATTERN_IDS) {
  const pattern = PATTERNS[id];
  const model = pattern.densityModel ?? 'layer';
  for (const [shapeName, makeShape] of Object.entries(TEST_SHAPES)) {
    const region = makeShape();
    test(`${id} on ${shapeName}: density, containment, clean segments, determinism`, (t) => {
      const figures: string[] = [];
      for (const d of DENSITIES) {
        const params = testParams(d);
        const r = generateInfill(id, layerAt(region, 1.4), params);
        assert.ok(r.lines.length + r.loops.length > 0, `${id} ${d}: something is printed`);
        // density
        let measured: number;
        if (model === 'volume') {
          const period = pattern.zPeriodMm ? pattern.zPeriodMm(params) : 1;
          const k = 8;
          measured = 0;
          for (let i = 0; i < k; i++)
            measured +=
              lineDensity(generateInfill(id, layerAt(region, 0.1 + (period * (i + 0.5)) / k), params), region, W) / k;
        } else measured = lineDensity(r, region, W);
        figures.push(`${(d * 100).toFixed(0)}% → ${(measured * 100).toFixed(1)}%`);
        if (model !== 'support') {
          assert.ok(
            Math.abs(measured - d) <= TOLERANCE * d,
            `${id} on ${shapeName} at ${d}: measured ${measured.toFixed(4)}`,
          );
        }
        // containment: nothing outside the region grown by half a line width; centre lines inside (±3 µm rounding)
        assert.ok(outsideLength(r, region, W / 2) < 1, `${id} ${d}: outside region + w/2`);
        assert.ok(outsideLength(r, region, 3) < 5, `${id} ${d}: centre lines outside the region`);
        // no zero-length or duplicate segments
        assert.deepEqual(segmentProblems(r), { zero: 0, dup: 0 }, `${id} ${d}`);
        // deterministic
        assert.deepEqual(generateInfill(id, layerAt(region, 1.4), params), r);
      }
      t.diagnostic(`${id} on ${shapeName} (${model}): ${figures.join(', ')}`);
    });
  }
  test(`${id}: centering ${pattern.followsRegion ? 'has no effect (follows the region)' : 'moves the pattern phase'}`, () => {
    const region = TEST_SHAPES.square();
    const a = generateInfill(id, layerAt(region, 1.4), testParams(0.2));
    const b = generateInfill(
      id,
      layerAt(region, 1.4),
      testParams(0.2, { centering: 'global', origin: { x: 117_345, y: 98_765 } }),
    );
    if (pattern.followsRegion) assert.deepEqual(b, a);
    else assert.notDeepEqual(b, a);
  });
  test(`${id}: connect=false leaves every line end unjoined, and empty inputs give empty results`, () => {
    const region = TEST_SHAPES.square();
    const r = generateInfill(id as PatternId, layerAt(region, 1.4), testParams(0.2, { connect: false }));
    assert.ok(r.lines.length + r.loops.length > 0);
    assert.deepEqual(generateInfill(id, layerAt([], 1.4), testParams(0.2)), { lines: [], loops: [] });
    assert.deepEqual(generateInfill(id, layerAt(region, 1.4), testParams(0)), { lines: [], loops: [] });
  });
}

test('custom infill takes every region’s place and its paths are taken as drawn, at any density setting', () => {
  const drawn: InfillResult = {
    lines: [
      [
        { x: 0, y: 0 },
        { x: 9_000, y: 0 },
      ],
    ],
    loops: [],
  };
  const custom: InfillPattern = { id: 'custom', description: 'a test', finished: true, generate: () => drawn };
  for (const id of PATTERN_IDS) {
    assert.equal(regionPattern(id, undefined), PATTERNS[id]);
    assert.equal(regionPattern(id, custom), custom);
  }
  const region = TEST_SHAPES.square();
  // not clipped, linked or ordered by the shared code, and drawn even where the setting is 0 (its own density)
  assert.equal(generateInfill(custom, layerAt(region, 1.4), testParams(0)), drawn);
});

test('the registry loads the custom infill module, which compiles an IceSL shader into a pattern', async () => {
  const { customPattern } = await loadCustomInfill();
  const stripes = 'vec4 cellular(vec3 world) { return vec4(mod(floor(world.x / 3.0), 2.0), 0.0, 0.0, 1.0); }';
  const pattern = customPattern({ name: 'stripes', shader: stripes }, resolveConfig({}));
  assert.equal(pattern.id, 'custom');
  assert.ok(pattern.finished);
  const region = TEST_SHAPES.square();
  const r = generateInfill(pattern, layerAt(region, 1.4), testParams(0.2));
  assert.ok(r.lines.length > 5, `stripes drawn: ${r.lines.length}`);
  assert.ok(outsideLength(r, region, 3) < 5, 'inside the region');
});
