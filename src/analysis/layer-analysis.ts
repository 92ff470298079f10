/**
 * The raster checks of one printed layer against the model section at its mid-height: walls, stray material,
 * skin coverage, infill density and XY shift.
 */
import { Feature, isPartFeature } from './feature-names.js';
import type { ExtrusionTable, GcodeLayer } from './gcode-types.js';
import type { Grid } from './grid.js';
import { bitmapAt, countSet, gridAround, newBitmap } from './grid.js';
import { outlineMetrics } from './outline.js';
import { beadWidth, dilateBitmap, rasterizeExtrusions, segmentLength, stampCapsule, volumeWidth } from './raster.js';
import type { AnalyzeOptions } from './report-types.js';
import type { CachedSection, SectionCache } from './section-cache.js';
import { SegmentIndex, WindingIndex } from './segment-index.js';
import { skinRegions } from './skin.js';
import type { Spans } from './spans.js';
import {
  bitmapToSpans, countInSpans, dilateSpans, erodeSpans, isEmptySpans, spansArea, spansBoolean, spansBounds,
  spansContain, spansToBitmap,
} from './spans.js';
import type { WeightedHistogram } from './stats.js';
import { quantileWithZeros } from './stats.js';

export type ResolvedOptions = Required<AnalyzeOptions>;

/** Material farther than this outside the section is not rasterised (its distance is still measured), mm. */
const RASTER_CLIP_MARGIN_MM = 5;
/** Outside-distance searches look this far before falling back to a search of the whole section, mm. */
const OUTSIDE_SEARCH_MM = 5;
/** Bead widths are clamped to [MIN_BEAD_MM, MAX_BEAD_LINE_WIDTHS × lineWidth]. */
const MIN_BEAD_MM = 0.05;
const MAX_BEAD_LINE_WIDTHS = 4;
/** Infill regions smaller than this (mm²) give no density. */
const MIN_INFILL_REGION_MM2 = 1;
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

/** Layers beyond the skin thickness that the infill region keeps away from top and bottom surfaces. */
export function skinMarginLayers(o: ResolvedOptions): number {
  return Math.ceil(o.skinMargin / o.layerHeight - 1e-9);
}

/** Layer height used to turn E into width: the measured thickness when plausible, else the nominal one. */
export function effectiveThickness(layer: GcodeLayer, o: ResolvedOptions): number {
  const nominal = layer.index === 0 ? o.firstLayerHeight : o.layerHeight;
  const t = layer.thickness;
  return t > 0.25 * nominal && t < 4 * nominal ? t : nominal;
}

export function measureLayer(layer: GcodeLayer, ctx: LayerContext): LayerMeasure {
  const o = ctx.opts;
  const h = effectiveThickness(layer, o);
  // Rounded to a nanometre so that float noise does not decide on which side of a mesh vertex the plane falls.
  const sectionZ = Math.round((layer.z - h / 2) * 1e6) / 1e6;
  const section = ctx.sections.get(sectionZ);
  const t = layer.extrusions;

  const part: number[] = [];
  for (let i = 0; i < t.count; i++) if (isPartFeature(t.feature[i]!)) part.push(i);
  const partIds = Uint32Array.from(part);
  const widths = new Float32Array(t.count);
  const layerWidths = new Map<number, number>();
  let partLength = 0;
  for (const i of partIds) {
    const len = segmentLength(t, i);
    partLength += len;
    const w = o.widthSource === 'nominal' ? o.lineWidth : beadWidth(t.e[i]!, len, h, ctx.filamentArea);
    widths[i] = Math.min(MAX_BEAD_LINE_WIDTHS * o.lineWidth, Math.max(MIN_BEAD_MM, w));
    ctx.widths.add(w, len);
    const key = Math.round(w * 1000);
    layerWidths.set(key, (layerWidths.get(key) ?? 0) + len);
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
    widthMedianMm: weightedMedianOfMap(layerWidths) / 1000,
    partLengthMm: partLength,
  };
  const bounds = spansBounds(section.spans);
  if (!bounds || section.segments.count === 0) return result;

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

  measureOutside(result, t, partIds, section, inside, grid, material, materialCells, ctx);

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
  measureInfill(result, t, grid, widths, h, section.spans, spansBoolean(near.top, near.bottom, 'union'), ctx);
  return result;
}

function layerGrid(
  bounds: [number, number, number, number], t: ExtrusionTable, partIds: Uint32Array, cell: number, lineWidth: number,
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

/**
 * Distances of part material outside the section grown by half a line width, and the area of beads there. Where
 * the section is ambiguous (the plane runs through mesh vertices), material inside either reading is inside.
 */
function measureOutside(
  r: LayerMeasure, t: ExtrusionTable, partIds: Uint32Array, section: CachedSection, windMain: WindingIndex,
  grid: Grid, material: Uint8Array, materialCells: number, ctx: LayerContext,
): void {
  const o = ctx.opts;
  const main = section.segments;
  const up = section.above?.segments ?? null;
  const windUp = up ? new WindingIndex(up.x0, up.y0, up.x1, up.y1, up.count, 1) : null;
  const nearMain = new SegmentIndex(main.x0, main.y0, main.x1, main.y1, null, main.count, 1);
  const nearUp = up ? new SegmentIndex(up.x0, up.y0, up.x1, up.y1, null, up.count, 1) : null;
  const tolerance = o.lineWidth / 2;
  const region = section.above ? spansBoolean(section.spans, section.above.spans, 'union') : section.spans;
  // Samples in cells whose centre lies within (tolerance - 3/4 cell) of the section are within the tolerance
  // wherever they sit in the cell: no exact test needed. (Spans sample the section, so they never overstate it.)
  const safe = newBitmap(grid);
  const safeRadius = tolerance - 0.75 * ctx.cell;
  spansToBitmap(safeRadius > 0 ? dilateSpans(region, safeRadius) : erodeSpans(region, 2 * ctx.cell), grid, safe);
  const step = ctx.cell;
  const positives: number[] = [];
  let samples = 0;
  for (const i of partIds) {
    const ax = t.x0[i]!, ay = t.y0[i]!;
    const dx = t.x1[i]! - ax, dy = t.y1[i]! - ay;
    const n = Math.max(1, Math.ceil(Math.hypot(dx, dy) / step));
    samples += n + 1;
    for (let k = 0; k <= n; k++) {
      const px = ax + (dx * k) / n;
      const py = ay + (dy * k) / n;
      if (bitmapAt(safe, grid, px, py)) continue;
      if (windMain.winding(px, py) !== 0 || (windUp !== null && windUp.winding(px, py) !== 0)) continue;
      const d = Math.min(outsideDistance(nearMain, px, py, tolerance), nearUp ? outsideDistance(nearUp, px, py, tolerance) : Infinity);
      if (d > tolerance) positives.push(d - tolerance);
    }
  }
  const arr = Float64Array.from(positives);
  r.outsidePositives = arr;
  r.outsideSamples = samples;
  r.outsideMaxMm = arr.reduce((m, v) => Math.max(m, v), 0);
  r.outsideP99Mm = quantileWithZeros(arr.slice(), samples, 0.99);
  const [, inside] = countInSpans(dilateSpans(region, tolerance), grid, material);
  r.outsideAreaMm2 = (materialCells - inside) * ctx.cell * ctx.cell;
}

/** Distance to the nearest outline segment, searched first within the tolerance, then farther, then everywhere. */
function outsideDistance(index: SegmentIndex, px: number, py: number, tolerance: number): number {
  let d = index.nearest(px, py, tolerance);
  if (d === Infinity) d = index.nearest(px, py, OUTSIDE_SEARCH_MM);
  if (d === Infinity) d = index.nearest(px, py, Number.MAX_SAFE_INTEGER);
  return d;
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

/**
 * Infill density: in the section shrunk by the wall thickness and a line width, minus model skin and (with feature types) the
 * G-code's own solid infill, each grown by skinMargin, the FILL lines' extruded volume per layer height (their
 * full-density area) over the region's area.
 */
function measureInfill(
  r: LayerMeasure, t: ExtrusionTable, grid: Grid, widths: Float32Array, h: number, section: Spans, skin: Spans,
  ctx: LayerContext,
): void {
  const o = ctx.opts;
  // One line width more than the walls: where infill meets them it overlaps or runs along them (anchors).
  let region = erodeSpans(section, o.wallThickness + o.lineWidth);
  if (!isEmptySpans(skin)) region = spansBoolean(region, skin, 'subtract');
  if (!isEmptySpans(region)) {
    // Excluded: the model's skin grown by skinMargin (slicers widen skin into the infill), and with feature types
    // the solid infill the G-code prints, grown by a line width.
    let excluded = newBitmap(grid);
    if (!isEmptySpans(skin)) {
      spansToBitmap(skin, grid, excluded);
      excluded = dilateBitmap(excluded, grid, o.skinMargin);
    }
    if (ctx.hasTypes) {
      for (let i = 0; i < t.count; i++) {
        if (t.feature[i] !== Feature.Skin) continue;
        stampCapsule(excluded, grid, t.x0[i]!, t.y0[i]!, t.x1[i]!, t.y1[i]!, widths[i]! / 2 + o.lineWidth);
      }
    }
    region = spansBoolean(region, bitmapToSpans(excluded, grid), 'subtract');
  }
  const area = spansArea(region);
  r.infillRegionAreaMm2 = area;
  if (area < MIN_INFILL_REGION_MM2) return;
  const step = ctx.cell / 2;
  let covered = 0;
  for (let i = 0; i < t.count; i++) {
    const f = t.feature[i]!;
    if (ctx.hasTypes ? f !== Feature.Fill : !isPartFeature(f)) continue;
    const ax = t.x0[i]!, ay = t.y0[i]!;
    const dx = t.x1[i]! - ax, dy = t.y1[i]! - ay;
    const len = Math.hypot(dx, dy);
    const n = Math.max(1, Math.ceil(len / step));
    let inside = 0;
    for (let k = 0; k < n; k++) {
      if (spansContain(region, ax + (dx * (k + 0.5)) / n, ay + (dy * (k + 0.5)) / n)) inside++;
    }
    if (inside === 0) continue;
    const w = o.widthSource === 'nominal' ? o.lineWidth : volumeWidth(t.e[i]!, len, h, ctx.filamentArea);
    covered += (len * inside * w) / n;
  }
  r.infillDensity = covered / area;
}

function weightedMedianOfMap(m: Map<number, number>): number {
  const keys = [...m.keys()].sort((a, b) => a - b);
  let total = 0;
  for (const k of keys) total += m.get(k)!;
  let acc = 0;
  for (const k of keys) {
    acc += m.get(k)!;
    if (acc >= total / 2) return k;
  }
  return NaN;
}
