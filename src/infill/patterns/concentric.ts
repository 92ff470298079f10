/**
 * Concentric: successive insets of the region until it is empty, traced as level sets of the exact
 * distance to the boundary (distance-field.ts; one field serves every loop, where a polygon offset per
 * loop would cost milliseconds each). The loops follow the region, so centering has no effect.
 *
 * Loops sit at depths (k − ½)·s, each in the middle of its own band, which gives density w/s. In parts
 * narrower than a few spacings the loops come in pairs across the part, so the density there jumps (a
 * 15 mm arm at 10 % holds two or four lines where 3.3 are due). Because the loops need not line up with
 * other layers, spacing and phase are chosen per region: spacing s·{1, 0.95, 1.05, …, 0.75, 1.25}, first
 * loop at {0.5, 0.4, 0.6} spacings; the candidate whose predicted extrusion is nearest the setting wins
 * (the first one within 2 %; the prediction is checked by tracing). A loop thinner than half a spacing
 * (two sides of a ridge) is printed as one side only, a centre line rather than a doubled one, or left out
 * when that is nearer the setting (the inset is then taken as empty).
 *
 * With `connect`, each loop is joined to one loop of the next depth (the one nearest to it): the path runs
 * round the outer loop, steps across to the nearest point of the inner one, runs round it, and so on.
 */
import type { InfillPattern } from '../types.js';
import { hypot, type Polygon, type Pt } from '../../geometry/types.js';
import { familySpacing } from '../density.js';
import { indexRegion, regionGeom } from '../region-index.js';
import { type DistanceField, distanceField, refineToDepth, restoreCorners } from '../distance-field.js';
import { contourScratch, traceContours } from '../contour.js';
import { closestOnSegment } from '../geom-util.js';
import { pathLengthUm } from '../measure.js';
import { ringArea } from '../../geometry/clip.js';

/** Spacing factors tried, nearest to 1 first. */
const SPACING_FACTORS = [1, 0.95, 1.05, 0.9, 1.1, 0.85, 1.15, 0.8, 1.2, 0.75, 1.25];
/** Depth of the first loop in spacings, tried for each factor: the middle of its band first. */
const PHASES = [0.5, 0.4, 0.6];
/** A candidate predicted this close to the setting (relative) ends the search. */
const GOOD_ENOUGH = 0.02;
/** The best few predicted candidates are traced for real (the prediction halves thin parts cell by cell,
 * the output decides per loop) until one is within TRACED_GOOD_ENOUGH. */
const TRACED_CANDIDATES = 4;
const TRACED_GOOD_ENOUGH = 0.04;
/** Grid cells per spacing for the distance field. */
const CELLS_PER_SPACING = 4;
/** Upper bound on distance-field nodes (the cell grows for huge regions). */
const MAX_NODES = 400_000;

/** Loop depths: (k − phase)·sp for k = 1, 2, … below the region's depth. */
function depths(sp: number, phase: number, maxDepth: number): number[] {
  const out: number[] = [];
  for (let k = 1; (k - phase) * sp < maxDepth; k++) out.push((k - phase) * sp);
  return out;
}

/** Field maximum over the 6×6 nodes around each cell (±2 nodes beyond its corners): how deep it gets nearby. */
function nearbyMax(f: DistanceField): Float64Array {
  const W = f.nx + 1,
    H = f.ny + 1,
    R = 2;
  const rows = new Float64Array(W * H),
    out = new Float64Array(f.nx * f.ny);
  for (let j = 0; j < H; j++) {
    for (let i = 0; i < W; i++) {
      let m = -Infinity;
      for (let k = Math.max(0, i - R); k <= Math.min(W - 1, i + 1 + R); k++) m = Math.max(m, f.v[j * W + k]);
      rows[j * W + i] = m;
    }
  }
  for (let j = 0; j < f.ny; j++) {
    for (let i = 0; i < f.nx; i++) {
      let m = -Infinity;
      for (let k = Math.max(0, j - R); k <= Math.min(H - 1, j + 1 + R); k++) m = Math.max(m, rows[k * W + i]);
      out[j * f.nx + i] = m;
    }
  }
  return out;
}

/**
 * Predicted printed length at spacing sp, all depths in one pass over the cells: the contours' length,
 * halved where the field gets no deeper than t + sp/4 within two cells (a ridge is near: the loop's two
 * sides are closer than sp/2 and it will be printed as one side).
 */
function predictedLengthUm(f: DistanceField, near: Float64Array, sp: number, phase: number): number {
  const { nx, ny, v } = f;
  const W = nx + 1;
  const crossings = new Float64Array(8);
  let total = 0;
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const n = j * W + i;
      const a = v[n],
        b = v[n + 1],
        c = v[n + W + 1],
        d = v[n + W];
      const lo = Math.min(a, b, c, d),
        hi = Math.max(a, b, c, d);
      if (hi <= 0) continue;
      // depths t_k = (k − phase)·sp with lo < t_k ≤ hi
      const k0 = Math.max(1, Math.floor(lo / sp + phase) + 1),
        k1 = Math.floor(hi / sp + phase);
      for (let k = k0; k <= k1; k++) {
        const t = (k - phase) * sp;
        total += cellLength(a - t, b - t, c - t, d - t, crossings) * f.h * (near[j * nx + i] - t < sp / 4 ? 0.5 : 1);
      }
    }
  }
  return total;
}

/** For each depth t_k = (k − phase)·sp (k = 1 … count), the cells whose corner values span it. */
function cellsByDepth(f: DistanceField, count: number, sp: number, phase: number): number[][] {
  const { nx, ny, v } = f;
  const W = nx + 1;
  const out: number[][] = Array.from({ length: count }, () => []);
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const n = j * W + i;
      const a = v[n],
        b = v[n + 1],
        c = v[n + W + 1],
        d = v[n + W];
      const lo = Math.min(a, b, c, d),
        hi = Math.max(a, b, c, d);
      if (hi <= 0) continue;
      const k0 = Math.max(1, Math.floor(lo / sp + phase)),
        k1 = Math.min(count, Math.floor(hi / sp + phase) + 1);
      for (let k = k0; k <= k1; k++) out[k - 1].push(j * nx + i);
    }
  }
  return out;
}

/**
 * Length of the zero set in a unit cell with corner values a (0,0), b (1,0), c (1,1), d (0,1).
 * @param p room for the zero set's crossings of the cell's edges, x, y (the caller's, reused from cell to cell)
 */
function cellLength(a: number, b: number, c: number, d: number, p: Float64Array): number {
  const sa = a >= 0,
    sb = b >= 0,
    sc = c >= 0,
    sd = d >= 0;
  let n = 0;
  if (sa !== sb) {
    p[2 * n] = a / (a - b);
    p[2 * n++ + 1] = 0;
  }
  if (sb !== sc) {
    p[2 * n] = 1;
    p[2 * n++ + 1] = b / (b - c);
  }
  if (sc !== sd) {
    p[2 * n] = 1 - c / (c - d);
    p[2 * n++ + 1] = 1;
  }
  if (sd !== sa) {
    p[2 * n] = 0;
    p[2 * n++ + 1] = 1 - d / (d - a);
  }
  if (n < 2) return 0;
  // a saddle (four crossings): the second piece runs from the fourth crossing to the second
  return hypot(p[2] - p[0], p[3] - p[1]) + (n === 4 ? hypot(p[6] - p[2], p[7] - p[3]) : 0);
}

function ringLengthUm(pts: readonly Pt[]): number {
  let l = 0;
  for (let i = 0, j = pts.length - 1; i < pts.length; j = i++) l += hypot(pts[i].x - pts[j].x, pts[i].y - pts[j].y);
  return l;
}

/** One side of a thin loop: from its farthest-apart pair of vertices, the first arc. */
function oneSide(ring: readonly Pt[]): Pt[] {
  const far = (from: Pt) => {
    let bi = 0,
      bd = -1;
    ring.forEach((p, i) => {
      const d = (p.x - from.x) ** 2 + (p.y - from.y) ** 2;
      if (d > bd) {
        bd = d;
        bi = i;
      }
    });
    return bi;
  };
  const a = far(ring[0]);
  const b = far(ring[a]);
  const [i0, i1] = a < b ? [a, b] : [b, a];
  return ring.slice(i0, i1 + 1);
}

/** Nearest point on a closed ring to p: edge index and the point. */
function nearestOnRing(ring: readonly Pt[], p: Pt): { i: number; x: number; y: number; d: number } {
  let best = { i: 0, x: ring[0].x, y: ring[0].y, d: Infinity };
  for (let i = 0; i < ring.length; i++) {
    const a = ring[i],
      b = ring[(i + 1) % ring.length];
    const q = closestOnSegment(a.x, a.y, b.x, b.y, p.x, p.y);
    if (q.d2 < best.d * best.d) best = { i, x: q.x, y: q.y, d: Math.sqrt(q.d2) };
  }
  return best;
}

/** The ring as a closed walk starting (and ending) at a point on edge i. */
function walkFrom(ring: readonly Pt[], i: number, start: Pt): Pt[] {
  const out: Pt[] = [start];
  const n = ring.length;
  for (let k = 1; k <= n; k++) out.push(ring[(i + k) % n]);
  out.push(start);
  return out;
}

/**
 * Split a loop with thin stretches: each wide stretch stays as it is (open), each thin stretch (out along
 * one side of a ridge and back along the other) keeps its first half: one line along the ridge.
 */
function splitThin(pts: readonly Pt[], thin: readonly boolean[], wide: Pt[][], centre: Pt[][]): void {
  const n = pts.length;
  const s0 = thin.findIndex((b) => !b);
  let run: Pt[] = [];
  let runThin = false;
  const flush = () => {
    if (run.length < 2) return;
    if (!runThin) {
      wide.push(run);
      return;
    }
    let total = 0;
    for (let k = 1; k < run.length; k++) total += hypot(run[k].x - run[k - 1].x, run[k].y - run[k - 1].y);
    const half: Pt[] = [run[0]];
    let acc = 0;
    for (let k = 1; k < run.length && acc < total / 2; k++) {
      acc += hypot(run[k].x - run[k - 1].x, run[k].y - run[k - 1].y);
      half.push(run[k]);
    }
    centre.push(half);
  };
  for (let k = 0; k <= n; k++) {
    const i = (s0 + k) % n;
    const isThin = k < n && thin[i];
    if (k > 0 && (isThin !== runThin || k === n)) {
      const last = run[run.length - 1];
      if (k === n) run.push(pts[i]);
      flush();
      run = [last];
    }
    runThin = isThin;
    if (k < n) run.push(pts[i]);
  }
}

/**
 * Join each loop to one loop of the next depth (the nearest one whose parent is free): round the outer
 * loop, across to the nearest point of the inner one, round it, and so on. Unjoined loops stay loops.
 */
function linkLevels(levels: Polygon[][], open: Pt[][], sp: number): { lines: Pt[][]; loops: Polygon[] } {
  const childOf = new Map<Polygon, Polygon>();
  const hasParent = new Set<Polygon>();
  for (let l = 1; l < levels.length; l++) {
    for (const child of levels[l]) {
      let best: Polygon | null = null;
      let bestD = 1.5 * sp;
      for (const parent of levels[l - 1]) {
        if (childOf.has(parent)) continue;
        const d = nearestOnRing(parent, child[0]).d;
        if (d < bestD) {
          bestD = d;
          best = parent;
        }
      }
      if (best) {
        childOf.set(best, child);
        hasParent.add(child);
      }
    }
  }
  const lines: Pt[][] = open.slice();
  const loops: Polygon[] = [];
  for (const ring of levels.flat()) {
    if (hasParent.has(ring)) continue;
    if (!childOf.has(ring)) {
      loops.push(ring);
      continue;
    }
    let path = walkFrom(ring, 0, ring[0]);
    let r: Polygon | undefined = ring;
    while ((r = childOf.get(r))) {
      const end = path[path.length - 1];
      const q = nearestOnRing(r, end);
      path = path.concat(walkFrom(r, q.i, { x: Math.round(q.x), y: Math.round(q.y) }));
    }
    lines.push(path);
  }
  return { lines, loops };
}

export const concentric: InfillPattern = {
  id: 'concentric',
  description: 'Successive insets of the region until empty, each loop linked to the next.',
  followsRegion: true,
  generate(layer, params) {
    const s = familySpacing(params.density, params.lineWidthUm, 1);
    const geom = regionGeom(layer.region);
    if (!(geom.area > 0) || !isFinite(s)) return { lines: [], loops: [], link: false };
    const ix = indexRegion(geom);
    const span = (geom.maxX - geom.minX) * (geom.maxY - geom.minY);
    const h = Math.max(s / CELLS_PER_SPACING, Math.sqrt(span / MAX_NODES));
    const field = distanceField(ix, h);
    const W = field.nx + 1;
    const centre = (i: number, j: number) => {
      const n = j * W + i;
      return (field.v[n] + field.v[n + 1] + field.v[n + W] + field.v[n + W + 1]) / 4;
    };
    const target = (params.density * geom.area) / params.lineWidthUm;
    const scratch = contourScratch(field);
    /** Trace the loops of one candidate, depth by depth; thin loops become centre lines. */
    const build = (sp: number, phase: number) => {
      const levels: Polygon[][] = [];
      const wideParts: Pt[][] = [];
      const centreLines: Pt[][] = [];
      const ts = depths(sp, phase, field.maxDepth);
      const buckets = cellsByDepth(field, ts.length, sp, phase);
      for (let li = 0; li < ts.length; li++) {
        const t = ts[li];
        const rings: Polygon[] = [];
        for (const c of traceContours(
          field,
          t,
          centre,
          (x, y, a, b) => refineToDepth(ix, field, x, y, a, b, t),
          buckets[li],
          scratch,
        )) {
          const pts: Pt[] = [];
          for (const q of restoreCorners(ix, c.pts, c.closed, 1.5 * field.h)) {
            const p = { x: Math.round(q.x), y: Math.round(q.y) };
            const last = pts[pts.length - 1];
            if (!last || last.x !== p.x || last.y !== p.y) pts.push(p);
          }
          if (pts.length < 3) continue;
          const len = ringLengthUm(pts);
          if ((2 * Math.abs(ringArea(pts))) / len < sp / 2) {
            centreLines.push(oneSide(pts));
            continue;
          }
          // thin stretches (a ridge within sp/4: the loop's two sides closer than sp/2) keep one side
          const thin = pts.map((p) => {
            const i = Math.min(field.nx - 1, Math.max(0, Math.floor((p.x - field.x0) / field.h)));
            const j = Math.min(field.ny - 1, Math.max(0, Math.floor((p.y - field.y0) / field.h)));
            return near[j * field.nx + i] - t < sp / 4;
          });
          if (!thin.some((b) => b)) rings.push(pts);
          else if (thin.every((b) => b)) centreLines.push(oneSide(pts));
          else splitThin(pts, thin, wideParts, centreLines);
        }
        levels.push(rings);
      }
      // with the centre lines, and (if there are any) without them: whichever is nearer the setting
      let best: { lines: Pt[][]; loops: Polygon[]; printed: number } | null = null;
      for (const centre of centreLines.length ? [centreLines, []] : [centreLines]) {
        const open = wideParts.concat(centre);
        const out = params.connect ? linkLevels(levels, open, sp) : { lines: open, loops: levels.flat() };
        const printed = pathLengthUm(out);
        if (!best || Math.abs(printed - target) < Math.abs(best.printed - target)) best = { ...out, printed };
      }
      return best as { lines: Pt[][]; loops: Polygon[]; printed: number };
    };
    // the first candidate predicted close enough is traced; if the trace misses, all candidates are
    // ranked by prediction and the best few traced
    const near = nearbyMax(field);
    const cands: Array<{ sp: number; phase: number; err: number }> = [];
    for (const f of SPACING_FACTORS) for (const ph of PHASES) cands.push({ sp: s * f, phase: ph, err: NaN });
    const predict = (c: { sp: number; phase: number; err: number }) => {
      if (Number.isNaN(c.err)) c.err = Math.abs(predictedLengthUm(field, near, c.sp, c.phase) - target);
      return c.err;
    };
    const first =
      cands.find((c) => predict(c) <= GOOD_ENOUGH * target) ??
      cands.reduce((a, b) => (predict(b) < predict(a) ? b : a));
    let chosen = build(first.sp, first.phase);
    if (Math.abs(chosen.printed - target) > TRACED_GOOD_ENOUGH * target) {
      const ranked = cands.filter((c) => c !== first).sort((a, b) => predict(a) - predict(b));
      for (let k = 0; k < Math.min(ranked.length, TRACED_CANDIDATES - 1); k++) {
        const b = build(ranked[k].sp, ranked[k].phase);
        if (Math.abs(b.printed - target) < Math.abs(chosen.printed - target)) chosen = b;
        if (Math.abs(chosen.printed - target) <= TRACED_GOOD_ENOUGH * target) break;
      }
    }
    return { lines: chosen.lines, loops: chosen.loops, link: false, fitted: true };
  },
};
