/**
 * Final clean-up of a layer's infill: repeated points and zero-length segments go, a segment that appears
 * twice (in either direction, in any path) is kept once (the later copy is cut out of its path), and
 * paths too short to print are dropped.
 */
import type { Pt } from '../geometry/types.js';
import { polylineLengthUm, pushPt } from './piece.js';

/** Remove consecutive repeated points. */
export function dedupePoints(pts: readonly Pt[]): Pt[] {
  const out: Pt[] = [];
  for (const p of pts) pushPt(out, p);
  return out;
}

/**
 * Clean lines and loops. Loops that lose a segment become open lines. `minLengthUm`: shorter open paths
 * are dropped (a blob, not a line).
 */
export function cleanPaths(
  lines: readonly Pt[][],
  loops: readonly Pt[][],
  minLengthUm: number,
): { lines: Pt[][]; loops: Pt[][] } {
  const L = lines.map(dedupePoints).filter((l) => l.length >= 2);
  const C = loops
    .map((l) => {
      const d = dedupePoints(l);
      while (d.length > 1 && d[0].x === d[d.length - 1].x && d[0].y === d[d.length - 1].y) d.pop();
      return d;
    })
    .filter((l) => l.length >= 3);
  // every segment: canonical key (smaller endpoint first), owner path, index
  let n = 0;
  for (const l of L) n += l.length - 1;
  for (const l of C) n += l.length;
  const key = new Float64Array(4 * n);
  const owner = new Int32Array(n);
  const idx = new Int32Array(n);
  let k = 0;
  const add = (a: Pt, b: Pt, o: number, i: number) => {
    const swap = a.x > b.x || (a.x === b.x && a.y > b.y);
    const p = swap ? b : a,
      q = swap ? a : b;
    key[4 * k] = p.x;
    key[4 * k + 1] = p.y;
    key[4 * k + 2] = q.x;
    key[4 * k + 3] = q.y;
    owner[k] = o;
    idx[k] = i;
    k++;
  };
  L.forEach((l, o) => {
    for (let i = 0; i + 1 < l.length; i++) add(l[i], l[i + 1], o, i);
  });
  C.forEach((l, o) => {
    for (let i = 0; i < l.length; i++) add(l[i], l[(i + 1) % l.length], L.length + o, i);
  });
  // find equal segments: sort by a hash of the four coordinates (native numeric sort of hash·2²⁰ + index),
  // then compare exactly within runs of equal hash; the lowest index of a set of copies is kept
  const drop = new Uint8Array(n);
  let any = false;
  const same = (a: number, b: number) =>
    key[4 * a] === key[4 * b] &&
    key[4 * a + 1] === key[4 * b + 1] &&
    key[4 * a + 2] === key[4 * b + 2] &&
    key[4 * a + 3] === key[4 * b + 3];
  if (n < 1 << 20) {
    const sk = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      let h = Math.imul(key[4 * i] | 0, 73856093) ^ Math.imul(key[4 * i + 1] | 0, 19349663);
      h ^= Math.imul(key[4 * i + 2] | 0, 83492791) ^ Math.imul(key[4 * i + 3] | 0, 49979687);
      sk[i] = (h >>> 0) * 1048576 + i;
    }
    sk.sort();
    for (let r = 0; r < n; ) {
      const hr = Math.floor(sk[r] / 1048576);
      let e = r + 1;
      while (e < n && Math.floor(sk[e] / 1048576) === hr) e++;
      for (let a = r; a < e; a++) {
        const ia = sk[a] % 1048576;
        if (drop[ia]) continue;
        for (let b = a + 1; b < e; b++) {
          const ib = sk[b] % 1048576;
          if (!drop[ib] && same(ia, ib)) {
            drop[ib] = 1;
            any = true;
          }
        }
      }
      r = e;
    }
  } else {
    const order = new Int32Array(n);
    for (let i = 0; i < n; i++) order[i] = i;
    order.sort(
      (a, b) =>
        key[4 * a] - key[4 * b] ||
        key[4 * a + 1] - key[4 * b + 1] ||
        key[4 * a + 2] - key[4 * b + 2] ||
        key[4 * a + 3] - key[4 * b + 3] ||
        a - b,
    );
    for (let i = 1; i < n; i++) {
      if (same(order[i - 1], order[i])) {
        drop[order[i]] = 1;
        any = true;
      }
    }
  }
  let outLines: Pt[][] = L;
  let outLoops: Pt[][] = C;
  if (any) {
    const dropped = new Map<number, Set<number>>();
    for (let s = 0; s < n; s++) {
      if (!drop[s]) continue;
      let set = dropped.get(owner[s]);
      if (!set) dropped.set(owner[s], (set = new Set()));
      set.add(idx[s]);
    }
    outLines = [];
    outLoops = [];
    const splitOpen = (pts: Pt[], cut: Set<number>) => {
      let cur: Pt[] = [pts[0]];
      for (let i = 0; i + 1 < pts.length; i++) {
        if (cut.has(i)) {
          if (cur.length >= 2) outLines.push(cur);
          cur = [pts[i + 1]];
        } else cur.push(pts[i + 1]);
      }
      if (cur.length >= 2) outLines.push(cur);
    };
    L.forEach((l, o) => {
      const cut = dropped.get(o);
      if (!cut) outLines.push(l);
      else splitOpen(l, cut);
    });
    C.forEach((l, o) => {
      const cut = dropped.get(L.length + o);
      if (!cut) {
        outLoops.push(l);
        return;
      }
      // open the loop after its first dropped segment, then split
      const first = Math.min(...cut);
      const m = l.length;
      const pts: Pt[] = [];
      const shifted = new Set<number>();
      for (let i = 0; i <= m; i++) pts.push(l[(first + 1 + i) % m]);
      for (const c of cut) shifted.add((c - first - 1 + m) % m);
      splitOpen(pts, shifted);
    });
  }
  return { lines: outLines.filter((l) => polylineLengthUm(l) >= minLengthUm), loops: outLoops };
}
