/**
 * Ordering paths for short travel: greedy nearest neighbour from a start point over a bucket grid
 * of path ends. Open paths may be reversed; closed loops may start at any vertex. Consecutive paths
 * whose ends touch are joined into one polyline.
 */
import type { Polyline, Pt } from '../geometry/types.js';
import { isClosed } from './polyline-tools.js';

interface Entry {
  path: Polyline;
  closed: boolean;
  used: boolean;
}

function rotateClosed(p: Polyline, at: Pt): Polyline {
  // p repeats its first point at the end; start it at the vertex nearest `at`.
  let best = 0;
  let bestD = Infinity;
  for (let i = 0; i < p.length - 1; i++) {
    const d = (p[i].x - at.x) ** 2 + (p[i].y - at.y) ** 2;
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  if (best === 0) return p;
  const ring = p.slice(0, -1);
  const out = [...ring.slice(best), ...ring.slice(0, best)];
  out.push(out[0]);
  return out;
}

/** Order (and orient) paths from `start` so the travel between them is short. */
export function orderPaths(paths: readonly Polyline[], start: Pt, joinGap = 5): Polyline[] {
  const entries: Entry[] = paths
    .filter((p) => p.length >= 2)
    .map((p) => ({ path: p, closed: isClosed(p), used: false }));
  if (entries.length === 0) return [];
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (const e of entries) {
    for (const q of [e.path[0], e.path[e.path.length - 1]]) {
      if (q.x < minX) minX = q.x;
      if (q.y < minY) minY = q.y;
      if (q.x > maxX) maxX = q.x;
      if (q.y > maxY) maxY = q.y;
    }
  }
  const span = Math.max(maxX - minX, maxY - minY, 1);
  const cell = Math.max(span / Math.ceil(Math.sqrt(entries.length)), 100);
  const gw = Math.floor((maxX - minX) / cell) + 1;
  const gh = Math.floor((maxY - minY) / cell) + 1;
  const buckets: number[][] = Array.from({ length: gw * gh }, () => []);
  const bucketOf = (p: Pt) => {
    const bx = Math.min(gw - 1, Math.max(0, Math.floor((p.x - minX) / cell)));
    const by = Math.min(gh - 1, Math.max(0, Math.floor((p.y - minY) / cell)));
    return by * gw + bx;
  };
  // Endpoint k: entry k >> 1, end (k & 1) (0 = first point, 1 = last point).
  entries.forEach((e, i) => {
    buckets[bucketOf(e.path[0])].push(2 * i);
    if (!e.closed) buckets[bucketOf(e.path[e.path.length - 1])].push(2 * i + 1);
  });
  const out: Polyline[] = [];
  let at = start;
  let remaining = entries.length;
  while (remaining > 0) {
    const cx = Math.min(gw - 1, Math.max(0, Math.floor((at.x - minX) / cell)));
    const cy = Math.min(gh - 1, Math.max(0, Math.floor((at.y - minY) / cell)));
    let best = -1;
    let bestD = Infinity;
    for (let r = 0; r <= Math.max(gw, gh); r++) {
      // Ring r around (cx, cy); stop once the ring is farther than the best found.
      if (best >= 0) {
        const ringDist = (r - 1) * cell;
        if (ringDist > 0 && ringDist * ringDist > bestD) break;
      }
      for (let by = cy - r; by <= cy + r; by++) {
        if (by < 0 || by >= gh) continue;
        for (let bx = cx - r; bx <= cx + r; bx++) {
          if (bx < 0 || bx >= gw) continue;
          if (Math.max(Math.abs(bx - cx), Math.abs(by - cy)) !== r) continue;
          const list = buckets[by * gw + bx];
          for (let k = list.length - 1; k >= 0; k--) {
            const ep = list[k];
            const e = entries[ep >> 1];
            if (e.used) {
              list[k] = list[list.length - 1];
              list.pop();
              continue;
            }
            const q = ep & 1 ? e.path[e.path.length - 1] : e.path[0];
            const d = (q.x - at.x) ** 2 + (q.y - at.y) ** 2;
            if (d < bestD) {
              bestD = d;
              best = ep;
            }
          }
        }
      }
    }
    const e = entries[best >> 1];
    e.used = true;
    remaining--;
    let p = e.path;
    if (e.closed) p = rotateClosed(p, at);
    else if (best & 1) p = p.slice().reverse();
    const prev = out[out.length - 1];
    const gap = prev === undefined ? Infinity : Math.hypot(p[0].x - at.x, p[0].y - at.y);
    if (prev !== undefined && gap <= joinGap && !isClosed(prev) && !e.closed) {
      out[out.length - 1] = prev.concat(gap === 0 ? p.slice(1) : p);
    } else out.push(p);
    at = p[p.length - 1];
  }
  return out;
}
