import { test } from 'node:test';
import assert from 'node:assert/strict';
import { analyzePrint } from './checks.js';
import { formatReport } from './format-report.js';
import type { AnalyzeOptions, PrintReport } from './report-types.js';
import { boxMesh, mergeMeshes, rectLines } from './synthetic-print.js';
import { toyGcode } from './toy-slicer.js';
import type { ToyOptions } from './toy-slicer.js';

const within = (v: number | null, lo: number, hi: number, what: string) =>
  assert.ok(v !== null && v >= lo && v <= hi, `${what}: ${v} is not in [${lo}, ${hi}]`);

const LW = 0.4;
const H = 0.2;
const FIL = 1.75;
const OPTS: AnalyzeOptions = { layerHeight: H, firstLayerHeight: H, lineWidth: LW, filamentDiameter: FIL };
const TOY: ToyOptions = {
  layerHeight: H,
  firstLayerHeight: H,
  lineWidth: LW,
  filamentDiameter: FIL,
  infillSpacing: 4,
  skinLayers: 4,
};

// A T: a 10 × 20 mm column up to z = 4 under a 30 × 20 mm plate up to z = 6. Its arms (two 10 × 20 mm) start on
// layer 20 (mid-height 4.1) over nothing.
const T = mergeMeshes(boxMesh(50, 50, 0, 60, 70, 4), boxMesh(40, 50, 4, 70, 70, 6));
const ARM_LAYER = 20;
/** The arms' area beyond the threshold's allowance (50°: 0.24 mm from the column). */
const OVERHANG_MM2 = 2 * (10 - H * Math.tan((50 * Math.PI) / 180)) * 20;
/** Under each arm, 0.6 mm (the XY gap) off the column. */
const SUPPORT_RECTS: [number, number, number, number][] = [
  [40, 50, 49.4, 70],
  [60.6, 50, 70, 70],
];

/** Support under the arms up to layer ARM_LAYER - 1 - gap: lines 2 mm apart, the top two layers dense interface. */
function supportUnderArms(gap: number, rects = SUPPORT_RECTS) {
  const top = ARM_LAYER - 1 - gap;
  return (i: number, _z: number, h: number): string[] => {
    if (i > top) return [];
    const dense = i >= top - 1;
    const type = dense ? 'SUPPORT-INTERFACE' : 'SUPPORT';
    return rects.flatMap((r) => rectLines(r, dense ? LW : 2, h, LW, FIL, type, !dense));
  };
}

function tPrint(extra?: ToyOptions['extra'], options: Partial<AnalyzeOptions> = {}): PrintReport {
  return analyzePrint(T, toyGcode(T, { ...TOY, ...(extra ? { extra } : {}) }), { ...OPTS, ...options });
}

test('a T without support: its arms overhang unsupported and lie over nothing', () => {
  const r = tPrint();
  const u = r.summary.support!;
  within(u.overhangAreaMm2, 0.95 * OVERHANG_MM2, 1.05 * OVERHANG_MM2, 'overhang area');
  within(u.overhangSupported, 0, 0.2, 'overhang supported');
  assert.equal(u.overhangWorstLayers[0]!.layer, ARM_LAYER);
  // The arms' first layer (bottom skin and walls across 390 mm²) is over nothing; nothing else is.
  within(u.overNothingMm2, 0.8 * OVERHANG_MM2, 1.1 * OVERHANG_MM2, 'over nothing area');
  assert.equal(u.overNothingWorstLayers[0]!.layer, ARM_LAYER);
  within(u.overNothing, 0.03, 0.2, 'over nothing share');
  assert.equal(u.supportLayers, 0);
  assert.equal(u.topGap.medianMm, null);
  assert.equal(u.volume.supportMm3, 0);
  // The layer report carries the same.
  within(r.layers[ARM_LAYER]!.support!.overhangAreaMm2, 0.95 * OVERHANG_MM2, 1.05 * OVERHANG_MM2, 'layer overhang');
  assert.match(formatReport(r), /supported \d\.\d %/);
});

test('a T with support under its arms: overhang supported, nothing over nothing, nothing inside, one layer gap', () => {
  const r = tPrint(supportUnderArms(1));
  const s = r.summary;
  const u = s.support!;
  within(u.overhangSupported, 0.95, 1, 'overhang supported');
  within(u.overNothing, 0, 0.003, 'over nothing');
  within(u.insideAreaMm2, 0, 1, 'support inside the part');
  assert.equal(u.topGap.medianLayers, 1);
  assert.equal(u.topGap.minLayers, 1);
  within(u.topGap.medianMm, 0.19, 0.21, 'top gap (mm)');
  within(u.topGap.byLayers[1]!, 0.9, 1, 'share of the top gap at one layer');
  // Support stands on the bed: no bottom gap.
  assert.equal(u.bottomGap.medianMm, null);
  assert.equal(u.supportLayers, ARM_LAYER - 1);
  // Volume: the written E back (two rectangles of lines, per layer).
  const v = u.volume;
  assert.ok(v.supportMm3 > 0 && v.interfaceMm3 > 0, JSON.stringify(v));
  within(v.modelMm3, 10 * 20 * 4 + 30 * 20 * 2 - 1e-6, 10 * 20 * 4 + 30 * 20 * 2 + 1e-6, 'model volume');
  within(v.supportShare, (v.supportMm3 + v.interfaceMm3) / v.modelMm3 - 1e-9, 1, 'support share');
  // Dense interface 2 layers × 2 rectangles × ~9.5 × 20 mm² × 0.2 mm ≈ 150 mm³ of interface.
  within(v.interfaceMm3, 130, 170, 'interface volume');
  assert.equal(v.raftMm3, 0);
  // The part checks ignore support: nothing outside, walls everywhere.
  assert.equal(s.outside.maxMm, 0);
  within(s.walls.coverage, 0.99, 1, 'walls');
  assert.ok(formatReport(r).includes('top Z gap: median 0.20 mm (1 layer)'), formatReport(r));
});

test('the top Z gap is measured in layers, and support farther down than supportGapLayers does not hold', () => {
  for (const gap of [0, 1, 2, 3]) {
    const u = tPrint(supportUnderArms(gap)).summary.support!;
    assert.equal(u.topGap.medianLayers, gap, `gap ${gap}`);
    if (gap <= 2) {
      within(u.overhangSupported, 0.95, 1, `supported at gap ${gap}`);
      within(u.overNothing, 0, 0.003, `over nothing at gap ${gap}`);
    } else {
      within(u.overhangSupported, 0, 0.2, `supported at gap ${gap}`);
      within(u.overNothing, 0.03, 0.2, `over nothing at gap ${gap}`);
    }
  }
  // With supportGapLayers 3, a three-layer gap holds again.
  const u = tPrint(supportUnderArms(3), { supportGapLayers: 3 }).summary.support!;
  within(u.overhangSupported, 0.95, 1, 'supported at gap 3 when allowed');
});

test('support under half of each arm supports about half of the overhang', () => {
  const half: [number, number, number, number][] = [
    [40, 60, 49.4, 70],
    [60.6, 60, 70, 70],
  ];
  const u = tPrint(supportUnderArms(1, half)).summary.support!;
  within(u.overhangSupported, 0.45, 0.58, 'half supported');
});

test('support inside the part is measured by area, and a bead touching the wall is not inside', () => {
  // Layers 5..9: a dense 6 × 10 mm patch of support in the middle of the column, 5 × 60 mm² in all.
  const patch = (i: number, _z: number, h: number) =>
    i >= 5 && i <= 9 ? rectLines([52, 55, 58, 65], LW, h, LW, FIL, 'SUPPORT') : [];
  const inside = tPrint(patch).summary.support!;
  within(inside.insideAreaMm2, 0.8 * 300, 1.2 * 300, 'inside area');
  within(inside.insideWorstMm2, 0.8 * 60, 1.2 * 60, 'worst layer');
  within(inside.insideWorstLayer, 5, 9, 'worst layer index');
  // A support line whose bead touches the column's -x wall from outside, and one overlapping it by a quarter of
  // its width: neither counts.
  const touching = (i: number, _z: number, h: number) =>
    i >= 5 && i <= 9
      ? [
          ...rectLines([49.6, 51, 50, 69], LW, h, LW, FIL, 'SUPPORT', true),
          ...rectLines([59.9, 51, 60.3, 69], LW, h, LW, FIL, 'SUPPORT-INTERFACE', true),
        ]
      : [];
  const edge = tPrint(touching).summary.support!;
  assert.ok(edge.supportAreaMm2 > 5 * 2 * 18 * 0.4 * 0.9, `support area ${edge.supportAreaMm2}`);
  within(edge.insideAreaMm2, 0, 1, 'touching beads');
});

/** Raft layers under the column's footprint grown by 3 mm: a 0.3 mm base of wide lines, two 0.2 mm layers. */
function raft(type: string) {
  const rect: [number, number, number, number] = [47, 47, 63, 73];
  return [
    { z: 0.3, h: 0.3, lines: rectLines(rect, 1.6, 0.3, 0.8, FIL, type) },
    { z: 0.5, h: 0.2, lines: rectLines(rect, 1, 0.2, 0.8, FIL, type, true) },
    { z: 0.7, h: 0.2, lines: rectLines(rect, LW, 0.2, LW, FIL, type) },
  ];
}
/** Raft top 0.7 and a 0.2 mm air gap: the part's first layer (0.2 thick) prints at 1.1. */
const RAFT_OFFSET = 0.9;

test('a raft raises the model: its offset is found and every check lines up with the sections', () => {
  const plain = tPrint().summary;
  for (const type of ['SUPPORT-INTERFACE', 'RAFT']) {
    const gcode = toyGcode(T, { ...TOY, prelude: raft(type), zOffset: RAFT_OFFSET });
    const r = analyzePrint(T, gcode, OPTS);
    const s = r.summary;
    assert.equal(s.modelZ.source, 'detected', type);
    within(s.modelZ.offsetMm, RAFT_OFFSET - 1e-6, RAFT_OFFSET + 1e-6, `${type} offset`);
    assert.equal(s.modelZ.raftLayerCount, 3);
    assert.equal(s.modelZ.firstModelLayer, 3);
    within(s.modelZ.raftGapMm, 0.2 - 1e-6, 0.2 + 1e-6, 'air gap');
    assert.deepEqual(
      r.layers.slice(0, 4).map((l) => l.role),
      ['raft', 'raft', 'raft', 'part'],
    );
    within(r.layers[3]!.modelZ, H - 1e-6, H + 1e-6, 'first model layer Z');
    // The part's checks read as without the raft.
    assert.equal(s.zMismatchCount, 0);
    assert.equal(s.missingLayerCount, 0);
    assert.equal(s.outside.maxMm, 0);
    assert.deepEqual(s.outside.emptySectionLayers, []);
    within(s.walls.coverage, plain.walls.coverage! - 1e-3, 1, `${type} walls`);
    within(s.skin.bottom.coverage, plain.skin.bottom.coverage! - 1e-3, 1, `${type} bottom skin`);
    within(s.infill.density, plain.infill.density! - 1e-3, plain.infill.density! + 1e-3, `${type} density`);
    // The raft is neither support nor part; the first model layer rests on it.
    const u = s.support!;
    assert.equal(u.volume.supportMm3 + u.volume.interfaceMm3, 0, type);
    // Base 16 × 26 mm at 1.6 mm spacing, 0.8 wide, 0.3 high, and two 0.2 mm layers: about 100 + 83 + 83 mm³.
    within(u.volume.raftMm3, 200, 320, `${type} raft volume`);
    assert.equal(u.supportLayers, 0);
    assert.ok(!u.overNothingWorstLayers.some((w) => w.layer === 3), JSON.stringify(u.overNothingWorstLayers));
    within(u.overhangSupported, 0, 0.2, 'arms still unsupported');
    within(u.overhangAreaMm2, 0.95 * OVERHANG_MM2, 1.05 * OVERHANG_MM2, 'overhang area over a raft');
  }
});

// A T standing on a slab: the slab 30 × 20 mm up to z = 2 under the column and the arms.
const T_ON_SLAB = mergeMeshes(
  boxMesh(40, 50, 0, 70, 70, 2),
  boxMesh(50, 50, 2, 60, 70, 4),
  boxMesh(40, 50, 4, 70, 70, 6),
);

/**
 * Support standing on the slab (its top layer 9), one layer above it: a floor of two dense layers whose lines cross,
 * a sparse body, the roof two dense layers under the arms, one layer below them.
 */
function supportOnSlab(i: number, _z: number, h: number): string[] {
  if (i < 11 || i > ARM_LAYER - 2) return [];
  const dense = i <= 12 || i >= ARM_LAYER - 3;
  const type = dense ? 'SUPPORT-INTERFACE' : 'SUPPORT';
  return SUPPORT_RECTS.flatMap((r) => rectLines(r, dense ? 0.57 : 2, h, LW, FIL, type, i % 2 === 0));
}

test('support standing on the part one layer above it has a one-layer bottom gap, between dense floor lines and over a raft too', () => {
  const slab: [number, number, number, number] = [37, 47, 73, 73];
  const raftUnder = [
    { z: 0.3, h: 0.3, lines: rectLines(slab, 1.6, 0.3, 0.8, FIL, 'SUPPORT-INTERFACE') },
    { z: 0.5, h: 0.2, lines: rectLines(slab, 1, 0.2, 0.8, FIL, 'SUPPORT-INTERFACE', true) },
    { z: 0.7, h: 0.2, lines: rectLines(slab, LW, 0.2, LW, FIL, 'SUPPORT-INTERFACE') },
  ];
  for (const raft of [false, true]) {
    const gcode = toyGcode(T_ON_SLAB, {
      ...TOY,
      extra: supportOnSlab,
      ...(raft ? { prelude: raftUnder, zOffset: RAFT_OFFSET } : {}),
    });
    const u = analyzePrint(T_ON_SLAB, gcode, OPTS).summary.support!;
    const what = raft ? 'over a raft' : 'on the bed';
    within(u.overhangSupported, 0.95, 1, `supported, ${what}`);
    assert.equal(u.bottomGap.medianLayers, 1, `bottom gap, ${what}`);
    within(u.bottomGap.byLayers[1]!, 0.95, 1, `share of the bottom gap at one layer, ${what}`);
    // what stands on the slab: the first floor's lines, 70 % of 2 × 9.4 × 20 mm²
    within(u.bottomGap.areaMm2, 220, 330, `bottom gap area, ${what}`);
  }
});

test('the model Z offset can be given, and a wrong one misaligns the checks', () => {
  const gcode = toyGcode(T, { ...TOY, prelude: raft('RAFT'), zOffset: RAFT_OFFSET });
  const given = analyzePrint(T, gcode, { ...OPTS, modelZOffset: RAFT_OFFSET }).summary;
  assert.equal(given.modelZ.source, 'option');
  assert.equal(given.zMismatchCount, 0);
  assert.deepEqual(given.outside.emptySectionLayers, []);
  // Read as if the part stood on the bed, the top layers print above the model.
  const wrong = analyzePrint(T, gcode, { ...OPTS, modelZOffset: 0 }).summary;
  assert.ok(wrong.outside.emptySectionLayers.length >= 4, JSON.stringify(wrong.outside));
  assert.ok(wrong.zMismatchCount > 0);
});

test('support checks can be turned off, and bad support options are errors', () => {
  const r = tPrint(undefined, { supportChecks: false });
  assert.equal(r.summary.support, null);
  assert.equal(r.layers[ARM_LAYER]!.support, null);
  assert.throws(() => tPrint(undefined, { overhangAngleDeg: 95 }), /overhangAngleDeg/);
  assert.throws(() => tPrint(undefined, { supportSpanMm: 0 }), /supportSpanMm/);
  assert.throws(() => tPrint(undefined, { modelZOffset: -1 }), /modelZOffset/);
});

test('the overhang threshold sets how far a layer may reach past the one below', () => {
  // At 80° a 0.2 mm layer may reach 1.13 mm past the one below: the arms overhang by 8.87 mm each.
  const steep = tPrint(undefined, { overhangAngleDeg: 80 }).summary.support!;
  const allowed = H * Math.tan((80 * Math.PI) / 180);
  within(steep.overhangAreaMm2, 0.95 * 2 * (10 - allowed) * 20, 1.05 * 2 * (10 - allowed) * 20, 'overhang at 80°');
  // At 88.9° it may reach 10.4 mm: the arms are no overhang, and their first layer lies within reach.
  const flat = tPrint(undefined, { overhangAngleDeg: 88.9 }).summary.support!;
  within(flat.overhangAreaMm2, 0, 1, 'overhang at 88.9°');
  within(flat.overNothing, 0, 0.003, 'over nothing at 88.9°');
});
