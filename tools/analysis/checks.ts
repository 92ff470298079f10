/**
 * analyzePrint: judges G-code against the model it was sliced from, as an outside reviewer would — layer heights,
 * walls on every outline, nothing outside the part, solid top and bottom skin, sparse infill density, consistent
 * E bookkeeping. Independent of Strata's slicer: own parser, sections and rasters.
 */
import type { Mesh } from '#strata/mesh/types.js';
import { StrataError } from '#strata/errors.js';
import { parseGcode } from './gcode-parse.js';
import type { ParsedGcode } from './gcode-types.js';
import type { LayerContext, ResolvedOptions } from './layer-analysis.js';
import { effectiveThickness, measureLayer, partThickness, skinMarginLayers, widthHistogram } from './layer-analysis.js';
import { modelZFrames } from './model-z.js';
import { layerReport } from './layer-report.js';
import { collectWarnings, summarize } from './print-summary.js';
import { filamentArea } from './raster.js';
import type { AnalyzeOptions, LayerReport, PrintReport } from './report-types.js';
import { SectionCache } from './section-cache.js';
import { SupportAnalysis } from './support.js';
import { meshVolume, supportVolumes } from './support-volume.js';

export type { AnalyzeOptions, LayerReport, PrintReport, PrintSummary } from './report-types.js';

const DEFAULT_CELL_MM = 0.05;
/** Cells of one layer raster at most; a larger model gets a coarser cell. */
const MAX_LAYER_CELLS = 16e6;
/** Margin around the model assumed when sizing rasters (mm). */
const RASTER_MARGIN_MM = 10;
/** Defaults of the support checks' options (see AnalyzeOptions). */
const DEFAULT_OVERHANG_ANGLE_DEG = 50;
const DEFAULT_SUPPORT_GAP_LAYERS = 2;
const DEFAULT_SUPPORT_SPAN_MM = 3;
const DEFAULT_OVERHANG_MIN_AREA_MM2 = 1;

export function analyzePrint(mesh: Mesh, gcodeText: string, options: AnalyzeOptions): PrintReport {
  resolveOptions(options); // bad options fail before the parse
  const t0 = performance.now();
  const parsed = parseGcode(gcodeText);
  const parseMs = performance.now() - t0;
  return analyzeParsed(mesh, parsed, options, parseMs);
}

/** The same analysis for G-code already parsed (for example with the streaming parser). */
export function analyzeParsed(mesh: Mesh, parsed: ParsedGcode, options: AnalyzeOptions, parseMs = 0): PrintReport {
  const opts = resolveOptions(options);
  const t0 = performance.now();
  const warnings: string[] = [];
  const bounds = meshBoundsXY(mesh);
  const cell = cellSizeFor(bounds, opts.cellSize);
  if (cell > opts.cellSize) warnings.push(`raster cell grown to ${cell.toFixed(3)} mm to bound memory`);
  const sections = new SectionCache(mesh, cell);
  const widths = widthHistogram(opts);
  const modelZ = modelZFrames(parsed.layers, opts);
  const frames = modelZ.frames;
  const ctx: LayerContext = {
    opts,
    cell,
    sections,
    hasTypes: parsed.hasTypeMarkers,
    filamentArea: filamentArea(opts.filamentDiameter),
    widths,
    frames,
  };
  const support =
    opts.supportChecks && bounds
      ? new SupportAnalysis(parsed.layers, modelZ, sections, bounds, {
          layerHeight: opts.layerHeight,
          lineWidth: opts.lineWidth,
          wallThickness: opts.wallThickness,
          overhangAngleDeg: opts.overhangAngleDeg,
          supportGapLayers: opts.supportGapLayers,
          supportSpanMm: opts.supportSpanMm,
          overhangMinAreaMm2: opts.overhangMinAreaMm2,
          cell,
          filamentArea: ctx.filamentArea,
          widthSource: opts.widthSource,
          partHeight: (f) => partThickness(f, opts),
          supportHeight: (f) => effectiveThickness(f.supportThickness, f.raft && f.modelZ <= 0, opts),
        })
      : null;

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
    const report = layerReport(layer, m, opts, retractionsByLayer[i]!, frames[i]!);
    report.support = support ? support.measure(i, m.sectionZ) : null;
    layers.push(report);
    const keep = Math.round(opts.bottomThickness / opts.layerHeight) + skinMarginLayers(opts) + 2;
    sections.dropBelow(m.sectionZ - keep * opts.layerHeight);
  }

  const summary = summarize(parsed, layers, opts, sections, widths, positives, samples, frames);
  summary.cellSizeMm = cell;
  summary.modelZ = {
    offsetMm: modelZ.offsetMm,
    source: modelZ.source,
    firstModelLayer: modelZ.firstModelLayer,
    raftLayerCount: modelZ.raftLayerCount,
    raftGapMm: modelZ.raftGapMm,
  };
  summary.support = support
    ? support.summary(supportVolumes(parsed.layers, frames, ctx.filamentArea, meshVolume(mesh)))
    : null;
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
    modelZOffset: o.modelZOffset === undefined ? null : nonNegative('modelZOffset', o.modelZOffset),
    layerHeightRange: o.layerHeightRange === undefined ? null : heightRange(o.layerHeightRange),
    supportChecks: o.supportChecks ?? true,
    overhangAngleDeg: angle(o.overhangAngleDeg ?? DEFAULT_OVERHANG_ANGLE_DEG),
    supportGapLayers: nonNegative('supportGapLayers', o.supportGapLayers ?? DEFAULT_SUPPORT_GAP_LAYERS),
    supportSpanMm: positive('supportSpanMm', o.supportSpanMm ?? DEFAULT_SUPPORT_SPAN_MM),
    overhangMinAreaMm2: nonNegative('overhangMinAreaMm2', o.overhangMinAreaMm2 ?? DEFAULT_OVERHANG_MIN_AREA_MM2),
  };
}

function heightRange(r: unknown): [number, number] {
  if (
    !Array.isArray(r) ||
    r.length !== 2 ||
    !r.every((v) => typeof v === 'number' && v > 0 && Number.isFinite(v)) ||
    r[0] > r[1]
  ) {
    throw new StrataError(
      'BAD_SETTING',
      `analyzePrint: layerHeightRange must be [min, max] mm with 0 < min <= max (got ${JSON.stringify(r)})`,
    );
  }
  return [r[0], r[1]];
}

function nonNegative(name: string, v: number | undefined): number {
  if (typeof v !== 'number' || !(v >= 0) || !Number.isFinite(v)) {
    throw new StrataError('BAD_SETTING', `analyzePrint: ${name} must be a number >= 0 (got ${String(v)})`);
  }
  return v;
}

function angle(v: number): number {
  if (typeof v !== 'number' || !(v > 0 && v < 90)) {
    throw new StrataError('BAD_SETTING', `analyzePrint: overhangAngleDeg must be between 0 and 90 (got ${String(v)})`);
  }
  return v;
}

/** [xmin, ymin, xmax, ymax] of the mesh's vertices, null without vertices. */
function meshBoundsXY(mesh: Mesh): [number, number, number, number] | null {
  const p = mesh.positions;
  let xmin = Infinity,
    xmax = -Infinity,
    ymin = Infinity,
    ymax = -Infinity;
  for (let k = 0; k < p.length; k += 3) {
    xmin = Math.min(xmin, p[k]!);
    xmax = Math.max(xmax, p[k]!);
    ymin = Math.min(ymin, p[k + 1]!);
    ymax = Math.max(ymax, p[k + 1]!);
  }
  return xmax >= xmin ? [xmin, ymin, xmax, ymax] : null;
}

function cellSizeFor(bounds: [number, number, number, number] | null, requested: number): number {
  if (!bounds) return requested;
  const [xmin, ymin, xmax, ymax] = bounds;
  const area = (xmax - xmin + 2 * RASTER_MARGIN_MM) * (ymax - ymin + 2 * RASTER_MARGIN_MM);
  return Math.max(requested, Math.sqrt(area / MAX_LAYER_CELLS));
}
