/**
 * Closing the gaps of an open mesh's section. Segments are chained end-to-start (points matched at 0.1 µm, or in a
 * neighbouring 0.1 µm cell); each
 * chain that does not close on itself is then joined from its last point to the nearest free chain start (its
 * own start included), greedily. The added segments are marked synthetic. Afterwards every chain is a loop, so a
 * winding-number fill cannot leak along a scanline through a hole in the mesh.
 */

/** Oriented section segments (solid on the left), coordinates in mm. */
export interface SectionSegments {
  count: number;
  x0: Float64Array;
  y0: Float64Array;
  x1: Float64Array;
  y1: Float64Array;
  /** 1 for segments added to close a gap, 0 for segments cut from triangles. */
  synthetic: Uint8Array;
  /**
   * Joins longer than GAP_REPORT_MM made to close open chains (0 for a watertight mesh; shorter joins only mend
   * rounding at T-junctions and non-manifold edges).
   */
  gapsClosed: number;
}

const KEYS_PER_MM = 1e4;
const KEY_OFFSET = 2 ** 25;
const KEY_SPAN = 2 ** 26;
/** Joins shorter than this (mm) are not counted as gaps. */
const GAP_REPORT_MM = 1e-3;
/** Above this many open chains, each open chain is closed on itself instead of matched (keeps the cost linear). */
const MAX_MATCHED_CHAINS = 4000;

function pointKey(x: number, y: number): number {
  return (Math.round(x * KEYS_PER_MM) + KEY_OFFSET) * KEY_SPAN + (Math.round(y * KEYS_PER_MM) + KEY_OFFSET);
}

export function closeGaps(seg: SectionSegments): SectionSegments {
  const n = seg.count;
  if (n === 0) return seg;
  // Segments by start point, as linked lists sharing one `nextSameStart` array.
  const headByKey = new Map<number, number>();
  const nextSameStart = new Int32Array(n).fill(-1);
  for (let i = n - 1; i >= 0; i--) {
    const key = pointKey(seg.x0[i]!, seg.y0[i]!);
    const head = headByKey.get(key);
    if (head !== undefined) nextSameStart[i] = head;
    headByKey.set(key, i);
  }
  const succ = new Int32Array(n).fill(-1);
  const hasPred = new Uint8Array(n);
  const link = (i: number, key: number): boolean => {
    let j = headByKey.get(key);
    while (j !== undefined && j >= 0) {
      if (j !== i && hasPred[j] === 0) {
        succ[i] = j;
        hasPred[j] = 1;
        return true;
      }
      j = nextSameStart[j]!;
    }
    return false;
  };
  for (let i = 0; i < n; i++) link(i, pointKey(seg.x1[i]!, seg.y1[i]!));
  // Points computed on different but collinear edges (T-junctions) may round to a neighbouring key.
  for (let i = 0; i < n; i++) {
    if (succ[i]! >= 0) continue;
    const key = pointKey(seg.x1[i]!, seg.y1[i]!);
    for (let dx = -1; dx <= 1 && succ[i]! < 0; dx++) {
      for (let dy = -1; dy <= 1; dy++) if ((dx !== 0 || dy !== 0) && link(i, key + dx * KEY_SPAN + dy)) break;
    }
  }
  // Open chains run from a segment without predecessor to one without successor.
  const heads: number[] = [];
  const tails: number[] = [];
  for (let i = 0; i < n; i++) {
    if (hasPred[i] !== 0) continue;
    let t = i;
    let guard = 0;
    while (succ[t]! >= 0 && guard++ < n) t = succ[t]!;
    heads.push(i);
    tails.push(t);
  }
  if (heads.length === 0) return { ...seg, gapsClosed: 0 };

  const k = heads.length;
  const joinTo = new Int32Array(k);
  if (k > MAX_MATCHED_CHAINS) {
    for (let c = 0; c < k; c++) joinTo[c] = c;
  } else {
    const used = new Uint8Array(k);
    for (let c = 0; c < k; c++) {
      const tx = seg.x1[tails[c]!]!;
      const ty = seg.y1[tails[c]!]!;
      let best = -1;
      let bestD = Infinity;
      for (let h = 0; h < k; h++) {
        if (used[h] !== 0) continue;
        const d = Math.hypot(seg.x0[heads[h]!]! - tx, seg.y0[heads[h]!]! - ty);
        if (d < bestD) {
          bestD = d;
          best = h;
        }
      }
      used[best] = 1;
      joinTo[c] = best;
    }
  }
  const total = n + k;
  const out: SectionSegments = {
    count: total,
    x0: new Float64Array(total),
    y0: new Float64Array(total),
    x1: new Float64Array(total),
    y1: new Float64Array(total),
    synthetic: new Uint8Array(total),
    gapsClosed: 0,
  };
  out.x0.set(seg.x0.subarray(0, n));
  out.y0.set(seg.y0.subarray(0, n));
  out.x1.set(seg.x1.subarray(0, n));
  out.y1.set(seg.y1.subarray(0, n));
  out.synthetic.set(seg.synthetic.subarray(0, n));
  let w = n;
  for (let c = 0; c < k; c++) {
    const t = tails[c]!;
    const h = heads[joinTo[c]!]!;
    out.x0[w] = seg.x1[t]!;
    out.y0[w] = seg.y1[t]!;
    out.x1[w] = seg.x0[h]!;
    out.y1[w] = seg.y0[h]!;
    out.synthetic[w] = 1;
    if (Math.hypot(out.x1[w]! - out.x0[w]!, out.y1[w]! - out.y0[w]!) > GAP_REPORT_MM) out.gapsClosed++;
    w++;
  }
  return out;
}
