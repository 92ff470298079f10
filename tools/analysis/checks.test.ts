import { test } from 'node:test';
import assert from 'node:assert/strict';
import { analyzePrint } from './checks.js';
import { formatReport } from './format-report.js';
import type { BoxPrintOptions } from './synthetic-print.js';
import { GcodeWriter, boxMesh, writeBoxPrint } from './synthetic-print.js';

const near = (a: number | null, b: number, tol: number, what = '') =>
  assert.ok(a !== null && Math.abs(a - b) <= tol, `${what} ${a} is not within ${tol} of ${b}`);

const SIZE: [number, number, number] = [21.6, 21.6, 6];
const ORIGIN: [number, number] = [50, 50];
const mesh = boxMesh(ORIGIN[0], ORIGIN[1], 0, ORIGIN[0] + SIZE[0], ORIGIN[1] + SIZE[1], SIZE[2]);
const OPTS = { layerHeight: 0.2, firstLayerHeight: 0.2, lineWidth: 0.4, filamentDiameter: 1.75 };

type Markers = 'cura' | 'prusa' | 'none';

function boxGcode(extra: Partial<BoxPrintOptions> = {}, relativeE = false, markers: Markers = 'cura') {
  const writer = new GcodeWriter({ lineWidth: 0.4, filamentDiameter: 1.75, relativeE, markers });
  writeBoxPrint({
    size: SIZE,
    origin: ORIGIN,
    layerHeight: 0.2,
    lineWidth: 0.4,
    walls: 2,
    skinLayers: 4,
    infillSpacing: 4,
    writer,
    ...extra,
  });
  return writer;
}

test('a perfect box print: walls, solid skin, 20 % infill, nothing outside', () => {
  const report = analyzePrint(mesh, boxGcode().text(), OPTS);
  const s = report.summary;
  assert.equal(s.layerCount, 30);
  assert.equal(s.expectedLayerCount, 30);
  assert.equal(s.zMismatchCount, 0);
  near(s.firstLayerZ, 0.2, 1e-9);
  near(s.walls.minCoverage, 1, 1e-9, 'walls');
  assert.deepEqual(s.walls.layersBelowThreshold, []);
  near(s.outside.maxMm, 0, 1e-6, 'outside');
  near(s.outside.areaMm2, 0, 0.01, 'outside area');
  near(s.skin.bottom.minCoverage, 1, 0.005, 'bottom skin');
  near(s.skin.top.minCoverage, 1, 0.005, 'top skin');
  near(s.skin.bottom.areaMm2, 4 * SIZE[0] * SIZE[1], 1, 'bottom area');
  // 20.8 %: five lines per direction in the measured 19.2 mm (see the line-grid test).
  near(s.infill.density, 0.2, 0.01, 'density');
  // Measured on layers 9..20: 4 skin layers and 1 mm (5 layers) of margin at each end.
  assert.equal(s.infill.layersMeasured, 12);
  assert.ok(s.shift.maxMm !== null && s.shift.maxMm < 0.01, `shift ${s.shift.maxMm}`);
  assert.deepEqual(s.shift.shiftedLayers, []);
  near(report.layers[5]!.shift!.inset, 0.2, 0.01, 'outer wall inset');
  assert.equal(s.e.balance.unbalanced, 0);
  near(s.e.flowRatio, 1 + (0.2 * (1 - Math.PI / 4)) / 0.4, 0.01, 'flow ratio');
  assert.ok((s.featureLengthMm['WALL-OUTER'] ?? 0) > 20 * 4 * 20);
  assert.ok(formatReport(report).includes('walls: outline coverage 100.0 %'));
});

test('absolute, relative and marker-less G-code give the same analysis', () => {
  const a = analyzePrint(mesh, boxGcode({}, false).text(), OPTS).summary;
  const r = analyzePrint(mesh, boxGcode({}, true, 'prusa').text(), OPTS).summary;
  const n = analyzePrint(mesh, boxGcode({}, true, 'none').text(), OPTS).summary;
  // Relative E rounds every move to 5 decimals, absolute E only the running total.
  near(r.e.extruded, a.e.extruded, 1e-5 * a.e.extruded, 'relative vs absolute');
  near(n.e.extruded, r.e.extruded, 1e-9, 'no markers');
  assert.equal(n.layerCount, 30);
  near(r.infill.density, a.infill.density!, 1e-5);
  near(n.skin.top.coverage, a.skin.top.coverage!, 1e-5);
});

test('a line outside the part is flagged with its distance', () => {
  const g = boxGcode();
  // On the last layer, a line 1 mm beyond the +X side (the section grown by half a width ends 0.2 mm out).
  const x = ORIGIN[0] + SIZE[0] + 1;
  g.type('WALL-OUTER').travel(x, 55).line(x, 60);
  const s = analyzePrint(mesh, g.text(), OPTS).summary;
  near(s.outside.maxMm, 0.8, 0.002, 'distance');
  assert.equal(s.outside.worstLayer, 29);
  // A 5 mm bead of width ~0.44 lies fully outside the grown section (raster: ± one cell across its width).
  near(s.outside.areaMm2, 5 * 0.443 + Math.PI * 0.22 * 0.22, 0.3, 'area');
  // Support and skirt are allowed outside.
  const h = boxGcode();
  h.type('SKIRT').travel(40, 40).line(80, 40).type('SUPPORT').travel(x, 55).line(x, 60);
  near(analyzePrint(mesh, h.text(), OPTS).summary.outside.maxMm, 0, 1e-9, 'skirt and support');
});

test('missing walls, missing skin and a shifted layer are caught', () => {
  const faulty = boxGcode({ skipWallsOn: [7], skipSkinOn: [28], shift: { layer: 10, dx: 0.3 } });
  const s = analyzePrint(mesh, faulty.text(), OPTS);
  const sum = s.summary;
  // The shifted layer's wall is 0.5 mm from one side of the outline, more than a line width: not walled either.
  assert.deepEqual(sum.walls.layersBelowThreshold, [7, 10]);
  near(s.layers[10]!.outlineCoverage, 0.75, 0.01, 'shifted layer walls');
  assert.equal(sum.skin.top.worstLayer, 28);
  assert.ok(sum.skin.top.minCoverage! < 0.2, `top coverage ${sum.skin.top.minCoverage}`);
  assert.deepEqual(sum.shift.shiftedLayers, [10]);
  near(s.layers[10]!.shift!.dx, 0.3, 0.02, 'dx');
  near(s.layers[10]!.shift!.dy, 0, 0.02, 'dy');
  // Its outer wall centreline is 0.1 mm outside the model: within the half-width tolerance, so only the shift fit
  // and the wall coverage tell.
  near(sum.outside.maxMm, 0, 1e-9, 'shifted wall within tolerance');
});

test('infill density of hand-made line grids at known spacing', () => {
  // Lines 0.4 wide at spacing s in both directions across the 20 mm core inside the two walls. The measured region
  // keeps a line width off the walls: [0.4, 19.6] mm of the core, so it holds the lines inside that band.
  for (const spacing of [2, 4, 5, 8, 10]) {
    const s = analyzePrint(mesh, boxGcode({ infillSpacing: spacing }).text(), OPTS).summary;
    let lines = 0;
    for (let x = spacing / 2; x < 20; x += spacing) if (x >= 0.4 && x <= 19.6) lines++;
    const exact = (2 * lines * 0.4) / 19.2;
    near(s.infill.density, exact, 0.01, `spacing ${spacing}`);
    // Edge effects aside, that is the nominal 2·w/s.
    near(s.infill.density, (2 * 0.4) / spacing, 0.025, `spacing ${spacing} nominal`);
  }
});

test('layer Z errors, missing layers and sampling', () => {
  const text = boxGcode().text().replace('G0 Z1.2 F600', 'G0 Z1.25 F600');
  const report = analyzePrint(mesh, text, { ...OPTS, sampleEvery: 5 });
  assert.deepEqual(report.summary.zMismatchLayers, [5]);
  assert.equal(report.summary.missingLayerCount, 1);
  near(report.summary.missingLayerZ[0]!, 1.2, 1e-9);
  assert.deepEqual(
    report.layers.map((l) => l.index),
    [0, 5, 10, 15, 20, 25, 29],
  );
  assert.equal(report.layers[1]!.zOk, false);
  assert.equal(report.layerZ.length, 30);
  // Drop layer 12 entirely: every later layer stays on the grid, one grid Z is missing.
  const lines = boxGcode().text().split('\n');
  const from = lines.indexOf(';LAYER:12');
  const to = lines.indexOf(';LAYER:13');
  const dropped = analyzePrint(mesh, [...lines.slice(0, from), ...lines.slice(to)].join('\n'), OPTS).summary;
  assert.equal(dropped.layerCount, 29);
  assert.equal(dropped.zMismatchCount, 0);
  assert.equal(dropped.missingLayerCount, 1);
  near(dropped.missingLayerZ[0]!, 2.6, 1e-9);
});

test('bad options are errors', () => {
  assert.throws(() => analyzePrint(mesh, '', { ...OPTS, layerHeight: 0 }), /layerHeight/);
  const empty = analyzePrint(mesh, '', OPTS);
  assert.equal(empty.summary.layerCount, 0);
  assert.ok(empty.warnings.some((w) => w.includes('extrudes nothing')));
});
