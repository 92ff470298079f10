/** The whole-print summary of a report, gathered from the analysed layers and the parsed G-code, and warnings. */
import type { FeatureName } from './feature-names.js';
import { FEATURE_NAMES } from './feature-names.js';
import type { ParsedGcode } from './gcode-types.js';
import type { ResolvedOptions } from './layer-analysis.js';
import { expectedLayerCount, gridZ, onZGrid, orNull, thicknessOk, travelLength } from './layer-report.js';
import type { LayerFrame } from './model-z.js';
import { segmentLength } from './raster.js';
import type { LayerReport, PrintSummary } from './report-types.js';
import type { SectionCache } from './section-cache.js';
import type { WeightedHistogram } from './stats.js';
import { quantileWithZeros } from './stats.js';

const MAX_LISTED = 50;
/** Surfaces smaller than this many line widths squared do not count for the worst skin layer. */
const MIN_SKIN_LINE_WIDTHS_SQUARED = 10;
/** A flow ratio outside this range is warned about. */
const FLOW_RATIO_RANGE: [number, number] = [0.5, 2];

/**
 * Skin summary: coverage weighted by surface area over all layers; the worst layer among those whose surface is
 * at least minArea (slivers of a fraction of a mm² that no slicer fills would otherwise always be the worst).
 */
function skinSummary(
  layers: LayerReport[],
  pick: (l: LayerReport) => { areaMm2: number; coverage: number | null },
  minArea: number,
) {
  let area = 0;
  let coveredArea = 0;
  let min: number | null = null;
  let worst: number | null = null;
  for (const l of layers) {
    const s = pick(l);
    if (s.coverage === null) continue;
    area += s.areaMm2;
    coveredArea += s.areaMm2 * s.coverage;
    if (s.areaMm2 < minArea) continue;
    if (min === null || s.coverage < min) {
      min = s.coverage;
      worst = l.index;
    }
  }
  return { areaMm2: area, coverage: area > 0 ? coveredArea / area : null, minCoverage: min, worstLayer: worst };
}

interface GridCheck {
  zMismatch: number[];
  zMismatchCount: number;
  expectedCount: number;
  missing: number[];
  missingCount: number;
}

/** Layer Zs against the even grid (firstLayerHeight, then every layerHeight): off-grid layers, grid Zs not printed. */
function evenGrid(parsed: ParsedGcode, frames: readonly LayerFrame[], zTop: number, o: ResolvedOptions): GridCheck {
  const zMismatch: number[] = [];
  let zMismatchCount = 0;
  const onGrid = new Set<number>();
  for (const l of parsed.layers) {
    const frame = frames[l.index]!;
    // The first layer over a raft stands for the grid's first layer wherever the air gap puts it.
    if (frame.firstOverRaft) onGrid.add(0);
    if (!onZGrid(frame)) continue;
    const [z, k] = gridZ(frame.modelZ, o);
    if (Math.abs(frame.modelZ - z) > o.zTolerance) {
      zMismatchCount++;
      if (zMismatch.length < MAX_LISTED) zMismatch.push(l.index);
    } else {
      onGrid.add(k);
    }
  }
  const expectedCount = expectedLayerCount(zTop, o);
  const missing: number[] = [];
  let missingCount = 0;
  for (let k = 0; k < expectedCount; k++) {
    if (onGrid.has(k)) continue;
    missingCount++;
    if (missing.length < MAX_LISTED) missing.push(o.firstLayerHeight + k * o.layerHeight);
  }

  return { zMismatch, zMismatchCount, expectedCount, missing, missingCount };
}

/**
 * Layer Zs with variable layer height: part layers thinner or thicker than the range (off-grid), and the
 * layers left out where two part layers (or the last one and the model's top) are further apart than max.
 */
function variableGrid(
  parsed: ParsedGcode,
  frames: readonly LayerFrame[],
  zTop: number,
  [, max]: readonly [number, number],
  o: ResolvedOptions,
): GridCheck {
  const out: GridCheck = { zMismatch: [], zMismatchCount: 0, expectedCount: 0, missing: [], missingCount: 0 };
  let last = 0;
  const skipped = (from: number, gap: number) => {
    const n = Math.max(0, Math.ceil((gap - o.zTolerance) / max) - 1);
    for (let k = 1; k <= n; k++) if (out.missing.length < MAX_LISTED) out.missing.push(from + (k * gap) / (n + 1));
    out.missingCount += n;
  };
  for (const l of parsed.layers) {
    const frame = frames[l.index]!;
    if (!onZGrid(frame)) continue;
    out.expectedCount++;
    if (!thicknessOk(frame, o.layerHeightRange!, o)) {
      out.zMismatchCount++;
      if (out.zMismatch.length < MAX_LISTED) out.zMismatch.push(l.index);
    }
    if (Number.isFinite(frame.partThickness) && frame.modelZ - last > max + o.zTolerance)
      skipped(last, frame.modelZ - last);
    last = frame.modelZ;
  }
  // the top: a layer is missing when the model goes on more than half a layer above the last
  if (zTop - last > max / 2 + o.zTolerance) skipped(last, zTop - last + max / 2);
  out.expectedCount += out.missingCount;
  return out;
}

export function summarize(
  parsed: ParsedGcode,
  layers: LayerReport[],
  o: ResolvedOptions,
  sections: SectionCache,
  widths: WeightedHistogram,
  positives: Float64Array[],
  samples: number,
  frames: readonly LayerFrame[],
): PrintSummary {
  const { zMismatch, zMismatchCount, expectedCount, missing, missingCount } = o.layerHeightRange
    ? variableGrid(parsed, frames, sections.zMax, o.layerHeightRange, o)
    : evenGrid(parsed, frames, sections.zMax, o);

  let wallLen = 0,
    wallCovered = 0;
  let wallMin: number | null = null,
    wallWorst: number | null = null;
  const wallsBelow: number[] = [];
  let outMax = 0,
    outArea = 0;
  let outWorst: number | null = null;
  const emptyLayers: number[] = [];
  let emptyMaterial = 0;
  let infillArea = 0,
    infillCovered = 0,
    infillLayers = 0;
  let infillMin: number | null = null,
    infillMax: number | null = null;
  let shiftMax: number | null = null,
    shiftWorst: number | null = null;
  const shifted: number[] = [];
  for (const l of layers) {
    const partLength = partMaterialLength(l);
    if (l.sectionEmpty) {
      if (partLength > 0) {
        if (emptyLayers.length < MAX_LISTED) emptyLayers.push(l.index);
        emptyMaterial += partLength;
      }
      continue;
    }
    if (l.outlineCoverage !== null) {
      wallLen += l.outlineLengthMm;
      wallCovered += l.outlineLengthMm * l.outlineCoverage;
      if (wallMin === null || l.outlineCoverage < wallMin) {
        wallMin = l.outlineCoverage;
        wallWorst = l.index;
      }
      if (l.outlineCoverage < o.wallCoverageThreshold && wallsBelow.length < MAX_LISTED) wallsBelow.push(l.index);
    }
    if (l.outsideMaxMm > outMax) {
      outMax = l.outsideMaxMm;
      outWorst = l.index;
    }
    outArea += l.outsideAreaMm2;
    if (l.infillDensity !== null) {
      infillLayers++;
      infillArea += l.infillRegionAreaMm2;
      infillCovered += l.infillRegionAreaMm2 * l.infillDensity;
      infillMin = infillMin === null ? l.infillDensity : Math.min(infillMin, l.infillDensity);
      infillMax = infillMax === null ? l.infillDensity : Math.max(infillMax, l.infillDensity);
    }
    if (l.shiftMm !== null) {
      if (shiftMax === null || l.shiftMm > shiftMax) {
        shiftMax = l.shiftMm;
        shiftWorst = l.index;
      }
      if (l.shiftMm > o.shiftTolerance && shifted.length < MAX_LISTED) shifted.push(l.index);
    }
  }
  let totalPositives = 0;
  for (const p of positives) totalPositives += p.length;
  const allPositives = new Float64Array(totalPositives);
  let at = 0;
  for (const p of positives) {
    allPositives.set(p, at);
    at += p.length;
  }

  const featureTotals = new Float64Array(FEATURE_NAMES.length);
  let travel = 0;
  for (const layer of parsed.layers) {
    const t = layer.extrusions;
    for (let i = 0; i < t.count; i++) {
      featureTotals[t.feature[i]!] = featureTotals[t.feature[i]!]! + segmentLength(t, i);
    }
    travel += travelLength(layer);
  }
  const featureLengthMm: Partial<Record<FeatureName, number>> = {};
  featureTotals.forEach((v, k) => {
    if (v > 0) featureLengthMm[FEATURE_NAMES[k]!] = v;
  });
  let preamble = 0;
  for (let i = 0; i < parsed.preamble.extrusions.count; i++) preamble += segmentLength(parsed.preamble.extrusions, i);

  const widthMedian = widths.quantile(0.5);
  const minSkinArea = MIN_SKIN_LINE_WIDTHS_SQUARED * o.lineWidth * o.lineWidth;
  return {
    layerCount: parsed.layers.length,
    expectedLayerCount: expectedCount,
    missingLayerZ: missing,
    missingLayerCount: missingCount,
    firstLayerZ: parsed.layers.length > 0 ? parsed.layers[0]!.z : null,
    zMismatchLayers: zMismatch,
    zMismatchCount,
    analysedLayers: layers.length,
    walls: {
      coverage: wallLen > 0 ? wallCovered / wallLen : null,
      minCoverage: wallMin,
      worstLayer: wallWorst,
      layersBelowThreshold: wallsBelow,
    },
    outside: {
      maxMm: outMax,
      p99Mm: quantileWithZeros(allPositives, samples, 0.99),
      areaMm2: outArea,
      worstLayer: outWorst,
      emptySectionLayers: emptyLayers,
      materialOnEmptySectionMm: emptyMaterial,
    },
    skin: {
      top: skinSummary(layers, (l) => l.topSkin, minSkinArea),
      bottom: skinSummary(layers, (l) => l.bottomSkin, minSkinArea),
    },
    infill: {
      density: infillArea > 0 ? infillCovered / infillArea : null,
      minDensity: infillMin,
      maxDensity: infillMax,
      layersMeasured: infillLayers,
      regionAreaMm2: infillArea,
    },
    shift: { maxMm: shiftMax, worstLayer: shiftWorst, shiftedLayers: shifted },
    e: {
      ...parsed.e,
      balance: parsed.balance,
      widthMedianMm: orNull(widthMedian),
      flowRatio: Number.isFinite(widthMedian) ? widthMedian / o.lineWidth : null,
    },
    featureLengthMm,
    travelLengthMm: travel,
    retractionCount: parsed.balance.retractions + parsed.balance.firmwareRetractions,
    preambleExtrusionMm: preamble,
    extents: parsed.extents,
    hasLayerMarkers: parsed.hasLayerMarkers,
    hasTypeMarkers: parsed.hasTypeMarkers,
    cellSizeMm: 0,
    timingMs: { parse: 0, analyse: 0 },
    modelZ: { offsetMm: 0, source: 'none', firstModelLayer: null, raftLayerCount: 0, raftGapMm: null },
    support: null,
  };
}

function partMaterialLength(l: LayerReport): number {
  const f = l.featureLengthMm;
  return (f['UNKNOWN'] ?? 0) + (f['WALL-OUTER'] ?? 0) + (f['WALL-INNER'] ?? 0) + (f['SKIN'] ?? 0) + (f['FILL'] ?? 0);
}

export function collectWarnings(
  parsed: ParsedGcode,
  s: PrintSummary,
  sections: SectionCache,
  o: ResolvedOptions,
): string[] {
  const w: string[] = [];
  if (parsed.layers.length === 0) w.push('the G-code extrudes nothing');
  if (!parsed.hasLayerMarkers) w.push('no layer markers: layers are the distinct Z heights of extrusion');
  if (!parsed.hasTypeMarkers) w.push('no ;TYPE: markers: infill density counts every extrusion in the infill region');
  if (parsed.unknownTypes.length > 0) {
    w.push(`unknown ;TYPE: names treated as part material: ${parsed.unknownTypes.join(', ')}`);
  }
  if (parsed.e.mode === 'mixed') w.push('E switches between absolute and relative mode while extruding');
  if (sections.gapsClosed > 0 || sections.chainsDropped > 0) {
    w.push(`open mesh: ${sections.gapsClosed} gaps in sections closed, ${sections.chainsDropped} open runs left out`);
  }
  if (Math.abs(sections.zMin) > o.zTolerance && sections.zMax > sections.zMin) {
    w.push(`the mesh is not on the bed (lowest Z ${sections.zMin.toFixed(3)} mm)`);
  }
  const ratio = s.e.flowRatio;
  if (ratio !== null && (ratio < FLOW_RATIO_RANGE[0] || ratio > FLOW_RATIO_RANGE[1])) {
    w.push(`median bead width is ${ratio.toFixed(2)}× the line width: check E mode and filament diameter`);
  }
  return w;
}
