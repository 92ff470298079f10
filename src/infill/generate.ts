/**
 * The entry point: run a pattern for one layer's region, clip its lines (scanline engine for line
 * families, general clipper for everything else), link neighbouring ends along the boundary, clean up
 * and order the result for short travel.
 *
 * Density: the pattern's spacing rule gets the lines' share right in a large region, but two things move
 * the real figure. Connectors along the boundary are extruded too (the inner half of their footprint lies
 * in the region): about half the boundary length whatever the spacing, which would add 15–25 % on a 30 mm
 * square at 10 %. And where few lines cross a small region, where they fall (their phase) moves the share
 * by ±10 % or more. So each run is measured (clipped line length × width less the pattern's crossing
 * overlap, plus the connectors) and, if it misses the setting by more than 3 %, the pattern is run again
 * with its density scaled by what was missing (or halfway between runs on either side of the setting);
 * at most five runs (two for most layers), the best one wins. The factor is rounded to 1/64 so layers of
 * similar outline get exactly the same spacing and their lines stack. Patterns that change with Z on
 * purpose ('volume': gyroid, cubic) only pay for their connectors, measured at two fixed reference heights,
 * so their period stays the same from layer to layer and the 3D structure is kept.
 */
import type { ExPolygon, Polyline, Pt } from '../geometry/types.js';
import type { InfillLayerInput, InfillParams, InfillPattern, InfillResult, PatternId } from './types.js';
import { PATTERNS } from './registry.js';
import { type RegionGeom, type RegionIndex, indexRegion, regionGeom } from './region-index.js';
import { clipSweep } from './sweep.js';
import { clipPolylines } from './clip-polylines.js';
import { linkPieces } from './link.js';
import { cleanPaths } from './cleanup.js';
import { orderPaths } from './order.js';
import { type Piece, polylineLength } from './piece.js';

/** Ends are joined along the boundary when at most this many line spacings apart. */
export const LINK_REACH = 2.5;
/** Open paths shorter than this fraction of the line width are dropped (a blob, not a line). */
const MIN_PRINTABLE_WIDTHS = 0.5;
/** Steps of the connector density correction (see above). */
const CORRECTION_STEPS = 64;
/** The density is never lowered below this fraction of the setting to pay for connectors. */
const MIN_CORRECTION = 0.5;

interface Ctx {
  geom: RegionGeom;
  index: RegionIndex | null;
}

interface Run {
  lines: Pt[][];
  loops: Pt[][];
  /** The pattern fitted its own spacing (no further runs). */
  fitted: boolean;
  /** Region share covered by the pattern's own lines (length × width less crossing overlaps). */
  lineShare: number;
  /** Region share covered by boundary connectors. */
  connectorShare: number;
  /** Density factor this run used. */
  factor: number;
}

function lengthOf(paths: readonly Pt[][], closed: boolean): number {
  let l = 0;
  for (const p of paths) {
    l += polylineLength(p);
    if (closed && p.length > 2) l += Math.hypot(p[0].x - p[p.length - 1].x, p[0].y - p[p.length - 1].y);
  }
  return l;
}

function runPattern(pattern: InfillPattern, layer: InfillLayerInput, params: InfillParams, prepared: unknown, ctx: Ctx, factor: number): Run {
  const p = factor === 1 ? params : { ...params, density: params.density * factor };
  const out = pattern.generate(layer, p, prepared);
  const pieces: Piece[] = [];
  for (const sw of out.sweeps ?? []) clipSweep(ctx.geom, sw, p.origin, pieces);
  if (out.lines.length) {
    ctx.index ??= indexRegion(ctx.geom);
    clipPolylines(ctx.index, out.lines, pieces);
  }
  const w = params.lineWidth, A = ctx.geom.area;
  let own = out.loops.length ? lengthOf(out.loops, true) : 0;
  for (const pc of pieces) own += polylineLength(pc.pts);
  const lineShare = ((own * w) / A) * (1 - (out.overlap ?? 0));
  if (p.connect && out.link !== false && out.linkSpacing && out.linkSpacing > 0) {
    const linked = linkPieces(ctx.geom, pieces, LINK_REACH * out.linkSpacing);
    return { lines: linked.lines, loops: out.loops, fitted: !!out.fitted, lineShare, connectorShare: connectorShare(linked.connectorLength, w, A), factor };
  }
  return { lines: pieces.map((pc) => pc.pts), loops: out.loops, fitted: !!out.fitted, lineShare, connectorShare: 0, factor };
}

/**
 * Share of the region covered by connectors: the inner half of their footprint, less the part that lies on
 * the line ends they join (about 15 % of it, measured by rasterising the test shapes).
 */
export function connectorShare(connectorLength: number, lineWidth: number, area: number): number {
  return area > 0 ? (CONNECTOR_INSIDE * connectorLength * lineWidth) / 2 / area : 0;
}
const CONNECTOR_INSIDE = 0.85;

function quantize(f: number): number {
  return Math.round(Math.min(MAX_CORRECTION, Math.max(MIN_CORRECTION, f)) * CORRECTION_STEPS) / CORRECTION_STEPS;
}

/**
 * Run the pattern and steer its density factor so that lines plus connectors cover the setting (see the
 * head of this file). 'layer' patterns are steered on what they actually cover (which also absorbs the
 * phase error of few lines in a small region), at most MAX_RUNS runs, the best one wins; 'volume' patterns
 * only pay for their connectors, measured at reference heights, since their layers vary on purpose;
 * 'support' patterns and patterns that fitted themselves are left alone.
 */
function runCorrected(pattern: InfillPattern, layer: InfillLayerInput, params: InfillParams, prepared: unknown, ctx: Ctx): Run {
  const d = params.density;
  const model = pattern.densityModel ?? 'layer';
  if (model === 'volume' && !params.connect) return runPattern(pattern, layer, params, prepared, ctx, 1);
  if (model === 'volume') {
    // The pattern changes with Z, and so would its connectors and any correction measured on this layer:
    // its period would then jump from layer to layer and break the 3D structure. The connectors are
    // measured at fixed reference heights instead, so layers of the same outline get the same period.
    const period = pattern.zPeriod ? pattern.zPeriod(params) : 0;
    let share = 0;
    for (let k = 0; k < VOLUME_REFERENCES; k++) {
      const z = layer.layerHeight + (k * period) / VOLUME_REFERENCES;
      share += runPattern(pattern, { ...layer, layerIndex: 0, z, draft: true }, params, prepared, ctx, 1).connectorShare / VOLUME_REFERENCES;
    }
    const f = share > CORRECTION_SETTLED * d ? quantize(1 - share / d) : 1;
    return runPattern(pattern, layer, params, prepared, ctx, f);
  }
  const r0 = runPattern(pattern, layer, params, prepared, ctx, 1);
  if (model === 'support' || r0.fitted) return r0;
  const total = (r: Run) => r.lineShare + r.connectorShare;
  const err = (r: Run) => Math.abs(total(r) - d);
  let best = r0;
  let cur = r0;
  const runs: Run[] = [r0];
  const tried = new Set<number>([1]);
  for (let k = 1; k < MAX_RUNS && err(best) > CORRECTION_SETTLED * d; k++) {
    // bisect between the nearest runs on either side of the setting, else scale by what was missing
    let below: Run | null = null, above: Run | null = null;
    for (const r of runs) {
      if (total(r) < d && (!below || r.factor > below.factor)) below = r;
      if (total(r) > d && (!above || r.factor < above.factor)) above = r;
    }
    let f: number;
    if (below && above && below.factor < above.factor) f = quantize((below.factor + above.factor) / 2);
    else {
      if (!(cur.lineShare > 0)) break;
      f = quantize((cur.factor * (d - cur.connectorShare)) / cur.lineShare);
    }
    if (tried.has(f)) break;
    tried.add(f);
    cur = runPattern(pattern, layer, params, prepared, ctx, f);
    runs.push(cur);
    if (err(cur) < err(best)) best = cur;
  }
  return best;
}
/** A run whose predicted total is within this fraction of the setting needs no further step. */
const CORRECTION_SETTLED = 0.03;
const MAX_RUNS = 5;
/** Reference heights (spread over one Z period) at which a 'volume' pattern's connectors are measured. */
const VOLUME_REFERENCES = 2;
const MAX_CORRECTION = 1.5;

/**
 * One layer's (or one island's) infill: clipped to `layer.region`, linked (if `params.connect`), free of
 * zero-length and duplicate segments, ordered from `start` (default: the region's lower-left corner):
 * loops first, then lines. `prepared` is this layer's entry of the pattern's `prepare` result, if it has one.
 */
export function generateInfill(patternId: PatternId, layer: InfillLayerInput, params: InfillParams, prepared?: unknown, start?: Pt): InfillResult {
  const pattern: InfillPattern | undefined = PATTERNS[patternId];
  if (!pattern) throw new Error(`unknown infill pattern '${String(patternId)}'`);
  if (!(params.density > 0) || layer.region.length === 0) return { lines: [], loops: [] };
  const geom = regionGeom(layer.region);
  if (!(geom.area > 0)) return { lines: [], loops: [] };
  const ctx: Ctx = { geom, index: null };
  const run = runCorrected(pattern, layer, params, prepared, ctx);
  const clean = cleanPaths(run.lines, run.loops, MIN_PRINTABLE_WIDTHS * params.lineWidth);
  return orderPaths(clean.lines, clean.loops, start ?? { x: geom.minX, y: geom.minY });
}

export interface SolidFillOptions {
  /** Join neighbouring line ends along the boundary (zig-zag). Default true. */
  connect?: boolean;
  /** Where the nozzle is before the fill; the first line starts nearest to it. */
  start?: Pt;
}

/**
 * Solid (skin) fill: one family of lines `spacingUm` apart at `angleDeg`, phase anchored at `origin`,
 * clipped exactly by the scanline engine, zig-zag linked and ordered.
 */
export function solidFill(region: readonly ExPolygon[], angleDeg: number, spacingUm: number, origin: Pt, options: SolidFillOptions = {}): Polyline[] {
  if (region.length === 0 || !(spacingUm > 0)) return [];
  const geom = regionGeom(region);
  const pieces: Piece[] = [];
  clipSweep(geom, { angle: angleDeg, spacing: spacingUm, offset: 0 }, origin, pieces);
  const lines = options.connect === false ? pieces.map((p) => p.pts) : linkPieces(geom, pieces, LINK_REACH * spacingUm).lines;
  const clean = cleanPaths(lines, [], 0);
  return orderPaths(clean.lines, [], options.start ?? { x: geom.minX, y: geom.minY }).lines;
}
