/** Small polyline helpers: simplification (Douglas–Peucker), length, conversion to µm. */
import type { Polyline, Pt } from '../geometry/types.js';
import type { MmPath } from './contour-link.js';

/** Douglas–Peucker on a flat mm path, keeping both ends; tolerance in mm. */
export function simplifyMmPath(path: MmPath, tol: number): MmPath {
  const n = path.length / 2;
  if (n <= 2 || tol <= 0) return path.slice();
  const keep = new Uint8Array(n);
  keep[0] = 1;
  keep[n - 1] = 1;
  const stack: number[] = [0, n - 1];
  const tol2 = tol * tol;
  while (stack.length > 0) {
    const b = stack.pop() as number;
    const a = stack.pop() as number;
    const ax = path[2 * a];
    const ay = path[2 * a + 1];
    const dx = path[2 * b] - ax;
    const dy = path[2 * b + 1] - ay;
    const len2 = dx * dx + dy * dy;
    let worst = -1;
    let worstD = tol2;
    for (let i = a + 1; i < b; i++) {
      const px = path[2 * i] - ax;
      const py = path[2 * i + 1] - ay;
      let d2: number;
      if (len2 === 0) d2 = px * px + py * py;
      else {
        const t = Math.max(0, Math.min(1, (px * dx + py * dy) / len2));
        const qx = px - t * dx;
        const qy = py - t * dy;
        d2 = qx * qx + qy * qy;
      }
      if (d2 > worstD) {
        worstD = d2;
        worst = i;
      }
    }
    if (worst >= 0) {
      keep[worst] = 1;
      stack.push(a, worst, worst, b);
    }
  }
  const out: MmPath = [];
  for (let i = 0; i < n; i++) if (keep[i]) out.push(path[2 * i], path[2 * i + 1]);
  return out;
}

/** A mm path as an integer-µm polyline, dropping repeated points. */
export function toMicrons(path: MmPath): Polyline {
  const out: Pt[] = [];
  for (let i = 0; i < path.length; i += 2) {
    const p = { x: Math.round(path[i] * 1000), y: Math.round(path[i + 1] * 1000) };
    const last = out[out.length - 1];
    if (last !== undefined && last.x === p.x && last.y === p.y) continue;
    out.push(p);
  }
  return out;
}

export function polylineLength(p: readonly Pt[]): number {
  let s = 0;
  for (let i = 1; i < p.length; i++) s += Math.hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
  return s;
}

export function isClosed(p: readonly Pt[]): boolean {
  return p.length > 3 && p[0].x === p[p.length - 1].x && p[0].y === p[p.length - 1].y;
}
