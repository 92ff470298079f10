/**
 * The scanline clipper for families of parallel lines. The region's edges are rotated into the family's
 * frame (u along the lines, v across), sorted by their lower v, and swept with an active edge table; each
 * scanline's crossings are paired even-odd into segments. Crossings use the half-open rule
 * (min v ≤ line < max v), so a line through a vertex is counted exactly once and the result is exact at the
 * boundary (up to rounding to whole µm). Every segment end carries its boundary anchor for linking.
 */
import type { Pt } from '../geometry/types.js';
import { workArray } from '../geometry/work-arrays.js';
import type { Sweep } from './types.js';
import type { RegionGeom } from './region-index.js';
import { type Piece, rnd } from './piece.js';

/** Segments shorter than this are dropped as degenerate (a scanline grazing a vertex), µm. */
const MIN_SEGMENT_UM = 1;

/** Clip one family of parallel lines to the region; appends pieces to `out` (each pointing in +u). */
export function clipSweep(geom: RegionGeom, sweep: Sweep, origin: Pt, out: Piece[]): void {
  if (!(sweep.spacingUm > 0) || geom.edgeCount === 0) return;
  const a = (sweep.angle * Math.PI) / 180;
  const c = Math.cos(a),
    s = Math.sin(a);
  const E = geom.edgeCount;
  // per edge, in the sweep frame: vLo, vHi, u at vLo, du/dv, and the arc data to anchor a crossing
  const vLo = workArray(E),
    vHi = workArray(E),
    uLo = workArray(E),
    dudv = workArray(E);
  const ring = workArray(E),
    edgeLocal = workArray(E),
    fromStart = workArray(E);
  let m = 0;
  let vMin = Infinity,
    vMax = -Infinity;
  for (let r = 0; r < geom.rings.length; r++) {
    const R = geom.rings[r];
    for (let i = 0; i < R.n; i++) {
      const j = i + 1 === R.n ? 0 : i + 1;
      const x0 = R.xs[i],
        y0 = R.ys[i],
        x1 = R.xs[j],
        y1 = R.ys[j];
      const v0 = -x0 * s + y0 * c,
        v1 = -x1 * s + y1 * c;
      if (v0 === v1) continue;
      const u0 = x0 * c + y0 * s,
        u1 = x1 * c + y1 * s;
      if (v0 < v1) {
        vLo[m] = v0;
        vHi[m] = v1;
        uLo[m] = u0;
        fromStart[m] = 1;
      } else {
        vLo[m] = v1;
        vHi[m] = v0;
        uLo[m] = u1;
        fromStart[m] = 0;
      }
      dudv[m] = (u1 - u0) / (v1 - v0);
      ring[m] = r;
      edgeLocal[m] = i;
      if (vLo[m] < vMin) vMin = vLo[m];
      if (vHi[m] > vMax) vMax = vHi[m];
      m++;
    }
  }
  if (m === 0) return;
  const order = workArray(m);
  for (let i = 0; i < m; i++) order[i] = i;
  order.sort((p, q) => vLo[p] - vLo[q] || p - q);

  const v0 = -origin.x * s + origin.y * c + sweep.offsetUm;
  const kFirst = Math.ceil((vMin - v0) / sweep.spacingUm);
  const kLast = Math.floor((vMax - v0) / sweep.spacingUm);
  const active: number[] = [];
  const xu: number[] = [];
  const xe: number[] = [];
  let next = 0;
  for (let k = kFirst; k <= kLast; k++) {
    const v = v0 + k * sweep.spacingUm;
    while (next < m && vLo[order[next]] <= v) active.push(order[next++]);
    // drop edges that ended; compute crossings
    let w = 0;
    xu.length = 0;
    xe.length = 0;
    for (let q = 0; q < active.length; q++) {
      const e = active[q];
      if (vHi[e] <= v) continue;
      active[w++] = e;
      xu.push(uLo[e] + (v - vLo[e]) * dudv[e]);
      xe.push(e);
    }
    active.length = w;
    const n = xu.length;
    if (n < 2) continue;
    // insertion sort (crossing counts per scanline are small)
    for (let i = 1; i < n; i++) {
      const ku = xu[i],
        ke = xe[i];
      let j = i - 1;
      while (j >= 0 && (xu[j] > ku || (xu[j] === ku && xe[j] > ke))) {
        xu[j + 1] = xu[j];
        xe[j + 1] = xe[j];
        j--;
      }
      xu[j + 1] = ku;
      xe[j + 1] = ke;
    }
    for (let i = 0; i + 1 < n; i += 2) {
      const ua = xu[i],
        ub = xu[i + 1];
      if (ub - ua < MIN_SEGMENT_UM) continue;
      out.push({
        pts: [rnd(ua * c - v * s, ua * s + v * c), rnd(ub * c - v * s, ub * s + v * c)],
        a0: anchorOf(geom, xe[i], v, vLo, vHi, fromStart, ring, edgeLocal),
        a1: anchorOf(geom, xe[i + 1], v, vLo, vHi, fromStart, ring, edgeLocal),
      });
    }
  }
}

function anchorOf(
  geom: RegionGeom,
  e: number,
  v: number,
  vLo: number[],
  vHi: number[],
  fromStart: number[],
  ring: number[],
  edgeLocal: number[],
) {
  const f = (v - vLo[e]) / (vHi[e] - vLo[e]);
  const t = fromStart[e] ? f : 1 - f;
  const R = geom.rings[ring[e]];
  const i = edgeLocal[e];
  return { ring: ring[e], pos: R.cum[i] + t * (R.cum[i + 1] - R.cum[i]) };
}

/**
 * The lines of one family over a single convex ring, as clipSweep cuts them (the same frame, the same
 * half-open crossing rule, the same rounding), without the sweep's set-up: a convex ring meets each line
 * in at most one segment. Segments that round to a point are left out.
 */
export function sweepConvexRing(ring: readonly Pt[], sweep: Sweep, origin: Pt): Pt[][] {
  const out: Pt[][] = [];
  const n = ring.length;
  if (!(sweep.spacingUm > 0) || n < 3) return out;
  const a = (sweep.angle * Math.PI) / 180;
  const c = Math.cos(a),
    s = Math.sin(a);
  let vMin = Infinity,
    vMax = -Infinity;
  for (const p of ring) {
    const v = -p.x * s + p.y * c;
    if (v < vMin) vMin = v;
    if (v > vMax) vMax = v;
  }
  const v0 = -origin.x * s + origin.y * c + sweep.offsetUm;
  const kFirst = Math.ceil((vMin - v0) / sweep.spacingUm);
  const kLast = Math.floor((vMax - v0) / sweep.spacingUm);
  for (let k = kFirst; k <= kLast; k++) {
    const v = v0 + k * sweep.spacingUm;
    let ua = Infinity,
      ub = -Infinity,
      crossings = 0;
    for (let i = 0; i < n; i++) {
      const p = ring[i],
        q = ring[i + 1 === n ? 0 : i + 1];
      const pv = -p.x * s + p.y * c,
        qv = -q.x * s + q.y * c;
      if (pv === qv) continue;
      const lo = pv < qv ? pv : qv,
        hi = pv < qv ? qv : pv;
      if (!(lo <= v && v < hi)) continue;
      const pu = p.x * c + p.y * s,
        qu = q.x * c + q.y * s;
      const uLo = pv < qv ? pu : qu;
      const u = uLo + (v - lo) * ((qu - pu) / (qv - pv));
      crossings++;
      if (u < ua) ua = u;
      if (u > ub) ub = u;
    }
    if (crossings !== 2 || ub - ua < MIN_SEGMENT_UM) continue;
    const pa = rnd(ua * c - v * s, ua * s + v * c),
      pb = rnd(ub * c - v * s, ub * s + v * c);
    if (pa.x !== pb.x || pa.y !== pb.y) out.push([pa, pb]);
  }
  return out;
}
