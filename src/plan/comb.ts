/**
 * Combing: travel routes that stay inside an island. A straight travel that would leave the island
 * (across a concave part of the outline) or cross a hole is replaced by a walk along the boundary
 * between the points where it would cross. Rings are walked the shorter way round.
 */
import { pointInRing } from '../geometry/contain.js';
import { hypot, segmentDistance2, type ExPolygon, type Polygon, type Pt } from '../geometry/types.js';
import { SEGMENT_T_EPS } from '../geometry/tolerances.js';

/** Parametric crossing of segment a→b with ring edge i: t along a→b, u along the edge. */
interface Crossing {
  t: number;
  ring: number;
  edge: number;
  u: number;
  p: Pt;
}

/** Ring with its bounding box, for quick rejection. */
export interface CombRing {
  pts: Polygon;
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  /** Cumulative length at each vertex (for walking distances), made when a travel first walks the ring. */
  cum: Float64Array | null;
}

export interface CombArea {
  outline: ExPolygon;
  rings: CombRing[];
}

function makeRing(pts: Polygon): CombRing {
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (let i = 0; i < pts.length; i++) {
    const p = pts[i];
    if (p.x < minX) minX = p.x;
    if (p.y < minY) minY = p.y;
    if (p.x > maxX) maxX = p.x;
    if (p.y > maxY) maxY = p.y;
  }
  return { pts, minX, minY, maxX, maxY, cum: null };
}

/** The ring's cumulative lengths (the last is its perimeter). */
function cumulative(ring: CombRing): Float64Array {
  if (ring.cum) return ring.cum;
  const pts = ring.pts;
  const n = pts.length;
  const cum = new Float64Array(n + 1);
  for (let i = 0; i < n; i++) {
    const p = pts[i],
      q = pts[(i + 1) % n];
    cum[i + 1] = cum[i] + hypot(q.x - p.x, q.y - p.y);
  }
  return (ring.cum = cum);
}

/** Prepare an island for combing: `boundary` is the ring set to walk along (e.g. the outer wall's centreline). */
export function makeCombArea(outline: ExPolygon, boundary: readonly Polygon[]): CombArea {
  return { outline, rings: boundary.filter((r) => r.length >= 3).map(makeRing) };
}

function crossings(a: Pt, b: Pt, rings: readonly CombRing[]): Crossing[] {
  const out: Crossing[] = [];
  const minX = Math.min(a.x, b.x),
    maxX = Math.max(a.x, b.x),
    minY = Math.min(a.y, b.y),
    maxY = Math.max(a.y, b.y);
  const dx = b.x - a.x,
    dy = b.y - a.y;
  for (let r = 0; r < rings.length; r++) {
    const ring = rings[r];
    if (ring.maxX < minX || ring.minX > maxX || ring.maxY < minY || ring.minY > maxY) continue;
    const pts = ring.pts;
    const n = pts.length;
    for (let i = 0; i < n; i++) {
      const p = pts[i],
        q = pts[i + 1 === n ? 0 : i + 1];
      if (
        (p.x < minX && q.x < minX) ||
        (p.x > maxX && q.x > maxX) ||
        (p.y < minY && q.y < minY) ||
        (p.y > maxY && q.y > maxY)
      )
        continue;
      const ex = q.x - p.x,
        ey = q.y - p.y;
      const den = dx * ey - dy * ex;
      if (den === 0) continue;
      const fx = p.x - a.x,
        fy = p.y - a.y;
      const t = (fx * ey - fy * ex) / den;
      const u = (fx * dy - fy * dx) / den;
      if (t <= SEGMENT_T_EPS || t >= 1 - SEGMENT_T_EPS || u < 0 || u >= 1) continue;
      out.push({ t, ring: r, edge: i, u, p: { x: Math.round(a.x + t * dx), y: Math.round(a.y + t * dy) } });
    }
  }
  out.sort((c1, c2) => c1.t - c2.t);
  return out;
}

/** Walk ring from crossing c1 to crossing c2 the shorter way; returns the waypoints between them. */
function walk(ring: CombRing, c1: Crossing, c2: Crossing): Pt[] {
  const n = ring.pts.length;
  const cum = cumulative(ring);
  const length = cum[n];
  const pos = (c: Crossing) => cum[c.edge] + c.u * (cum[c.edge + 1] - cum[c.edge]);
  const s1 = pos(c1),
    s2 = pos(c2);
  let forward = s2 - s1;
  if (forward < 0) forward += length;
  const out: Pt[] = [c1.p];
  if (forward <= length - forward) {
    // forward: vertices edge+1 ... up to c2.edge
    let i = (c1.edge + 1) % n;
    const stop = (c2.edge + 1) % n;
    let guard = 0;
    if (!(c1.edge === c2.edge && c2.u >= c1.u)) {
      while (i !== stop && guard++ <= n) {
        out.push(ring.pts[i]);
        i = (i + 1) % n;
      }
    }
  } else {
    let i = c1.edge;
    const stop = c2.edge;
    let guard = 0;
    if (!(c1.edge === c2.edge && c2.u <= c1.u)) {
      while (i !== stop && guard++ <= n) {
        out.push(ring.pts[i]);
        i = (i - 1 + n) % n;
      }
    }
  }
  out.push(c2.p);
  return out;
}

export function pathLengthUm(a: Pt, way: readonly Pt[]): number {
  let len = 0;
  let p = a;
  for (const q of way) {
    len += hypot(q.x - p.x, q.y - p.y);
    p = q;
  }
  return len;
}

/**
 * Route a travel from a to b inside the comb area. Returns the waypoints after `a` (ending with b),
 * or null when no route stays inside (the caller then retracts and travels straight).
 */
export function combRoute(a: Pt, b: Pt, area: CombArea): Pt[] | null {
  const cs = crossings(a, b, area.rings);
  if (cs.length === 0) return [b];
  const way: Pt[] = [];
  let i = 0;
  while (i < cs.length) {
    const c1 = cs[i];
    // the next crossing of the same ring closes this excursion
    let j = i + 1;
    while (j < cs.length && cs[j].ring !== c1.ring) j++;
    if (j >= cs.length) return null;
    // crossings of other rings between i and j mean nested trouble: give up
    if (j !== i + 1) return null;
    for (const p of walk(area.rings[c1.ring], c1, cs[j])) way.push(p);
    i = j + 1;
  }
  way.push(b);
  return way;
}

/**
 * Whether `p` is inside the comb area's rings (even-odd over all of them: outer loops and the loops round
 * holes) or within `tolerance` µm of one (a travel that starts where a loop of the rings ended).
 */
export function insideRings(p: Pt, area: CombArea, tolerance: number): boolean {
  // inside by parity first (most travels are): the distances to the rings only for a point outside them
  let inside = false;
  for (const ring of area.rings) {
    if (p.x < ring.minX || p.x > ring.maxX || p.y < ring.minY || p.y > ring.maxY) continue;
    if (pointInRing(p, ring.pts)) inside = !inside;
  }
  if (inside) return true;
  const t2 = tolerance * tolerance;
  for (const ring of area.rings) {
    if (
      p.x < ring.minX - tolerance ||
      p.x > ring.maxX + tolerance ||
      p.y < ring.minY - tolerance ||
      p.y > ring.maxY + tolerance
    )
      continue;
    const pts = ring.pts;
    for (let i = 0, j = pts.length - 1; i < pts.length; j = i++) {
      if (segmentDistance2(p.x, p.y, pts[j].x, pts[j].y, pts[i].x, pts[i].y) <= t2) return true;
    }
  }
  return false;
}
