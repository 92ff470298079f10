/**
 * Closing the gaps of an open mesh's section. Segments are chained end-to-start (points matched at 0.1 µm, or in a
 * neighbouring 0.1 µm cell). Chains that do not close on themselves are then joined end to start, nearest pairs
 * first, where the gap is at most MAX_JOIN_MM (the added segments are marked synthetic). A run of chains that
 * still does not close is closed on itself when its gap is small next to its length (a wall with a hole), and
 * dropped otherwise (a stray flap of surface, as slicers drop them). Afterwards every chain is a loop, so a
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
  /** Open runs of surface that could not be closed and were left out. */
  chainsDropped: number;
}

const KEYS_PER_MM = 1e4;
const KEY_OFFSET = 2 ** 25;
const KEY_SPAN = 2 ** 26;
/** Joins shorter than this (mm) are not counted as gaps. */
const GAP_REPORT_MM = 1e-3;
/** Above this many open chains, chains are only closed on themselves (keeps the cost linear). */
const MAX_MATCHED_CHAINS = 4000;
/** Chain ends farther apart than this (mm) are not joined. */
const MAX_JOIN_MM = 2;
/** An open run is closed on itself when its gap is at most this fraction of its length, else dropped. */
const MAX_SELF_CLOSE_RATIO = 0.25;

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
  if (heads.length === 0) return { ...seg, gapsClosed: 0, chainsDropped: 0 };

  const k = heads.length;
  const endX = (c: number) => seg.x1[tails[c]!]!;
  const endY = (c: number) => seg.y1[tails[c]!]!;
  const startX = (c: number) => seg.x0[heads[c]!]!;
  const startY = (c: number) => seg.y0[heads[c]!]!;
  const joinTo = new Int32Array(k).fill(-1);
  const joinedFrom = new Int32Array(k).fill(-1);
  const join = (c: number, h: number) => {
    joinTo[c] = h;
    joinedFrom[h] = c;
  };
  if (k <= MAX_MATCHED_CHAINS) {
    const pairs: number[][] = [];
    for (let c = 0; c < k; c++) {
      for (let h = 0; h < k; h++) {
        const d = Math.hypot(startX(h) - endX(c), startY(h) - endY(c));
        if (d <= MAX_JOIN_MM) pairs.push([d, c, h]);
      }
    }
    pairs.sort((a, b) => a[0]! - b[0]!);
    for (const [, c, h] of pairs) if (joinTo[c!] === -1 && joinedFrom[h!] === -1) join(c!, h!);
  }
  // Runs of chains that are still open: from a chain nothing joins into, along the joins, to one that joins on to
  // nothing. Close each on itself or drop it.
  const dropped = new Uint8Array(k);
  let chainsDropped = 0;
  for (let c = 0; c < k; c++) {
    if (joinedFrom[c] !== -1) continue;
    let last = c;
    let length = 0;
    for (let r = c; r !== -1; r = joinTo[r]!) {
      last = r;
      length += chainLength(seg, heads[r]!, succ);
      if (joinTo[r] !== -1) length += Math.hypot(startX(joinTo[r]!) - endX(r), startY(joinTo[r]!) - endY(r));
    }
    const gap = Math.hypot(startX(c) - endX(last), startY(c) - endY(last));
    if (gap <= MAX_SELF_CLOSE_RATIO * length) {
      join(last, c);
    } else {
      chainsDropped++;
      for (let r = c; r !== -1; r = joinTo[r]!) dropped[r] = 1;
    }
  }

  const droppedSegment = new Uint8Array(n);
  for (let c = 0; c < k; c++) {
    if (dropped[c] === 0) continue;
    for (let i = heads[c]!, guard = 0; i !== -1 && guard <= n; i = succ[i]!, guard++) droppedSegment[i] = 1;
  }
  let total = 0;
  for (let i = 0; i < n; i++) if (droppedSegment[i] === 0) total++;
  for (let c = 0; c < k; c++) if (dropped[c] === 0) total++;
  const out: SectionSegments = {
    count: total,
    x0: new Float64Array(total),
    y0: new Float64Array(total),
    x1: new Float64Array(total),
    y1: new Float64Array(total),
    synthetic: new Uint8Array(total),
    gapsClosed: 0,
    chainsDropped,
  };
  let w = 0;
  for (let i = 0; i < n; i++) {
    if (droppedSegment[i] !== 0) continue;
    out.x0[w] = seg.x0[i]!;
    out.y0[w] = seg.y0[i]!;
    out.x1[w] = seg.x1[i]!;
    out.y1[w] = seg.y1[i]!;
    out.synthetic[w] = seg.synthetic[i]!;
    w++;
  }
  for (let c = 0; c < k; c++) {
    if (dropped[c] !== 0) continue;
    const h = joinTo[c]!;
    out.x0[w] = endX(c);
    out.y0[w] = endY(c);
    out.x1[w] = startX(h);
    out.y1[w] = startY(h);
    out.synthetic[w] = 1;
    if (Math.hypot(out.x1[w]! - out.x0[w]!, out.y1[w]! - out.y0[w]!) > GAP_REPORT_MM) out.gapsClosed++;
    w++;
  }
  return out;
}

/** Length of the chain starting at segment `head`. */
function chainLength(seg: SectionSegments, head: number, succ: Int32Array): number {
  let sum = 0;
  for (let i = head, guard = 0; i !== -1 && guard <= seg.count; i = succ[i]!, guard++) {
    sum += Math.hypot(seg.x1[i]! - seg.x0[i]!, seg.y1[i]! - seg.y0[i]!);
  }
  return sum;
}
