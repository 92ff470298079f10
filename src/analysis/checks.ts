/**
 * analyzePrint: judges G-code against the model it was sliced from, as an outside reviewer would — layer heights,
 * walls on every outline, nothing outside the part, solid top and bottom skin, sparse infill density, consistent
 * E bookkeeping. Independent of Strata's slicer: own parser, sections and rasters.
 */
import type { Mesh } from '../mesh/types.js';
import { StrataError } from '../errors.js';
import type { FeatureName } from './feature-names.js';
import { FEATURE_NAMES } from './feature-names.js';
import { parseGcode } from './gcode-parse.js';
import type { GcodeLayer, ParsedGcode } from './gcode-types.js';
import type { LayerContext, LayerMeasure, ResolvedOptions } from './layer-analysis.js';
import { measureLayer, skinMarginLayers } from './layer-analysis.js';
import { filamentArea, segmentLength } from './raster.js';
import type { AnalyzeOptions, LayerReport, PrintReport, PrintSummary } from './report-types.js';
import { SectionCache } from './section-cache.js';
import { WeightedHistogram, quantileWithZeros } from './stats.js';

export type { AnalyzeOptions, LayerReport, PrintReport, PrintSummary } from './report-types.js';

const DEFAULT_CELL_MM = 0.05;
/** Cells of one layer raster at most; a larger model gets a coarser cell. */
const MAX_LAYER_CELLS = 16e6;
/** Margin around the model assumed when sizing rasters (mm). */
const RASTER_MARGIN_MM = 10;
const MAX_LISTED = 50;
/** Surfaces smaller than this many line widths squared do not count for the worst skin layer. */
const MIN_SKIN_LINE_WIDTHS_SQUARED = 10;
/** Bead-width histogram resolution (mm). */
const WIDTH_BIN_MM = 0.001;
/** A flow ratio outside this range is warned about. */
const FLOW_RATIO_RANGE: [number, number] = [0.5, 2];

export function analyzePrint(mesh: Mesh, gcodeText: string, options: AnalyzeOptions): PrintReport {
  const opts = resolveOptions(options);
  const t0 = performance.now();
  const parsed = parseGcode(gcodeText);
  const parseMs = performance.now() - t0;
  return analyzeParsed(mesh, parsed, opts, parseMs);
}

/** The same analysis for G-code already parsed (for example with the streaming parser). */
export function analyzeParsed(mesh: Mesh, parsed: ParsedGcode, options: AnalyzeOptions, parseMs = 0): PrintReport {
  const opts = resolveOptions(options);
  const t0 = performance.now();
  const warnings: string[] = [];
  const cell = cellSizeFor(mesh, opts.cellSize);
  if (cell > opts.cellSize) warnings.push(`raster cell grown to ${cell.toFixed(3)} mm to bound memory`);
  const sections = new SectionCache(mesh, cell);
  const widths = new WeightedHistogram(4 * opts.lineWidth, WIDTH_BIN_MM);
  const ctx: LayerContext = {
    opts,
    cell,
    sections,
    hasTypes: parsed.hasTypeMarkers,
    filamentArea: filamentArea(opts.filamentDiameter),
    widths,
  };

  const retractionsByLayer = new Uint32Array(parsed.layers.length);
  for (let k = 0; k < parsed.retractions.count; k++) {
    const l = parsed.retractions.layer[k]!;
    if (l >= 0 && parsed.retractions.kind[k]! % 2 === 0) retractionsByLayer[l]!++;
  }

  const last = parsed.layers.length - 1;
  const step = Math.max(1, Math.floor(opts.sampleEvery));
  const layers: LayerReport[] = [];
  const positives: Float64Array[] = [];
  let samples = 0;
  for (const layer of parsed.layers) {
    const i = layer.index;
    if (i % step !== 0 && i !== 0 && i !== last) continue;
    const m = measureLayer(layer, ctx);
    positives.push(m.outsidePositives);
    samples += m.outsideSamples;
    layers.push(layerReport(layer, m, opts, retractionsByLayer[i]!));
    const keep = Math.round(opts.bottomThickness / opts.layerHeight) + skinMarginLayers(opts) + 2;
    sections.dropBelow(m.sectionZ - keep * opts.layerHeight);
  }

  const summary = summarize(parsed, layers, opts, sections, widths, positives, samples);
  summary.cellSizeMm = cell;
  summary.timingMs = { parse: parseMs, analyse: performance.now() - t0 };
  warnings.push(...collectWarnings(parsed, summary, sections, opts));
  return { summary, layers, layerZ: parsed.layers.map((l) => l.z), warnings };
}

function resolveOptions(o: AnalyzeOptions): ResolvedOptions {
  const positive = (name: string, v: number | undefined) => {
    if (typeof v !== 'number' || !(v > 0) || !Number.isFinite(v)) {
      throw new StrataError('BAD_SETTING', `analyzePrint: ${name} must be a positive number (got ${String(v)})`);
    }
    return v;
  };
  const lineWidth = positive('lineWidth', o.lineWidth);
  const widthSource = o.widthSource ?? 'flow';
  if (widthSource !== 'flow' && widthSource !== 'nominal') {
    throw new StrataError('BAD_SETTING', `analyzePrint: widthSource must be 'flow' or 'nominal' (got ${widthSource})`);
  }
  return {
    layerHeight: positive('layerHeight', o.layerHeight),
    firstLayerHeight: positive('firstLayerHeight', o.firstLayerHeight),
    lineWidth,
    filamentDiameter: positive('filamentDiameter', o.filamentDiameter),
    cellSize: positive('cellSize', o.cellSize ?? DEFAULT_CELL_MM),
    wallThickness: positive('wallThickness', o.wallThickness ?? 2 * lineWidth),
    topThickness: positive('topThickness', o.topThickness ?? 0.8),
    bottomThickness: positive('bottomThickness', o.bottomThickness ?? 0.8),
    widthSource,
    sampleEvery: positive('sampleEvery', o.sampleEvery ?? 1),
    zTolerance: positive('zTolerance', o.zTolerance ?? 0.005),
    skinMargin: positive('skinMargin', o.skinMargin ?? 1),
    wallCoverageThreshold: positive('wallCoverageThreshold', o.wallCoverageThreshold ?? 0.95),
    shiftTolerance: positive('shiftTolerance', o.shiftTolerance ?? 0.1),
  };
}

function cellSizeFor(mesh: Mesh, requested: number): number {
  const p = mesh.positions;
  let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
  for (let k = 0; k < p.length; k += 3) {
    xmin = Math.min(xmin, p[k]!);
    xmax = Math.max(xmax, p[k]!);
    ymin = Math.min(ymin, p[k + 1]!);
    ymax = Math.max(ymax, p[k + 1]!);
  }
  if (!(xmax >= xmin)) return requested;
  const area = (xmax - xmin + 2 * RASTER_MARGIN_MM) * (ymax - ymin + 2 * RASTER_MARGIN_MM);
  return Math.max(requested, Math.sqrt(area / MAX_LAYER_CELLS));
}

/** The nearest Z of the layer grid (firstLayerHeight, then every layerHeight) and its grid index. */
function gridZ(z: number, o: ResolvedOptions): [number, number] {
  const k = Math.max(0, Math.round((z - o.firstLayerHeight) / o.layerHeight));
  return [o.firstLayerHeight + k * o.layerHeight, k];
}

/** Layers whose mid-height lies below the model top: the first at firstLayerHeight/2, then every layerHeight. */
function expectedLayerCount(zTop: number, o: ResolvedOptions): number {
  if (!(zTop > o.firstLayerHeight / 2)) return 0;
  const x = (zTop - o.firstLayerHeight) / o.layerHeight + 0.5;
  return 1 + Math.max(0, Math.ceil(x - 1e-9) - 1);
}

function featureLengths(layer: GcodeLayer): Partial<Record<FeatureName, number>> {
  const sums = new Float64Array(FEATURE_NAMES.length);
  const t = layer.extrusions;
  for (let i = 0; i < t.count; i++) sums[t.feature[i]!] = sums[t.feature[i]!]! + segmentLength(t, i);
  const out: Partial<Record<FeatureName, number>> = {};
  sums.forEach((v, k) => {
    if (v > 0) out[FEATURE_NAMES[k]!] = v;
  });
  return out;
}

function travelLength(layer: GcodeLayer): number {
  const t = layer.travels;
  let sum = 0;
  for (let i = 0; i < t.count; i++) {
    sum += Math.hypot(t.x1[i]! - t.x0[i]!, t.y1[i]! - t.y0[i]!, t.z1[i]! - t.z0[i]!);
  }
  return sum;
}

const orNull = (v: number) => (Number.isFinite(v) ? v : null);

function layerReport(layer: GcodeLayer, m: LayerMeasure, o: ResolvedOptions, retractions: number): LayerReport {
  const [ez] = gridZ(layer.z, o);
  const shiftMm = m.shift ? Math.hypot(m.shift.dx, m.shift.dy) : null;
  return {
    index: layer.index,
    z: layer.z,
    thickness: layer.thickness,
    expectedZ: ez,
    zOk: Math.abs(layer.z - ez) <= o.zTolerance,
    marker: layer.marker,
    sectionZ: m.sectionZ,
    sectionAreaMm2: m.sectionAreaMm2,
    sectionEmpty: m.section.segments.count === 0,
    materialAreaMm2: m.materialAreaMm2,
    outlineLengthMm: m.outlineLengthMm,
    thinOutlineMm: m.thinOutlineMm,
    outlineCoverage: orNull(m.outlineCoverage),
    shift: m.shift,
    shiftMm,
    outsideMaxMm: m.outsideMaxMm,
    outsideP99Mm: m.outsideP99Mm,
    outsideAreaMm2: m.outsideAreaMm2,
    topSkin: { areaMm2: m.topAreaMm2, coverage: orNull(m.topCoverage) },
    bottomSkin: { areaMm2: m.bottomAreaMm2, coverage: orNull(m.bottomCoverage) },
    infillRegionAreaMm2: m.infillRegionAreaMm2,
    infillDensity: orNull(m.infillDensity),
    widthMedianMm: orNull(m.widthMedianMm),
    featureLengthMm: featureLengths(layer),
    travelLengthMm: travelLength(layer),
    retractions,
  };
}

/**
 * Skin summary: coverage weighted by surface area over all layers; the worst layer among those whose surface is
 * at least minArea (slivers of a fraction of a mm² that no slicer fills would otherwise always be the worst).
 */
function skinSummary(layers: LayerReport[], pick: (l: LayerReport) => { areaMm2: number; coverage: number | null },
  minArea: number) {
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

function summarize(
  parsed: ParsedGcode, layers: LayerReport[], o: ResolvedOptions, sections: SectionCache,
  widths: WeightedHistogram, positives: Float64Array[], samples: number,
): PrintSummary {
  const zMismatch: number[] = [];
  let zMismatchCount = 0;
  const onGrid = new Set<number>();
  for (const l of parsed.layers) {
    const [z, k] = gridZ(l.z, o);
    if (Math.abs(l.z - z) > o.zTolerance) {
      zMismatchCount++;
      if (zMismatch.length < MAX_LISTED) zMismatch.push(l.index);
    } else {
      onGrid.add(k);
    }
  }
  const expectedCount = expectedLayerCount(sections.zMax, o);
  const missing: number[] = [];
  let missingCount = 0;
  for (let k = 0; k < expectedCount; k++) {
    if (onGrid.has(k)) continue;
    missingCount++;
    if (missing.length < MAX_LISTED) missing.push(o.firstLayerHeight + k * o.layerHeight);
  }

  let wallLen = 0, wallCovered = 0;
  let wallMin: number | null = null, wallWorst: number | null = null;
  const wallsBelow: number[] = [];
  let outMax = 0, outArea = 0;
  let outWorst: number | null = null;
  const emptyLayers: number[] = [];
  let emptyMaterial = 0;
  let infillArea = 0, infillCovered = 0, infillLayers = 0;
  let infillMin: number | null = null, infillMax: number | null = null;
  let shiftMax: number | null = null, shiftWorst: number | null = null;
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
    for (let i = 0; i < t.count; i++) featureTotals[t.feature[i]!] = featureTotals[t.feature[i]!]! + segmentLength(t, i);
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
  };
}

function partMaterialLength(l: LayerReport): number {
  const f = l.featureLengthMm;
  return (f['UNKNOWN'] ?? 0) + (f['WALL-OUTER'] ?? 0) + (f['WALL-INNER'] ?? 0) + (f['SKIN'] ?? 0) + (f['FILL'] ?? 0);
}

function collectWarnings(parsed: ParsedGcode, s: PrintSummary, sections: SectionCache, o: ResolvedOptions): string[] {
  const w: string[] = [];
  if (parsed.layers.length === 0) w.push('the G-code extrudes nothing');
  if (!parsed.hasLayerMarkers) w.push('no layer markers: layers are the distinct Z heights of extrusion');
  if (!parsed.hasTypeMarkers) w.push('no ;TYPE: markers: infill density counts every extrusion in the infill region');
  if (parsed.unknownTypes.length > 0) w.push(`unknown ;TYPE: names treated as part material: ${parsed.unknownTypes.join(', ')}`);
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
