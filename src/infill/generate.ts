/**
 * The entry point: run a pattern for one layer's region, clip its lines (scanline engine for line
 * families, general clipper for everything else), link neighbouring ends along the boundary, clean up
 * and order the result for short travel.
 *
 * Density (see density.ts): the pattern's spacing rule gets the lines' share of the region right in a large
 * region, but where few lines cross a small region, where they fall (their phase) moves the share by ±10 %
 * or more. So each run is measured (clipped line length × width over the region's area) and, if it misses
 * the setting by more than 3 %, the pattern is run again with its density scaled by what was missing (or
 * halfway between runs on either side of the setting); at most five runs (two for most layers), the best
 * one wins. The factor is rounded to 1/64 so layers of similar outline get exactly the same spacing and
 * their lines stack. Connectors joining line ends along the boundary are not counted: they run on the
 * region's edge, beside the innermost wall or the skin, not through the sparse interior, as Cura's and
 * PrusaSlicer's connectors do (the G-code analyser leaves that edge band out for this reason); paying for
 * them thinned the lines of small regions by 10–15 %. Patterns that change with Z on purpose ('volume':
 * gyroid, cubic) run once, so their period stays the same from layer to layer and the 3D structure is kept.
 */
import { hypot, type Polyline, type Pt } from '../geometry/types.js';
import type { InfillLayerInput, InfillParams, InfillPattern, InfillResult, PatternId } from './types.js';
import { PATTERNS } from './registry.js';
import { type RegionGeom, type RegionIndex, indexRegion, regionGeom } from './region-index.js';
import { clipSweep } from './sweep.js';
import { clipPolylines } from './clip-polylines.js';
import { linkPieces } from './link.js';
import { cleanPaths } from './cleanup.js';
import { orderLines, orderLoops } from '../order/index.js';
import { type Piece, polylineLengthUm } from './piece.js';

/** Ends are joined along the boundary when at most this many line spacings apart. */
export const LINK_REACH = 2.5;
/** Open paths shorter than this fraction of the line width are dropped (a blob, not a line). */
const MIN_PRINTABLE_WIDTHS = 0.5;
/** Steps of the density correction (see above). */
const CORRECTION_STEPS = 64;
/** The density factor of a corrected run stays within [MIN_CORRECTION, MAX_CORRECTION]. */
const MIN_CORRECTION = 0.5;

interface Ctx {
  geom: RegionGeom;
  index: RegionIndex | null;
}

interface Run {
  pieces: Piece[];
  loops: Pt[][];
  /** Line ends this far apart along the boundary are joined (0: none). */
  linkReach: number;
  /** The pattern fitted its own spacing (no further runs). */
  fitted: boolean;
  /** Region share extruded by the pattern's own lines (length × width over area, connectors not counted). */
  lineShare: number;
  /** Density factor this run used. */
  factor: number;
}

function lengthOf(paths: readonly Pt[][], closed: boolean): number {
  let l = 0;
  for (const p of paths) {
    l += polylineLengthUm(p);
    if (closed && p.length > 2) l += hypot(p[0].x - p[p.length - 1].x, p[0].y - p[p.length - 1].y);
  }
  return l;
}

function runPattern(
  pattern: InfillPattern,
  layer: InfillLayerInput,
  params: InfillParams,
  prepared: Polyline[] | undefined,
  ctx: Ctx,
  factor: number,
): Run {
  const p = factor === 1 ? params : { ...params, density: params.density * factor };
  const out = pattern.generate(layer, p, prepared);
  const pieces: Piece[] = [];
  for (const sw of out.sweeps ?? []) clipSweep(ctx.geom, sw, p.origin, pieces);
  if (out.lines.length) {
    ctx.index ??= indexRegion(ctx.geom);
    clipPolylines(ctx.index, out.lines, pieces);
  }
  const w = params.lineWidthUm,
    A = ctx.geom.area;
  let own = out.loops.length ? lengthOf(out.loops, true) : 0;
  for (const pc of pieces) own += polylineLengthUm(pc.pts);
  const lineShare = (own * w) / A;
  const linkReach =
    p.connect && out.link !== false && out.linkSpacingUm && out.linkSpacingUm > 0 ? LINK_REACH * out.linkSpacingUm : 0;
  return { pieces, loops: out.loops, linkReach, fitted: !!out.fitted, lineShare, factor };
}

function quantize(f: number): number {
  return Math.round(Math.min(MAX_CORRECTION, Math.max(MIN_CORRECTION, f)) * CORRECTION_STEPS) / CORRECTION_STEPS;
}

/**
 * Run the pattern and steer its density factor so that its lines extrude the setting (see the head of this
 * file): at most MAX_RUNS runs, the best one wins. 'volume' and 'support' patterns and patterns that fitted
 * themselves are run once.
 */
function runCorrected(
  pattern: InfillPattern,
  layer: InfillLayerInput,
  params: InfillParams,
  prepared: Polyline[] | undefined,
  ctx: Ctx,
): Run {
  const d = params.density;
  const model = pattern.densityModel ?? 'layer';
  if (model === 'volume') return runPattern(pattern, layer, params, prepared, ctx, 1);
  const r0 = runPattern(pattern, layer, params, prepared, ctx, 1);
  if (model === 'support' || r0.fitted) return r0;
  const total = (r: Run) => r.lineShare;
  const err = (r: Run) => Math.abs(total(r) - d);
  let best = r0;
  let cur = r0;
  const runs: Run[] = [r0];
  const tried = new Set<number>([1]);
  for (let k = 1; k < MAX_RUNS && err(best) > CORRECTION_SETTLED * d; k++) {
    // bisect between the nearest runs on either side of the setting, else scale by what was missing
    let below: Run | null = null,
      above: Run | null = null;
    for (const r of runs) {
      if (total(r) < d && (!below || r.factor > below.factor)) below = r;
      if (total(r) > d && (!above || r.factor < above.factor)) above = r;
    }
    let f: number;
    if (below && above && below.factor < above.factor) f = quantize((below.factor + above.factor) / 2);
    else {
      if (!(cur.lineShare > 0)) break;
      f = quantize((cur.factor * d) / cur.lineShare);
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
const MAX_CORRECTION = 1.5;

/**
 * One layer's (or one island's) infill: clipped to `layer.region`, linked (if `params.connect`), free of
 * zero-length and duplicate segments, ordered from `start` (default: the region's lower-left corner):
 * loops first, then lines. `prepared` is this layer's entry of the pattern's `prepare` result, if it has one.
 * A pattern that draws finished paths (custom infill) is taken as it is.
 */
export function generateInfill(
  patternOrId: PatternId | InfillPattern,
  layer: InfillLayerInput,
  params: InfillParams,
  prepared?: Polyline[],
  start?: Pt,
): InfillResult {
  const pattern: InfillPattern | undefined = typeof patternOrId === 'string' ? PATTERNS[patternOrId] : patternOrId;
  if (!pattern) throw new Error(`unknown infill pattern '${String(patternOrId)}'`);
  if (pattern.finished) return pattern.generate(layer, params, prepared);
  if (!(params.density > 0) || layer.region.length === 0) return { lines: [], loops: [] };
  const geom = regionGeom(layer.region);
  if (!(geom.area > 0)) return { lines: [], loops: [] };
  const ctx: Ctx = { geom, index: null };
  const run = runCorrected(pattern, layer, params, prepared, ctx);
  const lines = run.linkReach > 0 ? linkPieces(geom, run.pieces, run.linkReach).lines : run.pieces.map((pc) => pc.pts);
  const clean = cleanPaths(lines, run.loops, MIN_PRINTABLE_WIDTHS * params.lineWidthUm);
  // loops first, nearest-first, then lines from where the loops end
  const loops = orderLoops(clean.loops, start ?? { x: geom.minX, y: geom.minY });
  return { loops: loops.loops, lines: orderLines(clean.lines, loops.end) };
}
