/**
 * analyzePrint: judges G-code against the model it was sliced from, as an outside reviewer would — layer heights,
 * walls on every outline, nothing outside the part, solid top and bottom skin, sparse infill density, consistent
 * E bookkeeping. Independent of Strata's slicer: own parser, sections and rasters.
 */
import type { Mesh } from '../mesh/types.js';
import { StrataError } from '../errors.js';
import { parseGcode } from './gcode-parse.js';
import type { ParsedGcode } from './gcode-types.js';
import type { LayerContext, ResolvedOptions } from './layer-analysis.js';
import { measureLayer, skinMarginLayers, widthHistogram } from './layer-analysis.js';
import { layerReport } from './layer-report.js';
import { collectWarnings, summarize } from './print-summary.js';
import { filamentArea } from './raster.js';
import type { AnalyzeOptions, LayerReport, PrintReport } from './report-types.js';
import { SectionCache } from './section-cache.js';

export type { AnalyzeOptions, LayerReport, PrintReport, PrintSummary } from './report-types.js';

const DEFAULT_CELL_MM = 0.05;
/** Cells of one layer raster at most; a larger model gets a coarser cell. */
const MAX_LAYER_CELLS = 16e6;
/** Margin around the model assumed when sizing rasters (mm). */
const RASTER_MARGIN_MM = 10;

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
  const widths = widthHistogram(opts);
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
