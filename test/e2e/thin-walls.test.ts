/**
 * Thin features with variable-width walls (`wallGenerator: 'variable'`): fins from below a line's width up to
 * four lines, a tapering wall and a comb of fins on a spine each print as much plastic as the model holds, where
 * it holds it, and the hollow calibration cube is laid without slivers of line and with solid skins. Judged from
 * the G-code alone (thin-measure.ts): each line's width is its E over its length and layer height.
 *
 * The measurement is tested first, on G-code written here, so the bars cannot pass by measuring nothing.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { skipWithoutModels, sliceAndAnalyze, type SlicedModel } from './models.js';
import {
  COMB_FIN_THICKNESSES,
  FIN_THICKNESSES,
  THIN_PART_HEIGHT,
  binaryStl,
  combPart,
  finsPart,
  polygonArea,
  prismTris,
  rectPolygon,
  taperPart,
  taperSections,
  type Polygon,
} from './thin-shapes.js';
import { beadLayers, measurePolygons, underWidthFraction, type PolygonMeasure } from './thin-measure.js';

const skip = skipWithoutModels();

const LAYER = 0.2;
/** The layers above the first two and below the top of a 4 mm part at 0.2 mm layers: Z 0.6 … 3.8. */
const BODY = { zMin: 3 * LAYER - 0.1, zMax: THIN_PART_HEIGHT - LAYER + 0.05 };

// ── the measurement, on G-code written here ──────────────────────────────────────────────────────────────

interface Line {
  type: string;
  x0: number;
  y0: number;
  x1: number;
  y1: number;
  /** Line width, mm. */
  w: number;
}

/** Relative-E G-code in the slicer's markers, one layer per entry, E from the rectangle flow model. */
function syntheticGcode(layers: Array<{ z: number; h: number; lines: Line[] }>): string {
  const fa = (Math.PI * 1.75 * 1.75) / 4;
  const out = ['G90', 'M83', 'G92 E0'];
  layers.forEach((layer, n) => {
    out.push(`;LAYER:${n}`, `;Z:${layer.z}`, `;HEIGHT:${layer.h}`, `G0 Z${layer.z} F600`);
    for (const l of layer.lines) {
      const e = (l.w * layer.h * Math.hypot(l.x1 - l.x0, l.y1 - l.y0)) / fa;
      out.push(`;TYPE:${l.type}`, `G0 X${l.x0} Y${l.y0} F6000`, `G1 X${l.x1} Y${l.y1} E${e.toFixed(6)} F1800`);
    }
  });
  return out.join('\n') + '\n';
}

/** A 2 × 10 mm rectangle at (50, 50) filled by five lines along Y, 0.4 mm apart, `w` wide, end to end. */
const RECT: Polygon = rectPolygon({ x0: 50, y0: 50, x1: 52, y1: 60 });
function fillLines(w: number, type = 'FILL'): Line[] {
  return [0.2, 0.6, 1.0, 1.4, 1.8].map((dx) => ({ type, x0: 50 + dx, y0: 50, x1: 50 + dx, y1: 60, w }));
}
const threeLayers = (lines: (k: number) => Line[]) => [0.2, 0.4, 0.6].map((z, k) => ({ z, h: 0.2, lines: lines(k) }));
/** The two upper layers. */
const UPPER = { zMin: 0.3, zMax: 0.7 };
/** Bead area beyond the grown rectangle of one line's two round ends: two circular segments, r 0.2, 0.1 deep. */
const CAP_OUT = 2 * (0.04 * Math.acos(0.5) - 0.1 * Math.sqrt(0.03));

test('measure: a rectangle filled with lines of the line width', () => {
  const g = syntheticGcode(threeLayers(() => fillLines(0.4)));
  const [m] = measurePolygons(g, [RECT], UPPER);
  assert.equal(m.layers, 2);
  assert.ok(Math.abs(m.heightSpanMm - 0.4) < 1e-6, `height span ${m.heightSpanMm}`);
  assert.ok(Math.abs(m.areaMm2 - 20) < 1e-9);
  assert.ok(Math.abs(m.volumeRatio - 1) < 0.005, `volume ratio ${m.volumeRatio}`);
  assert.ok(m.coverage > 0.995, `coverage ${m.coverage}`);
  assert.ok(Math.abs(m.outsideMm2 - 5 * CAP_OUT) < 0.03, `outside ${m.outsideMm2} vs ${5 * CAP_OUT}`);
  assert.ok(m.minWidthMm !== null && Math.abs(m.minWidthMm - 0.4) < 0.002 && Math.abs(m.maxWidthMm! - 0.4) < 0.002);
  // nothing there: nothing measured
  const [empty] = measurePolygons(g, [rectPolygon({ x0: 70, y0: 50, x1: 72, y1: 60 })], UPPER);
  assert.equal(empty.volumeRatio, 0);
  assert.equal(empty.coverage, 0);
  assert.equal(empty.outsideMm2, 0);
  assert.equal(empty.minWidthMm, null);
  // out of the Z range: no layers
  const [above] = measurePolygons(g, [RECT], { zMin: 1, zMax: 2 });
  assert.equal(above.layers, 0);
  assert.equal(above.coverage, 0);
});

test('measure: half-width lines cover half, skirt lines do not count, a stray line is outside', () => {
  const half = syntheticGcode(
    threeLayers(() => [
      ...fillLines(0.2),
      // skirt between the fill lines: not part material
      ...[0.4, 0.8, 1.2, 1.6].map((dx) => ({ type: 'SKIRT', x0: 50 + dx, y0: 50, x1: 50 + dx, y1: 60, w: 0.2 })),
    ]),
  );
  const [m] = measurePolygons(half, [RECT], UPPER);
  assert.ok(Math.abs(m.volumeRatio - 0.5) < 0.005, `volume ratio ${m.volumeRatio}`);
  assert.ok(Math.abs(m.coverage - 0.5) < 0.03, `coverage ${m.coverage}`);
  assert.ok(m.maxWidthMm !== null && Math.abs(m.maxWidthMm - 0.2) < 0.002, `width ${m.maxWidthMm}`);

  // a wall 0.5 mm left of the rectangle, on the upper two layers only: its whole capsule is outside
  const stray = syntheticGcode(
    threeLayers((k) => [
      ...fillLines(0.4),
      ...(k > 0 ? [{ type: 'WALL-OUTER', x0: 49.5, y0: 50, x1: 49.5, y1: 60, w: 0.4 }] : []),
    ]),
  );
  const [s] = measurePolygons(stray, [RECT], UPPER);
  const capsule = 10 * 0.4 + Math.PI * 0.04;
  assert.ok(
    Math.abs(s.outsideMm2 - (5 * CAP_OUT + capsule)) < 0.05,
    `outside ${s.outsideMm2} vs ${5 * CAP_OUT + capsule}`,
  );
  assert.ok(Math.abs(s.volumeRatio - 1) < 0.005, `its midpoint is outside, so not in the volume: ${s.volumeRatio}`);
  // on the first layer alone it is not there
  const [first] = measurePolygons(stray, [RECT], { zMin: 0.1, zMax: 0.3 });
  assert.ok(Math.abs(first.outsideMm2 - 5 * CAP_OUT) < 0.03, `first layer outside ${first.outsideMm2}`);
  // an allowed area is not outside
  const [ok] = measurePolygons(stray, [RECT], UPPER, { allowed: [rectPolygon({ x0: 49, y0: 49, x1: 50, y1: 61 })] });
  assert.ok(ok.outsideMm2 < 5 * CAP_OUT + 0.03, `outside with the stray line allowed ${ok.outsideMm2}`);
});

test('measure: under-width fraction over part lines only', () => {
  const g = syntheticGcode(
    threeLayers((k) => [
      ...fillLines(0.4),
      ...(k === 1
        ? [
            { type: 'WALL-INNER', x0: 60, y0: 50, x1: 60, y1: 60, w: 0.15 }, // part, narrow: 10 mm
            { type: 'SKIRT', x0: 40, y0: 50, x1: 40, y1: 70, w: 0.1 }, // not part
            { type: 'SUPPORT', x0: 45, y0: 50, x1: 45, y1: 70, w: 0.1 }, // not part
          ]
        : []),
    ]),
  );
  const f = underWidthFraction(g, 0.2);
  assert.ok(Math.abs(f - 10 / 160) < 1e-3, `under 0.2 mm: ${f}`);
  assert.equal(underWidthFraction(g, 0.1), 0);
  assert.ok(Math.abs(underWidthFraction(g, 0.5) - 1) < 1e-9);
  // widths as the layers see them
  const layers = beadLayers(g);
  assert.equal(layers.length, 3);
  assert.equal(layers[1].count, 6);
  assert.ok(Math.abs(layers[1].width[5] - 0.15) < 0.001, `narrow wall ${layers[1].width[5]}`);
});

test('thin parts: closed, consistently wound meshes of the right volume', () => {
  const fins = finsPart(),
    taper = taperPart(),
    comb = combPart();
  const combVolume = (4 * 20 + COMB_FIN_THICKNESSES.reduce((s, t) => s + 6 * t, 0)) * 4;
  for (const [name, stl, volume] of [
    ['fins', fins.stl, FIN_THICKNESSES.reduce((s, t) => s + t * 10 * 4, 0)],
    ['taper', taper.stl, 20 * 1.1 * 4],
    ['comb', comb.stl, combVolume],
  ] as const) {
    const dv = new DataView(stl.buffer, stl.byteOffset, stl.byteLength);
    const n = dv.getUint32(80, true);
    assert.equal(stl.byteLength, 84 + 50 * n);
    const edges = new Map<string, number>();
    let vol = 0;
    for (let t = 0; t < n; t++) {
      const v = [0, 1, 2].map((k) => [0, 1, 2].map((m) => dv.getFloat32(84 + 50 * t + 12 + 12 * k + 4 * m, true)));
      const [a, b, c] = v;
      vol +=
        (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) /
        6;
      for (let k = 0; k < 3; k++) {
        const key = `${v[k].join(',')}>${v[(k + 1) % 3].join(',')}`;
        edges.set(key, (edges.get(key) ?? 0) + 1);
      }
    }
    for (const [key, count] of edges) {
      const [p, q] = key.split('>');
      assert.equal(count, 1, `${name}: edge ${key} used ${count} times in one direction`);
      assert.equal(edges.get(`${q}>${p}`), 1, `${name}: edge ${key} has no twin`);
    }
    assert.ok(Math.abs(vol - volume) < 1e-3 * volume, `${name}: volume ${vol} vs ${volume}`);
  }
  assert.ok(Math.abs(polygonArea(taper.outline) - 22) < 1e-9);
  assert.ok(Math.abs(polygonArea(comb.outline) - combVolume / 4) < 1e-9);
  assert.equal(fins.fins.length, FIN_THICKNESSES.length);
});

// ── the bars ─────────────────────────────────────────────────────────────────────────────────────────────

type Generator = 'variable' | 'classic';
const slices = new Map<string, Promise<string>>();

/** G-code of a thin part (in its own XY: `center: false`), sliced once per generator. */
function sliceThin(name: string, stl: Uint8Array, wallGenerator: Generator): Promise<string> {
  const key = `${name}/${wallGenerator}`;
  let p = slices.get(key);
  if (!p) {
    const options: SliceOptions = { threads: 1, center: false, wallGenerator };
    p = new Slicer(options).slice(stl).then((r) => r.gcode);
    slices.set(key, p);
  }
  return p;
}

const cubes = new Map<Generator, Promise<SlicedModel>>();
function sliceCube(wallGenerator: Generator): Promise<SlicedModel> {
  let p = cubes.get(wallGenerator);
  if (!p) {
    p = sliceAndAnalyze('HollowCalibrationCube.stl', { wallGenerator });
    cubes.set(wallGenerator, p);
  }
  return p;
}

const fmt = (m: PolygonMeasure) =>
  `coverage ${m.coverage.toFixed(3)}, volume ${m.volumeRatio.toFixed(3)}, outside ${m.outsideMm2.toFixed(3)} mm², ` +
  `widths ${m.minWidthMm?.toFixed(3) ?? '-'}…${m.maxWidthMm?.toFixed(3) ?? '-'} mm`;

test('fins 0.25-1.6 mm: each printed, covered ≥ 85 %, 0.8-1.3 × its volume, ≤ 5 % of its area outside', {
  timeout: 60_000,
}, async (t) => {
  const part = finsPart();
  const gcode = await sliceThin('fins', part.stl, 'variable');
  const measures = measurePolygons(
    gcode,
    part.fins.map((f) => f.polygon),
    BODY,
  );
  const failed: string[] = [];
  part.fins.forEach((fin, k) => {
    const m = measures[k];
    t.diagnostic(`fin ${fin.thickness} mm: ${fmt(m)}`);
    assert.equal(m.layers, 17, 'layers in range');
    const bad = [
      Math.min(...m.layerCoverage) >= 0.5 ? '' : `a layer only ${Math.min(...m.layerCoverage).toFixed(3)} covered`,
      m.coverage >= 0.85 ? '' : `coverage ${m.coverage.toFixed(3)}`,
      m.volumeRatio >= 0.8 && m.volumeRatio <= 1.3 ? '' : `volume ratio ${m.volumeRatio.toFixed(3)}`,
      m.outsideMm2 <= 0.05 * m.areaMm2 ? '' : `outside ${m.outsideMm2.toFixed(3)} mm² of ${m.areaMm2.toFixed(2)}`,
    ].filter((s) => s);
    if (bad.length) failed.push(`fin ${fin.thickness} mm: ${bad.join(', ')}`);
  });
  assert.deepEqual(failed, []);
});

test('taper 0.2-2 mm: covered ≥ 90 % along its length, ≤ 5 % of its area outside', { timeout: 60_000 }, async (t) => {
  const part = taperPart();
  const gcode = await sliceThin('taper', part.stl, 'variable');
  const quarters = taperSections(part, 4);
  const [whole, ...parts] = measurePolygons(gcode, [part.outline, ...quarters], BODY);
  t.diagnostic(`whole: ${fmt(whole)}`);
  // a quarter's own volume and outside mean little (long wall lines run across quarters): only its coverage is judged
  parts.forEach((m, k) => t.diagnostic(`quarter ${k + 1}: coverage ${m.coverage.toFixed(3)}`));
  const failed: string[] = [];
  if (whole.coverage < 0.9) failed.push(`whole coverage ${whole.coverage.toFixed(3)}`);
  if (whole.outsideMm2 > 0.05 * whole.areaMm2)
    failed.push(`outside ${whole.outsideMm2.toFixed(3)} mm² of ${whole.areaMm2.toFixed(2)}`);
  parts.forEach((m, k) => {
    if (m.coverage < 0.9) failed.push(`quarter ${k + 1} coverage ${m.coverage.toFixed(3)}`);
  });
  assert.deepEqual(failed, []);
});

test('comb: fins 0.3-1.0 mm standing off a spine covered ≥ 85 %', { timeout: 60_000 }, async (t) => {
  const part = combPart();
  const gcode = await sliceThin('comb', part.stl, 'variable');
  const measures = measurePolygons(
    gcode,
    part.fins.map((f) => f.polygon),
    BODY,
    { allowed: [rectPolygon(part.spine)] },
  );
  const failed: string[] = [];
  part.fins.forEach((fin, k) => {
    t.diagnostic(`fin ${fin.thickness} mm: ${fmt(measures[k])}`);
    if (measures[k].coverage < 0.85)
      failed.push(`fin ${fin.thickness} mm: coverage ${measures[k].coverage.toFixed(3)}`);
  });
  assert.deepEqual(failed, []);
});

test('HollowCalibrationCube: ≤ 1 % of part lines under 0.2 mm wide, top and bottom skin ≥ 99 %', {
  skip,
  timeout: 120_000,
}, async (t) => {
  const { gcode, report } = await sliceCube('variable');
  const under = underWidthFraction(gcode, 0.2);
  const { top, bottom } = report.summary.skin;
  t.diagnostic(`under 0.2 mm: ${(under * 100).toFixed(2)} %, top skin ${top.coverage}, bottom skin ${bottom.coverage}`);
  assert.ok(under <= 0.01, `part lines under 0.2 mm: ${(under * 100).toFixed(2)} % of their length`);
  assert.ok(top.coverage !== null && top.coverage >= 0.99, `top skin ${top.coverage}`);
  assert.ok(bottom.coverage !== null && bottom.coverage >= 0.99, `bottom skin ${bottom.coverage}`);
});

test('classic walls still slice, and differently from variable ones', { timeout: 120_000 }, async () => {
  for (const [name, stl] of [
    ['fins', finsPart().stl],
    ['taper', taperPart().stl],
    ['comb', combPart().stl],
  ] as const) {
    const classic = await sliceThin(name, stl, 'classic');
    const variable = await sliceThin(name, stl, 'variable');
    assert.match(classic, /;TYPE:WALL-OUTER/, `${name}: classic walls`);
    assert.ok(classic !== variable, `${name}: classic and variable G-code differ`);
  }
});

test('HollowCalibrationCube: classic walls still slice, and differently from variable ones', {
  skip,
  timeout: 120_000,
}, async () => {
  const classic = await sliceCube('classic');
  const variable = await sliceCube('variable');
  assert.match(classic.gcode, /;TYPE:WALL-OUTER/);
  assert.ok(classic.layers > 0);
  assert.ok(classic.gcode !== variable.gcode, 'classic and variable G-code differ');
});

test('fins: two slices give byte-identical G-code', { timeout: 60_000 }, async () => {
  const part = finsPart();
  const first = await sliceThin('fins', part.stl, 'variable');
  const again = (await new Slicer({ threads: 1, center: false, wallGenerator: 'variable' }).slice(part.stl)).gcode;
  assert.ok(first.length > 1000);
  assert.ok(first === again, 'run to run');
});

test('a feature thinner than minFeatureSize is left out and the result says where and how much', {
  timeout: 60_000,
}, async () => {
  // a 10 × 10 mm block with a 0.06 mm fin standing off it, 12 mm long, 2 mm tall
  const block = prismTris(rectPolygon({ x0: 100, y0: 100, x1: 110, y1: 110 }), 0, 2);
  const fin = prismTris(rectPolygon({ x0: 112, y0: 100, x1: 112.06, y1: 112 }), 0, 2);
  const stl = binaryStl([...block, ...fin]);
  const r = await new Slicer({ threads: 1, center: false }).slice(stl);
  const lost = r.stats.thinLost;
  assert.ok(lost.length >= 8, `layers with area left out: ${lost.length}`);
  const total = lost.reduce((a, l) => a + l.areaMm2, 0);
  // 0.06 × 12 mm a layer, over the layers the fin stands in (all but a layer or two at its ends)
  assert.ok(
    total > 0.5 * 0.72 * lost.length && total < 1.5 * 0.72 * lost.length,
    `area left out ${total} mm² over ${lost.length} layers`,
  );
  assert.ok(
    lost.every((l) => l.z <= 2.01),
    'only the fin layers',
  );
  assert.equal(r.warnings.filter((w) => /too thin to print/.test(w)).length, 1, r.warnings.join('; '));
  // a fin the walls can print is not reported
  const printable = binaryStl([...block, ...prismTris(rectPolygon({ x0: 112, y0: 100, x1: 112.3, y1: 112 }), 0, 2)]);
  const ok = await new Slicer({ threads: 1, center: false }).slice(printable);
  assert.equal(ok.stats.thinLost.reduce((a, l) => a + l.areaMm2, 0) < 0.05, true, 'nothing reported for a 0.3 mm fin');
  assert.equal(ok.warnings.length, 0, ok.warnings.join('; '));
});
