/**
 * The raster checks of one printed layer against the model section at its mid-height: walls, stray material,
 * skin coverage, infill density and XY shift.
 */
import { isPartFeature } from './feature-names.js';
import type { ExtrusionTable, GcodeLayer } from './gcode-types.js';
import type { Grid } from './grid.js';
import { countSet, gridAround } from './grid.js';
import { measureInfill } from './infill-density.js';
import { outlineMetrics } from './outline.js';
import { measureOutside } from './outside.js';
import { beadWidth, rasterizeExtrusions, segmentLength } from './raster.js';
import type { AnalyzeOptions } from './report-types.js';
import type { LayerFrame } from './model-z.js';
import type { CachedSection, SectionCache } from './section-cache.js';
import { SegmentIndex, WindingIndex } from './segment-index.js';
import { skinRegions } from './skin.js';
import type { Spans } from './spans.js';
import { countInSpans, erodeSpans, isEmptySpans, spansArea, spansBoolean, spansBounds } from './spans.js';
import { WeightedHistogram } from './stats.js';

export type ResolvedOptions = Required<Omit<AnalyzeOptions, 'modelZOffset' | 'layerHeightRange'>> & {
  modelZOffset: number | null;
  layerHeightRange: [number, number] | null;
};

/** Material farther than this outside the section is not rasterised (its distance is still measured), mm. */
const RASTER_CLIP_MARGIN_MM = 5;
/** Bead widths are clamped to [MIN_BEAD_MM, MAX_BEAD_LINE_WIDTHS × lineWidth]. */
const MIN_BEAD_MM = 0.05;
const MAX_BEAD_LINE_WIDTHS = 4;
/** Resolution of bead-width medians (mm). */
const WIDTH_BIN_MM = 0.001;
/** The shift fit looks for extrusions up to this many line widths from the outline. */
const SHIFT_SEARCH_LINE_WIDTHS = 3;

export interface LayerContext {
  opts: ResolvedOptions;
  cell: number;
  sections: SectionCache;
  hasTypes: boolean;
  filamentArea: number;
  /** Bead-width histogram of the whole print, fed by each layer. */
  widths: WeightedHistogram;
  /** Each printed layer's place in the model's Z. */
  frames: readonly LayerFrame[];
}

export interface LayerMeasure {
  sectionZ: number;
  section: CachedSection;
  sectionAreaMm2: number;
  materialAreaMm2: number;
  outlineLengthMm: number;
  thinOutlineMm: number;
  outlineCoverage: number;
  shift: { dx: number; dy: number; inset: number } | null;
  /** Nonzero outside distances of centreline samples, and the number of samples. */
  outsidePositives: Float64Array;
  outsideSamples: number;
  outsideMaxMm: number;
  outsideP99Mm: number;
  outsideAreaMm2: number;
  topAreaMm2: number;
  topCoverage: number;
  bottomAreaMm2: number;
  bottomCoverage: number;
  infillRegionAreaMm2: number;
  infillDensity: number;
  widthMedianMm: number;
  partLengthMm: number;
}

/** The model's section height for a layer whose top is at model Z `modelZ`, `h` thick: its mid-height. */
export function modelSectionZ(modelZ: number, h: number): number {
  // Rounded to a nanometre so that float noise does not decide on which side of a mesh vertex the plane falls.
  return Math.round((modelZ - h / 2) * 1e6) / 1e6;
}

/** An empty length-weighted histogram of bead widths. */
export function widthHistogram(o: ResolvedOptions): WeightedHistogram {
  return new WeightedHistogram(MAX_BEAD_LINE_WIDTHS * o.lineWidth, WIDTH_BIN_MM);
}

/** Layers beyond the skin thickness that the infill region keeps away from top and bottom surfaces. */
export function skinMarginLayers(o: ResolvedOptions): number {
  return Math.ceil(o.skinMargin / o.layerHeight - 1e-9);
}

/**
 * Layer height used to turn E into width: the measured thickness (of the part's material, or of the support's)
 * when plausible, else the nominal one.
 */
export function effectiveThickness(measured: number, firstModelLayer: boolean, o: ResolvedOptions): number {
  const nominal = firstModelLayer ? o.firstLayerHeight : o.layerHeight;
  return measured > 0.25 * nominal && measured < 4 * nominal ? measured : nominal;
}

/** The part material's layer height on a printed layer (see model-z.ts). */
export function partThickness(frame: LayerFrame, o: ResolvedOptions): number {
  const first = frame.firstOverRaft || Math.abs(frame.modelZ - o.firstLayerHeight) <= o.zTolerance;
  return effectiveThickness(frame.partThickness, first, o);
}

export function measureLayer(layer: GcodeLayer, ctx: LayerContext): LayerMeasure {
  const o = ctx.opts;
  const frame = ctx.frames[layer.index]!;
  const h = partThickness(frame, o);
  const sectionZ = modelSectionZ(frame.modelZ, h);
  const section = ctx.sections.get(sectionZ);
  const t = layer.extrusions;

  // Raft layers and layers of support alone (PrusaSlicer prints support on a grid of its own) are not part layers.
  const judged = frame.hasPart;
  const part: number[] = [];
  if (judged) for (let i = 0; i < t.count; i++) if (isPartFeature(t.feature[i]!)) part.push(i);
  const partIds = Uint32Array.from(part);
  const widths = new Float32Array(t.count);
  const layerWidths = widthHistogram(o);
  let partLength = 0;
  for (const i of partIds) {
    const len = segmentLength(t, i);
    partLength += len;
    const w = o.widthSource === 'nominal' ? o.lineWidth : beadWidth(t.e[i]!, len, h, ctx.filamentArea);
    widths[i] = Math.min(MAX_BEAD_LINE_WIDTHS * o.lineWidth, Math.max(MIN_BEAD_MM, w));
    ctx.widths.add(w, len);
    layerWidths.add(w, len);
  }

  const result: LayerMeasure = {
    sectionZ,
    section,
    sectionAreaMm2: spansArea(section.spans),
    materialAreaMm2: 0,
    outlineLengthMm: 0,
    thinOutlineMm: 0,
    outlineCoverage: NaN,
    shift: null,
    outsidePositives: new Float64Array(0),
    outsideSamples: 0,
    outsideMaxMm: 0,
    outsideP99Mm: 0,
    outsideAreaMm2: 0,
    topAreaMm2: 0,
    topCoverage: NaN,
    bottomAreaMm2: 0,
    bottomCoverage: NaN,
    infillRegionAreaMm2: 0,
    infillDensity: NaN,
    widthMedianMm: layerWidths.quantile(0.5),
    partLengthMm: partLength,
  };
  const bounds = spansBounds(section.spans);
  if (!judged || !bounds || section.segments.count === 0) return result;

  const grid = layerGrid(bounds, t, partIds, ctx.cell, o.lineWidth);
  const material = rasterizeExtrusions(t, grid, widths, (i) => isPartFeature(t.feature[i]!));
  const materialCells = countSet(material);
  result.materialAreaMm2 = materialCells * ctx.cell * ctx.cell;

  const seg = section.segments;
  const inside = new WindingIndex(seg.x0, seg.y0, seg.x1, seg.y1, seg.count, 1);
  const index = new SegmentIndex(t.x0, t.y0, t.x1, t.y1, partIds, t.count, Math.max(0.5, o.lineWidth * 2));
  const outline = outlineMetrics(seg, inside, index, {
    coverRadius: o.lineWidth,
    searchRadius: SHIFT_SEARCH_LINE_WIDTHS * o.lineWidth,
    step: Math.min(2 * ctx.cell, o.lineWidth / 4),
    outlier: o.lineWidth / 2,
    minThickness: o.lineWidth / 2,
  });
  result.outlineLengthMm = outline.lengthMm;
  result.thinOutlineMm = outline.thinLengthMm;
  result.outlineCoverage = outline.coverage;
  result.shift = outline.shift;

  const out = measureOutside(t, partIds, section, inside, grid, material, materialCells, o.lineWidth / 2, ctx.cell);
  result.outsidePositives = out.positives;
  result.outsideSamples = out.samples;
  result.outsideMaxMm = out.maxMm;
  result.outsideP99Mm = out.p99Mm;
  result.outsideAreaMm2 = out.areaMm2;

  const nTop = Math.round(o.topThickness / o.layerHeight);
  const nBottom = Math.round(o.bottomThickness / o.layerHeight);
  const extra = skinMarginLayers(o);
  const above = neighbourSpans(ctx, sectionZ, +1, nTop + extra);
  const below = neighbourSpans(ctx, sectionZ, -1, nBottom + extra);
  const skin = skinRegions(section.spans, above.slice(0, nTop), below.slice(0, nBottom));
  const edge = ctx.cell;
  [result.topAreaMm2, result.topCoverage] = surfaceCoverage(skin.top, edge, grid, material);
  [result.bottomAreaMm2, result.bottomCoverage] = surfaceCoverage(skin.bottom, edge, grid, material);

  // The infill region also keeps skinMargin (in layers) away from skin above and below: slicers add solid or
  // supporting lines there (more top layers, skin edge support).
  const near = skinRegions(section.spans, above, below);
  const infill = measureInfill(t, grid, widths, section.spans, spansBoolean(near.top, near.bottom, 'union'), {
    wallThickness: o.wallThickness,
    lineWidth: o.lineWidth,
    skinMargin: o.skinMargin,
    typed: ctx.hasTypes,
    widthSource: o.widthSource,
    layerHeight: h,
    filamentArea: ctx.filamentArea,
  });
  result.infillRegionAreaMm2 = infill.regionAreaMm2;
  result.infillDensity = infill.density;
  return result;
}

function layerGrid(
  bounds: [number, number, number, number],
  t: ExtrusionTable,
  partIds: Uint32Array,
  cell: number,
  lineWidth: number,
): Grid {
  let [xmin, ymin, xmax, ymax] = bounds;
  for (const i of partIds) {
    xmin = Math.min(xmin, t.x0[i]!, t.x1[i]!);
    xmax = Math.max(xmax, t.x0[i]!, t.x1[i]!);
    ymin = Math.min(ymin, t.y0[i]!, t.y1[i]!);
    ymax = Math.max(ymax, t.y0[i]!, t.y1[i]!);
  }
  xmin = Math.max(xmin, bounds[0] - RASTER_CLIP_MARGIN_MM);
  ymin = Math.max(ymin, bounds[1] - RASTER_CLIP_MARGIN_MM);
  xmax = Math.min(xmax, bounds[2] + RASTER_CLIP_MARGIN_MM);
  ymax = Math.min(ymax, bounds[3] + RASTER_CLIP_MARGIN_MM);
  return gridAround(xmin, ymin, xmax, ymax, cell, 2 * lineWidth + cell);
}

/** Sections at the mid-heights of the next `count` layers up (dir +1) or down (dir -1). */
function neighbourSpans(ctx: LayerContext, z: number, dir: 1 | -1, count: number): Spans[] {
  const out: Spans[] = [];
  for (let k = 1; k <= count; k++) {
    const zk = z + dir * k * ctx.opts.layerHeight;
    if (zk <= ctx.sections.zMin || zk >= ctx.sections.zMax) {
      out.push(ctx.sections.get(Number.NaN).spans);
      break;
    }
    out.push(ctx.sections.get(zk).spans);
  }
  return out;
}

/** [area of the surface, fraction of it (shrunk by `edge` to forgive raster edges) covered by material]. */
function surfaceCoverage(surface: Spans, edge: number, grid: Grid, material: Uint8Array): [number, number] {
  const area = spansArea(surface);
  if (isEmptySpans(surface)) return [0, NaN];
  const [total, hit] = countInSpans(erodeSpans(surface, edge), grid, material);
  return [area, total > 0 ? hit / total : NaN];
}
