/**
 * Fuzzy skin: the outer wall's loops redrawn through new points about `fuzzySkinPointDistance` apart (each gap
 * ¾ to 1¼ of it), every point moved across the wall, in or out, by up to `fuzzySkinThickness`: a rough,
 * textured surface. The spacing and the ± thickness are PrusaSlicer's, OrcaSlicer's and CuraEngine's; a new
 * point's bead width is the wall's there (variable-width walls keep their widths along the loop).
 *
 * Made in the paths stage from the walls the regions stage found (so skin and infill, which border the
 * smooth walls, are untouched), before the entry flags the loop's runs over air. The randomness is seeded by
 * the layer and the loop's own points: the same wall on the same layer gets the same texture in every run, on
 * any number of threads and in any order of layers. Inner walls stay smooth, and so does the first layer.
 */
import type { Pt } from '../geometry/types.js';
import type { WallSet } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';

/** A wall set's paths and their per-point widths. */
export interface WallPaths {
  paths: Pt[][];
  widths: (Float64Array | null)[] | null;
}

/**
 * The set's paths with fuzzy skin where the region's config asks for it: the outer wall's closed loops, on
 * every layer but the first, the part's outside only (`outer`, the loops turning counter-clockwise) or
 * holes too (`all`). Anything else is the set as it is.
 */
export function fuzzyWalls(set: WallSet, cfg: Config, layer: number): WallPaths {
  if (cfg.fuzzySkin === 'off' || layer === 0 || set.role !== 'wall' || set.wall !== 0 || !set.closed) return set;
  const holes = cfg.fuzzySkin === 'all';
  const thickness = cfg.fuzzySkinThickness * 1000;
  const spacing = cfg.fuzzySkinPointDistance * 1000;
  let paths: Pt[][] | null = null;
  let widths: (Float64Array | null)[] | null = set.widths;
  for (let k = 0; k < set.paths.length; k++) {
    const loop = set.paths[k];
    if (loop.length < 3 || (!holes && signedArea2(loop) < 0)) continue;
    const fuzzy = fuzzyLoop(loop, set.widths?.[k] ?? null, thickness, spacing, seedOf(layer, loop));
    if (!fuzzy) continue;
    if (!paths) {
      paths = set.paths.slice(); // the regions' own arrays stay as they are
      if (widths) widths = widths.slice();
    }
    paths[k] = fuzzy.points;
    if (widths) widths[k] = fuzzy.widths;
  }
  return paths ? { paths, widths } : set;
}

/**
 * One closed loop made fuzzy: points every `spacing` × (¾ … 1¼) µm along it, each moved by up to `thickness`
 * µm across the edge it lies on, the randomness drawn from `seed`. Null when fewer than three points come out.
 */
export function fuzzyLoop(
  loop: readonly Pt[],
  widths: Float64Array | null,
  thickness: number,
  spacing: number,
  seed: number,
): { points: Pt[]; widths: Float64Array | null } | null {
  const n = loop.length;
  const minGap = spacing * 0.75;
  const gapRange = spacing * 0.5;
  let state = seed | 0;
  /** The next number in [0, 1) (mulberry32). */
  const next = (): number => {
    state = (state + 0x6d2b79f5) | 0;
    let t = Math.imul(state ^ (state >>> 15), 1 | state);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const points: Pt[] = [];
  const outWidths: number[] = [];
  // how far along the loop the first new point lies
  let carry = next() * (minGap / 2);
  for (let k = 0; k < n; k++) {
    const a = loop[k];
    const bi = k + 1 === n ? 0 : k + 1;
    const b = loop[bi];
    const dx = b.x - a.x,
      dy = b.y - a.y;
    const len = Math.sqrt(dx * dx + dy * dy);
    let d = carry;
    if (len > 0) {
      // unit normal (left of the edge): in or out, the jitter is symmetric
      const nx = -dy / len,
        ny = dx / len;
      for (; d < len; d += minGap + next() * gapRange) {
        const t = d / len;
        const off = (next() * 2 - 1) * thickness;
        points.push({ x: Math.round(a.x + t * dx + off * nx), y: Math.round(a.y + t * dy + off * ny) });
        if (widths) outWidths.push(widths[k] + t * (widths[bi] - widths[k]));
      }
    }
    carry = d - len;
  }
  if (points.length < 3) return null;
  return { points, widths: widths ? Float64Array.from(outWidths) : null };
}

/** Twice the loop's signed area (positive: counter-clockwise, an outer ring), µm². */
function signedArea2(loop: readonly Pt[]): number {
  let s = 0;
  for (let i = 0, j = loop.length - 1; i < loop.length; j = i++) s += (loop[j].x - loop[i].x) * (loop[j].y + loop[i].y);
  return s;
}

/** A seed from the layer and the loop: its first point and its size. */
function seedOf(layer: number, loop: readonly Pt[]): number {
  let h =
    Math.imul(layer + 1, 0x9e3779b1) ^
    Math.imul(loop[0].x, 0x85ebca77) ^
    Math.imul(loop[0].y, 0xc2b2ae3d) ^
    Math.imul(loop.length, 0x27d4eb2f);
  h = Math.imul(h ^ (h >>> 16), 0x7feb352d);
  h = Math.imul(h ^ (h >>> 15), 0x846ca68b);
  return h ^ (h >>> 16);
}
