/**
 * Raw mitred offset of closed rings, before the clean-up union.
 *
 * A general offsetter turns every concave corner (one where the two offset edges overlap) into a
 * small backwards loop through the original vertex and lets the final union remove it; on a
 * shrink every convex corner of the outline is such a corner, so the union has two extra
 * crossings per vertex to resolve. Here a concave corner whose offset edges cross inside both of
 * them (neither edge is used up by its two corners) gets that crossing point directly: the same
 * point the union would find, without the loop. An offset edge used up between two concave corners
 * is dropped and its neighbours meet instead; corners of other used-up edges keep their loops, so
 * such reversals are still left to the union. Convex corners get the usual mitre point, or are
 * squared off past the mitre limit.
 */
import type { Polygon, Pt } from './types.js';

const CONCAVE = 1,
  SQUARE = 2,
  LOOP = 4;

/**
 * The working arrays of rawMiterOffset, per vertex of the longest ring it has met (grown as needed): whoever
 * makes one owns it and hands it to each call, which overwrites what it reads (the clip operations keep one;
 * see clip.ts for why a kept one and not a fresh one per call).
 */
export class MiterWork {
  /** Unit normal of the edge from vertex i (pointing right of the ring's direction). */
  nx = new Float64Array(0);
  ny = new Float64Array(0);
  /** Length of the edge from vertex i, µm. */
  len = new Float64Array(0);
  /** cos of the turn at vertex i. */
  cosA = new Float64Array(0);
  /** How much of each adjacent offset edge the concave corner at vertex i uses up, µm. */
  used = new Float64Array(0);
  /** The corner's kind: CONCAVE, SQUARE, LOOP bits. */
  flag = new Uint8Array(0);
  /** dropUsedUpEdges, per edge: its neighbours still alive, the corner at its start, the edges to look at. */
  prev = new Int32Array(0);
  next = new Int32Array(0);
  cx = new Float64Array(0);
  cy = new Float64Array(0);
  stack = new Int32Array(0);

  /** Room for a ring of n points. */
  reserve(n: number): void {
    if (this.nx.length >= n) return;
    const m = Math.max(n, 2 * this.nx.length, 64);
    this.nx = new Float64Array(m);
    this.ny = new Float64Array(m);
    this.len = new Float64Array(m);
    this.cosA = new Float64Array(m);
    this.used = new Float64Array(m);
    this.flag = new Uint8Array(m);
    this.prev = new Int32Array(m);
    this.next = new Int32Array(m);
    this.cx = new Float64Array(m);
    this.cy = new Float64Array(m);
    this.stack = new Int32Array(2 * m);
  }
}

/** cos of the turn beyond which a corner is a spike: squared off, whichever way it turns. */
const SPIKE_COS = -0.999;

export interface RawOffset {
  /** One raw ring per input ring, in the same order. */
  rings: Pt[][];
  /** Whether some concave corner kept its backward loop (the rings then certainly overlap themselves). */
  loops: boolean;
}

/**
 * The raw offset rings (to be unioned with the positive fill rule), or null when some corner needs
 * a join this fast path does not make (a repeated point, a ring with fewer than three points,
 * rings wound the other way round): the caller then uses the general offsetter. Convex corners
 * past the mitre limit and spikes are squared off.
 * @param rings outer rings counter-clockwise, holes clockwise, µm
 * @param delta offset distance, µm (> 0 grows)
 * @param miterLimit mitre limit as a multiple of delta
 * @param work the working arrays (a fresh set when not given)
 */
export function rawMiterOffset(
  rings: readonly Polygon[],
  delta: number,
  miterLimit: number,
  work: MiterWork = new MiterWork(),
): RawOffset | null {
  if (!outermostIsCounterClockwise(rings)) return null;
  // a mitre is made while cos(turn) > mitreCos; beyond that the corner would be squared off
  const mitreCos = (miterLimit <= 1 ? 2 : 2 / (miterLimit * miterLimit)) - 1;
  const absDelta = Math.abs(delta);
  const out: Pt[][] = [];
  let loops = false;
  let most = 0;
  for (const ring of rings) if (ring.length > most) most = ring.length;
  work.reserve(most);
  const { nx, ny, len, cosA, used, flag } = work;
  for (const ring of rings) {
    const n = ring.length;
    if (n < 3) return null;
    for (let i = 0; i < n; i++) {
      const a = ring[i],
        b = ring[i + 1 === n ? 0 : i + 1];
      const dx = b.x - a.x,
        dy = b.y - a.y;
      if (dx === 0 && dy === 0) return null;
      const l = Math.sqrt(dx * dx + dy * dy);
      const f = 1 / l;
      nx[i] = dy * f;
      ny[i] = -dx * f;
      len[i] = l;
    }
    // per corner j (between edge j-1 and edge j): cos of the turn, its kind, and how much of each
    // adjacent offset edge a concave corner uses up (0 for the others)
    for (let j = 0, k = n - 1; j < n; k = j++) {
      let sin = ny[j] * nx[k] - ny[k] * nx[j];
      if (sin > 1) sin = 1;
      else if (sin < -1) sin = -1;
      const cos = nx[j] * nx[k] + ny[j] * ny[k];
      cosA[j] = cos;
      used[j] = 0;
      flag[j] = 0;
      if (cos > SPIKE_COS && sin * delta < 0) {
        flag[j] = CONCAVE;
        used[j] = (absDelta * Math.abs(sin)) / (1 + cos);
      } else if (cos <= 0.999 && cos <= mitreCos) {
        flag[j] = SQUARE;
      }
    }
    // a concave corner keeps the loop when an adjacent edge is used up by its two corners
    let usedUp = false;
    for (let i = 0; i < n; i++) {
      const next = i + 1 === n ? 0 : i + 1;
      if (used[i] + used[next] >= len[i] - 1) {
        usedUp = true;
        if (flag[i] & CONCAVE) flag[i] |= LOOP;
        if (flag[next] & CONCAVE) flag[next] |= LOOP;
      }
    }
    // unless used-up edges lie between concave corners only: then they are dropped instead
    const collapsed = usedUp ? dropUsedUpEdges(ring, delta, work) : null;
    if (collapsed) {
      out.push(collapsed);
      continue;
    }
    const path: Pt[] = [];
    for (let j = 0, k = n - 1; j < n; k = j++) {
      const p = ring[j];
      if (flag[j] & LOOP) {
        loops = true;
        path.push({ x: Math.round(p.x + nx[k] * delta), y: Math.round(p.y + ny[k] * delta) });
        path.push(p);
        path.push({ x: Math.round(p.x + nx[j] * delta), y: Math.round(p.y + ny[j] * delta) });
      } else if (flag[j] & SQUARE) {
        squareCorner(p, nx[k], ny[k], nx[j], ny[j], delta, path);
      } else {
        const q = delta / (cosA[j] + 1);
        path.push({ x: Math.round(p.x + (nx[k] + nx[j]) * q), y: Math.round(p.y + (ny[k] + ny[j]) * q) });
      }
    }
    out.push(path);
  }
  return { rings: out, loops };
}

/**
 * The raw offset of one ring (whose normals, turns and corner kinds are in `work`) with every
 * used-up offset edge between two concave corners dropped: its neighbours' offset lines meet
 * instead, as in the union of the looped version, repeated until no edge is used up. Null when
 * that does not settle it: a squared corner on the ring, a used-up edge next to a mitred corner, a
 * merged corner that is no longer concave, or fewer than three edges left.
 */
function dropUsedUpEdges(ring: Polygon, delta: number, work: MiterWork): Pt[] | null {
  const n = ring.length;
  const { nx, ny, cosA, flag, prev, next, cx, cy, stack } = work;
  for (let e = 0; e < n; e++) if (flag[e] & SQUARE) return null;
  // cx, cy: the corner at the start of edge e, where the offset lines of prev[e] and e meet
  for (let e = 0, k = n - 1; e < n; k = e++) {
    prev[e] = k;
    next[k] = e;
    const q = delta / (cosA[e] + 1);
    cx[e] = ring[e].x + (nx[k] + nx[e]) * q;
    cy[e] = ring[e].y + (ny[k] + ny[e]) * q;
    stack[e] = e;
  }
  let top = n,
    alive = n,
    first = 0;
  while (top > 0) {
    const e = stack[--top];
    if (prev[e] < 0) continue; // dropped already
    const b = next[e];
    // the offset edge runs along (-ny, nx) from its start corner to the next one
    if ((cx[b] - cx[e]) * -ny[e] + (cy[b] - cy[e]) * nx[e] >= 1) continue;
    if (!(flag[e] & CONCAVE) || !(flag[b] & CONCAVE) || alive <= 3) return null;
    const a = prev[e];
    // drop e: the offset lines of a and b now meet
    const turnSin = ny[b] * nx[a] - ny[a] * nx[b];
    const turnCos = nx[a] * nx[b] + ny[a] * ny[b];
    if (!(turnCos > SPIKE_COS && turnSin * delta < 0)) return null;
    const pax = ring[a].x + nx[a] * delta,
      pay = ring[a].y + ny[a] * delta;
    const pbx = ring[b].x + nx[b] * delta,
      pby = ring[b].y + ny[b] * delta;
    // directions: da = (-ny[a], nx[a]), db = (-ny[b], nx[b]); pa + t·da = pb + s·db
    const cross = nx[a] * ny[b] - ny[a] * nx[b]; // cross(da, db)
    const t = ((pbx - pax) * nx[b] + (pby - pay) * ny[b]) / cross; // cross(pb - pa, db) / cross(da, db)
    cx[b] = pax - ny[a] * t;
    cy[b] = pay + nx[a] * t;
    next[a] = b;
    prev[b] = a;
    prev[e] = -1;
    if (e === first) first = b;
    alive--;
    stack[top++] = a;
    stack[top++] = b;
  }
  const path: Pt[] = [];
  let e = first;
  do {
    path.push({ x: Math.round(cx[e]), y: Math.round(cy[e]) });
    e = next[e];
  } while (e !== first);
  return path;
}

/**
 * A corner too sharp for a mitre, squared off: cut by the line square to the corner's bisector at
 * |delta| from the vertex; its two points are where that line meets the two offset edges.
 */
function squareCorner(p: Pt, n1x: number, n1y: number, n2x: number, n2y: number, delta: number, out: Pt[]): void {
  // unit bisector, pointing to the wider side of the corner: the incoming edge's direction minus
  // the outgoing one's (edge direction = the normal turned a quarter left); stable for spikes
  let mx = n2y - n1y,
    my = n1x - n2x;
  const ml = Math.sqrt(mx * mx + my * my);
  mx /= ml;
  my /= ml;
  const absDelta = Math.abs(delta);
  out.push(squarePoint(p, n1x, n1y, mx, my, delta, absDelta));
  out.push(squarePoint(p, n2x, n2y, mx, my, delta, absDelta));
}

/** Where the offset edge with normal (nx, ny) meets the square cut with unit bisector (mx, my). */
function squarePoint(p: Pt, nx: number, ny: number, mx: number, my: number, delta: number, absDelta: number): Pt {
  const ex = -ny,
    ey = nx; // edge direction: the normal turned a quarter left
  const t = (absDelta - delta * (nx * mx + ny * my)) / (ex * mx + ey * my);
  return { x: Math.round(p.x + nx * delta + t * ex), y: Math.round(p.y + ny * delta + t * ey) };
}

/**
 * Whether the ring holding the lowest point (largest y, then smallest x) winds counter-clockwise:
 * it is an outer ring, so the rings are wound as outer CCW, holes CW.
 */
function outermostIsCounterClockwise(rings: readonly Polygon[]): boolean {
  let best = -1,
    bx = 0,
    by = -Infinity;
  for (let r = 0; r < rings.length; r++) {
    for (const p of rings[r]) {
      if (p.y > by || (p.y === by && p.x < bx)) {
        best = r;
        bx = p.x;
        by = p.y;
      }
    }
  }
  if (best < 0) return false;
  const ring = rings[best];
  let a = 0;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) a += (ring[j].x + ring[i].x) * (ring[j].y - ring[i].y);
  return a < 0;
}
