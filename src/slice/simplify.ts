/**
 * Ring simplification straight from a layer's slot sequences (before any point objects exist):
 * consecutive duplicates are dropped, then Douglas–Peucker keeps every removed point within the
 * tolerance of the kept outline, starting from a hull corner (a strict bound, unlike neighbour-only vertex removal).
 */
import { segmentDistance2, type Polygon } from '../geometry/types.js';

/**
 * Simplify closed rings given as slot sequences into µm polygons. Rings left with fewer than three
 * points are dropped. `toleranceUm` ≤ 0 only removes duplicates.
 */
export function simplifySlotRings(
  rings: readonly Int32Array[],
  slotX: Float64Array,
  slotY: Float64Array,
  toleranceUm: number,
): Polygon[] {
  const out: Polygon[] = [];
  const tol2 = toleranceUm > 0 ? toleranceUm * toleranceUm : 0;
  let xs = new Float64Array(256),
    ys = new Float64Array(256),
    rx = new Float64Array(256),
    ry = new Float64Array(256);
  let keep = new Uint8Array(256),
    stack = new Int32Array(512);
  for (const r of rings) {
    if (xs.length < r.length + 1) {
      const cap = 2 * r.length + 1;
      xs = new Float64Array(cap);
      ys = new Float64Array(cap);
      rx = new Float64Array(cap);
      ry = new Float64Array(cap);
      keep = new Uint8Array(cap);
      stack = new Int32Array(2 * cap);
    }
    // Dedupe (including the wrap-around).
    let n = 0;
    for (let i = 0; i < r.length; i++) {
      const x = slotX[r[i]],
        y = slotY[r[i]];
      if (n > 0 && xs[n - 1] === x && ys[n - 1] === y) continue;
      xs[n] = x;
      ys[n] = y;
      n++;
    }
    while (n > 1 && xs[n - 1] === xs[0] && ys[n - 1] === ys[0]) n--;
    if (n < 3) continue;
    if (tol2 === 0) {
      const ring: Polygon = new Array(n);
      for (let i = 0; i < n; i++) ring[i] = { x: xs[i], y: ys[i] };
      out.push(ring);
      continue;
    }
    // Start at the lowest-leftmost point (a hull corner, so a true vertex) and split the ring
    // there and at the point farthest from it (also a hull corner); index n closes the ring.
    let start = 0;
    for (let i = 1; i < n; i++) if (xs[i] < xs[start] || (xs[i] === xs[start] && ys[i] < ys[start])) start = i;
    if (start > 0) {
      for (let i = 0; i < n; i++) {
        const k = i + start < n ? i + start : i + start - n;
        rx[i] = xs[k];
        ry[i] = ys[k];
      }
      xs.set(rx.subarray(0, n));
      ys.set(ry.subarray(0, n));
    }
    let far = 0,
      farD = -1;
    for (let i = 1; i < n; i++) {
      const dx = xs[i] - xs[0],
        dy = ys[i] - ys[0];
      const d = dx * dx + dy * dy;
      if (d > farD) {
        farD = d;
        far = i;
      }
    }
    xs[n] = xs[0];
    ys[n] = ys[0];
    keep.fill(0, 0, n + 1);
    keep[0] = keep[far] = keep[n] = 1;
    let sp = 0;
    stack[sp++] = 0;
    stack[sp++] = far;
    stack[sp++] = far;
    stack[sp++] = n;
    while (sp > 0) {
      const b = stack[--sp],
        a = stack[--sp];
      if (b - a < 2) continue;
      let best = -1,
        bestD = tol2;
      const ax = xs[a],
        ay = ys[a],
        bx = xs[b],
        by = ys[b];
      for (let i = a + 1; i < b; i++) {
        const d = segmentDistance2(xs[i], ys[i], ax, ay, bx, by);
        if (d > bestD) {
          bestD = d;
          best = i;
        }
      }
      if (best < 0) continue;
      keep[best] = 1;
      stack[sp++] = a;
      stack[sp++] = best;
      stack[sp++] = best;
      stack[sp++] = b;
    }
    let m = 0;
    for (let i = 0; i < n; i++) m += keep[i];
    if (m < 3) continue;
    const ring: Polygon = new Array(m);
    for (let i = 0, j = 0; i < n; i++) if (keep[i]) ring[j++] = { x: xs[i], y: ys[i] };
    out.push(ring);
  }
  return out;
}
