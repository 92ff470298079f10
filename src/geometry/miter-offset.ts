/**
 * Raw mitred offset of closed rings, before the clean-up union.
 *
 * A general offsetter turns every concave corner (one where the two offset edges overlap) into a
 * small backwards loop through the original vertex and lets the final union remove it; on a
 * shrink every convex corner of the outline is such a corner, so the union has two extra
 * crossings per vertex to resolve. Here a concave corner whose offset edges cross inside both of
 * them (neither edge is used up by its two corners) gets that crossing point directly: the same
 * point the union would find, without the loop. Corners whose edges are used up keep the loop, so
 * reversals are still left to the union. Convex corners get the usual mitre point, or are squared
 * off past the mitre limit.
 */
import type { Polygon, Pt } from './types.js';

/** cos of the turn beyond which a corner is a spike: squared off, whichever way it turns. */
const SPIKE_COS = -0.999;

/**
 * The raw offset rings (to be unioned with the positive fill rule), or null when some corner needs
 * a join this fast path does not make (a repeated point, a ring with fewer than three points,
 * rings wound the other way round): the caller then uses the general offsetter. Convex corners
 * past the mitre limit and spikes are squared off.
 * @param rings outer rings counter-clockwise, holes clockwise, µm
 * @param delta offset distance, µm (> 0 grows)
 * @param miterLimit mitre limit as a multiple of delta
 */
export function rawMiterOffset(rings: readonly Polygon[], delta: number, miterLimit: number): Pt[][] | null {
  if (!outermostIsCounterClockwise(rings)) return null;
  // a mitre is made while cos(turn) > mitreCos; beyond that the corner would be squared off
  const mitreCos = (miterLimit <= 1 ? 2 : 2 / (miterLimit * miterLimit)) - 1;
  const absDelta = Math.abs(delta);
  const out: Pt[][] = [];
  for (const ring of rings) {
    const n = ring.length;
    if (n < 3) return null;
    const nx = new Float64Array(n), ny = new Float64Array(n), len = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      const a = ring[i], b = ring[i + 1 === n ? 0 : i + 1];
      const dx = b.x - a.x, dy = b.y - a.y;
      if (dx === 0 && dy === 0) return null;
      const l = Math.sqrt(dx * dx + dy * dy);
      const f = 1 / l;
      nx[i] = dy * f;
      ny[i] = -dx * f;
      len[i] = l;
    }
    // per corner j (between edge j-1 and edge j): cos of the turn, and how much of each adjacent
    // offset edge a concave corner uses up (0 for convex corners)
    const cosA = new Float64Array(n), used = new Float64Array(n);
    const concave = new Uint8Array(n), square = new Uint8Array(n);
    for (let j = 0, k = n - 1; j < n; k = j++) {
      let sin = ny[j] * nx[k] - ny[k] * nx[j];
      if (sin > 1) sin = 1;
      else if (sin < -1) sin = -1;
      const cos = nx[j] * nx[k] + ny[j] * ny[k];
      cosA[j] = cos;
      if (cos > SPIKE_COS && sin * delta < 0) {
        concave[j] = 1;
        used[j] = (absDelta * Math.abs(sin)) / (1 + cos);
      } else if (cos <= 0.999 && cos <= mitreCos) {
        square[j] = 1;
      }
    }
    // a concave corner keeps the loop when an adjacent edge is used up by its two corners
    const loop = new Uint8Array(n);
    for (let i = 0; i < n; i++) {
      const next = i + 1 === n ? 0 : i + 1;
      if (used[i] + used[next] >= len[i] - 1) {
        loop[i] = concave[i];
        loop[next] = concave[next];
      }
    }
    const path: Pt[] = [];
    for (let j = 0, k = n - 1; j < n; k = j++) {
      const p = ring[j];
      if (loop[j]) {
        path.push({ x: Math.round(p.x + nx[k] * delta), y: Math.round(p.y + ny[k] * delta) });
        path.push(p);
        path.push({ x: Math.round(p.x + nx[j] * delta), y: Math.round(p.y + ny[j] * delta) });
      } else if (square[j]) {
        squareCorner(p, nx[k], ny[k], nx[j], ny[j], delta, path);
      } else {
        const q = delta / (cosA[j] + 1);
        path.push({ x: Math.round(p.x + (nx[k] + nx[j]) * q), y: Math.round(p.y + (ny[k] + ny[j]) * q) });
      }
    }
    out.push(path);
  }
  return out;
}

/**
 * A corner too sharp for a mitre, squared off: cut by the line square to the corner's bisector at
 * |delta| from the vertex; its two points are where that line meets the two offset edges.
 */
function squareCorner(p: Pt, n1x: number, n1y: number, n2x: number, n2y: number, delta: number, out: Pt[]): void {
  // unit bisector, pointing to the wider side of the corner: the incoming edge's direction minus
  // the outgoing one's (edge direction = the normal turned a quarter left); stable for spikes
  let mx = n2y - n1y, my = n1x - n2x;
  const ml = Math.sqrt(mx * mx + my * my);
  mx /= ml;
  my /= ml;
  const absDelta = Math.abs(delta);
  for (const [nx, ny] of [[n1x, n1y], [n2x, n2y]]) {
    const ex = -ny, ey = nx;
    const t = (absDelta - delta * (nx * mx + ny * my)) / (ex * mx + ey * my);
    out.push({ x: Math.round(p.x + nx * delta + t * ex), y: Math.round(p.y + ny * delta + t * ey) });
  }
}

/**
 * Whether the ring holding the lowest point (largest y, then smallest x) winds counter-clockwise:
 * it is an outer ring, so the rings are wound as outer CCW, holes CW.
 */
function outermostIsCounterClockwise(rings: readonly Polygon[]): boolean {
  let best = -1, bx = 0, by = -Infinity;
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
