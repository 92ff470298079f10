/**
 * Tolerant closing of open chains (holes in scans, non-manifold or flipped patches): each chain's
 * tail is joined to the nearest free chain head within a gap, closest pairs first (a chain's own
 * head included, which closes it on itself). A run of chains still open afterwards is closed on
 * itself when that encloses solid (counter-clockwise: a part with a wall missing) or when the gap
 * between its ends is small next to its length (a hole's wall with a hole in it). A run that would
 * close into a hole across a wide gap is left out: a stray flap of surface (the edge of a scan's open
 * base) would cut a cavity into the solid, where support would then be put inside the part.
 */

/** A run that closes into a hole is closed only when its ends are at most this share of its length apart. */
export const MAX_SELF_CLOSE_SHARE = 0.25;

/** Join open chains (slot sequences, oriented) into closed rings (slot sequences). */
export function closeOpenChains(
  open: readonly Int32Array[],
  slotX: Float64Array,
  slotY: Float64Array,
  maxGapUm: number,
): Int32Array[] {
  const n = open.length;
  if (n === 0) return [];
  const headX = new Float64Array(n),
    headY = new Float64Array(n),
    tailX = new Float64Array(n),
    tailY = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const c = open[i];
    headX[i] = slotX[c[0]];
    headY[i] = slotY[c[0]];
    tailX[i] = slotX[c[c.length - 1]];
    tailY[i] = slotY[c[c.length - 1]];
  }
  // Candidate (tail i → head j) pairs within the gap.
  const cand: number[] = []; // triples: distance², i, j
  const gap2 = maxGapUm * maxGapUm;
  const consider = (i: number, j: number): void => {
    const dx = headX[j] - tailX[i],
      dy = headY[j] - tailY[i];
    const d2 = dx * dx + dy * dy;
    if (d2 <= gap2) cand.push(d2, i, j);
  };
  if (n <= 256 || !(maxGapUm > 0)) {
    for (let i = 0; i < n; i++) for (let j = 0; j < n; j++) consider(i, j);
  } else {
    // Grid of heads with cells one gap wide: only the 3×3 neighbourhood can be within the gap.
    const cell = maxGapUm;
    const grid = new Map<string, number[]>();
    for (let j = 0; j < n; j++) {
      const key = `${Math.floor(headX[j] / cell)},${Math.floor(headY[j] / cell)}`;
      const list = grid.get(key);
      if (list) list.push(j);
      else grid.set(key, [j]);
    }
    for (let i = 0; i < n; i++) {
      const cx = Math.floor(tailX[i] / cell),
        cy = Math.floor(tailY[i] / cell);
      for (let dx = -1; dx <= 1; dx++) {
        for (let dy = -1; dy <= 1; dy++) {
          const list = grid.get(`${cx + dx},${cy + dy}`);
          if (list) for (const j of list) consider(i, j);
        }
      }
    }
  }
  const pairs = new Int32Array(cand.length / 3);
  for (let k = 0; k < pairs.length; k++) pairs[k] = k;
  pairs.sort((a, b) => cand[3 * a] - cand[3 * b]);
  const next = new Int32Array(n).fill(-1);
  const prev = new Int32Array(n).fill(-1);
  for (let k = 0; k < pairs.length; k++) {
    const i = cand[3 * pairs[k] + 1],
      j = cand[3 * pairs[k] + 2];
    if (next[i] === -1 && prev[j] === -1) {
      next[i] = j;
      prev[j] = i;
    }
  }
  // Walk the links: cycles become rings; paths (from a chain nobody leads into) are closed on themselves
  // unless that makes a hole across a wide gap.
  const done = new Uint8Array(n);
  const rings: Int32Array[] = [];
  const emit = (start: number): void => {
    const parts: Int32Array[] = [];
    let count = 0;
    let c = start;
    for (; c !== -1 && !done[c]; c = next[c]) {
      done[c] = 1;
      parts.push(open[c]);
      count += open[c].length;
    }
    const ring = new Int32Array(count);
    let o = 0;
    for (const p of parts) {
      ring.set(p, o);
      o += p.length;
    }
    // a cycle came back to its start; a path ends at a chain nobody continues
    if (c !== start && !selfClosable(ring, slotX, slotY)) return;
    rings.push(ring);
  };
  for (let i = 0; i < n; i++) if (prev[i] === -1 && !done[i]) emit(i);
  for (let i = 0; i < n; i++) if (!done[i]) emit(i);
  return rings;
}

/** Whether an open run closed on itself is kept: it encloses solid, or its ends are close next to its length. */
function selfClosable(ring: Int32Array, slotX: Float64Array, slotY: Float64Array): boolean {
  let length = 0,
    twiceArea = 0;
  for (let k = 0; k < ring.length; k++) {
    const p = ring[k],
      q = ring[(k + 1) % ring.length];
    twiceArea += slotX[p] * slotY[q] - slotX[q] * slotY[p];
    if (k + 1 < ring.length) length += Math.hypot(slotX[q] - slotX[p], slotY[q] - slotY[p]);
  }
  if (twiceArea > 0) return true;
  const a = ring[0],
    b = ring[ring.length - 1];
  return Math.hypot(slotX[a] - slotX[b], slotY[a] - slotY[b]) <= MAX_SELF_CLOSE_SHARE * length;
}
