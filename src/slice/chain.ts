/**
 * Chaining one layer's segments into loops through the mesh topology: two segments connect when
 * they share a slot (an edge crossing), found with typed-array buckets keyed on slot ids — linear
 * time, no point matching.
 *
 * At each slot, segments arriving there are paired with segments leaving there. Left-overs (a
 * flipped triangle makes two arrivals or two departures meet) are paired with each other, and a
 * slot with one segment (an open edge) ends an open chain. Pairing at non-manifold edges is
 * arbitrary, which is harmless: the winding field of directed segments does not depend on how
 * they are grouped into loops.
 *
 * Each chain is oriented by a length-weighted vote of its segments' own directions, so a few
 * flipped triangles do not reverse a loop.
 */
import type { LayerSegments } from './intersect.js';
import { VOTE_TIE_UM } from '../geometry/tolerances.js';

/** Loops of one layer as slot sequences: closed rings (last slot not repeated) and open chains. */
export interface Chains {
  closed: Int32Array[];
  open: Int32Array[];
}

export function chainSegments(seg: LayerSegments): Chains {
  const { segCount: n, segStart, segEnd, slotCount, slotX, slotY } = seg;
  const closed: Int32Array[] = [];
  const open: Int32Array[] = [];
  if (n === 0) return { closed, open };

  // Endpoint 2s = start of segment s, 2s+1 = its end. Bucket endpoints by slot.
  const slotFirst = new Int32Array(slotCount + 1);
  for (let s = 0; s < n; s++) {
    slotFirst[segStart[s] + 1]++;
    slotFirst[segEnd[s] + 1]++;
  }
  for (let i = 0; i < slotCount; i++) slotFirst[i + 1] += slotFirst[i];
  const byslot = new Int32Array(2 * n);
  {
    const fill = slotFirst.slice(0, slotCount);
    for (let s = 0; s < n; s++) {
      byslot[fill[segStart[s]]++] = 2 * s;
      byslot[fill[segEnd[s]]++] = 2 * s + 1;
    }
  }

  const partner = new Int32Array(2 * n).fill(-1);
  const arrivals: number[] = [];
  const departures: number[] = [];
  for (let slot = 0; slot < slotCount; slot++) {
    const a = slotFirst[slot],
      b = slotFirst[slot + 1];
    if (b - a === 2) {
      partner[byslot[a]] = byslot[a + 1];
      partner[byslot[a + 1]] = byslot[a];
      continue;
    }
    if (b - a < 2) continue;
    arrivals.length = 0;
    departures.length = 0;
    for (let i = a; i < b; i++) (byslot[i] & 1 ? arrivals : departures).push(byslot[i]);
    const m = Math.min(arrivals.length, departures.length);
    for (let i = 0; i < m; i++) {
      partner[arrivals[i]] = departures[i];
      partner[departures[i]] = arrivals[i];
    }
    const rest = arrivals.length > m ? arrivals : departures;
    for (let i = m; i + 1 < rest.length; i += 2) {
      partner[rest[i]] = rest[i + 1];
      partner[rest[i + 1]] = rest[i];
    }
  }

  const slotOf = (ep: number): number => (ep & 1 ? segEnd[ep >> 1] : segStart[ep >> 1]);
  const segLength = (s: number): number => {
    const dx = slotX[segEnd[s]] - slotX[segStart[s]],
      dy = slotY[segEnd[s]] - slotY[segStart[s]];
    return Math.sqrt(dx * dx + dy * dy);
  };

  const visited = new Uint8Array(n);
  const path: number[] = [];
  const back: number[] = [];
  for (let s0 = 0; s0 < n; s0++) {
    if (visited[s0]) continue;
    visited[s0] = 1;
    path.length = 0;
    path.push(segStart[s0], segEnd[s0]);
    let vote = segLength(s0) + VOTE_TIE_UM;
    let isClosed = false;
    // Forward from the end of s0.
    let ep = 2 * s0 + 1;
    for (;;) {
      const q = partner[ep];
      if (q < 0) break;
      const s = q >> 1;
      if (s === s0) {
        isClosed = true;
        break;
      }
      visited[s] = 1;
      const exit = q ^ 1;
      path.push(slotOf(exit));
      vote += q & 1 ? -segLength(s) : segLength(s);
      ep = exit;
    }
    let chain: Int32Array;
    if (isClosed) {
      path.pop(); // back at the first slot
      chain = Int32Array.from(path);
    } else {
      // Backward from the start of s0.
      back.length = 0;
      ep = 2 * s0;
      for (;;) {
        const q = partner[ep];
        if (q < 0) break;
        const s = q >> 1;
        visited[s] = 1;
        const exit = q ^ 1;
        back.push(slotOf(exit));
        vote += q & 1 ? segLength(s) : -segLength(s);
        ep = exit;
      }
      chain = new Int32Array(back.length + path.length);
      for (let i = 0; i < back.length; i++) chain[i] = back[back.length - 1 - i];
      chain.set(path, back.length);
    }
    if (vote < 0) chain.reverse();
    (isClosed ? closed : open).push(chain);
  }
  return { closed, open };
}
