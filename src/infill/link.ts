/**
 * Linking: join the end of one infill piece to the start of another along the region boundary, so the
 * nozzle keeps extruding instead of travelling (the zig-zag of rectilinear infill). Only ends that are
 * neighbours along a boundary ring are candidates, so connectors never overlap each other or pass another
 * line's end, and none is longer than `maxGap`. Chains are grown like a zig-zag is drawn: from a piece at
 * the edge of the pattern (an end with the fewest candidates), across it, to the nearer free neighbour of
 * its far end, across that piece, and so on; then from its first end the other way. Union-find keeps
 * chains from closing into loops.
 */
import type { Pt } from '../geometry/types.js';
import { type Anchor, type RegionGeom, boundaryPath } from './region-index.js';
import { type Piece, pushPt, rnd } from './piece.js';

export interface LinkResult {
  lines: Pt[][];
  /** Total length of the boundary connectors added, µm. */
  connectorLength: number;
}

function find(parent: Int32Array, i: number): number {
  while (parent[i] !== i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/** Join pieces along the boundary where the gap between neighbouring ends is at most maxGap µm. */
export function linkPieces(geom: RegionGeom, pieces: readonly Piece[], maxGap: number): LinkResult {
  const P = pieces.length;
  const partner = new Int32Array(2 * P).fill(-1);
  const paths: (Pt[] | null)[] = new Array(2 * P).fill(null);
  let connectorLength = 0;
  if (maxGap > 0 && P > 1) {
    // anchored ends, sorted along each ring; for each node its ring and rank
    const perRing: Array<Array<{ node: number; pos: number }>> = geom.rings.map(() => []);
    const anchorOf = (node: number): Anchor | null => ((node & 1) === 0 ? pieces[node >> 1].a0 : pieces[node >> 1].a1);
    for (let i = 0; i < P; i++) {
      const p = pieces[i];
      if (p.a0) perRing[p.a0.ring].push({ node: 2 * i, pos: p.a0.pos });
      if (p.a1) perRing[p.a1.ring].push({ node: 2 * i + 1, pos: p.a1.pos });
    }
    const rank = new Int32Array(2 * P).fill(-1);
    for (const list of perRing) {
      list.sort((p, q) => p.pos - q.pos || p.node - q.node);
      list.forEach((e, k) => (rank[e.node] = k));
    }
    /** The two boundary neighbours of a node: [node, gap, forward?]. */
    const neighbours = (x: number): Array<[number, number, boolean]> => {
      const a = anchorOf(x);
      if (!a || rank[x] < 0) return [];
      const list = perRing[a.ring];
      const m = list.length;
      if (m < 2) return [];
      const L = geom.rings[a.ring].length;
      const k = rank[x];
      const nx = list[(k + 1) % m],
        pv = list[(k - 1 + m) % m];
      const gNext = k + 1 < m ? nx.pos - a.pos : nx.pos + L - a.pos;
      const gPrev = k > 0 ? a.pos - pv.pos : a.pos + L - pv.pos;
      return [
        [nx.node, gNext, true],
        [pv.node, gPrev, false],
      ];
    };
    const uf = new Int32Array(P);
    for (let i = 0; i < P; i++) uf[i] = i;
    const options = (x: number): Array<[number, number, boolean]> =>
      neighbours(x).filter(
        ([y, gap]) => gap <= maxGap && y >> 1 !== x >> 1 && partner[y] === -1 && find(uf, y >> 1) !== find(uf, x >> 1),
      );
    const link = (x: number, y: number, gap: number, forward: boolean) => {
      const ax = anchorOf(x) as Anchor,
        ay = anchorOf(y) as Anchor;
      const raw = forward ? boundaryPath(geom, ax, ay) : boundaryPath(geom, ay, ax).reverse();
      const path: Pt[] = [];
      for (const q of raw) pushPt(path, rnd(q.x, q.y));
      partner[x] = y;
      partner[y] = x;
      paths[x] = path;
      paths[y] = path.slice().reverse();
      uf[find(uf, x >> 1)] = find(uf, y >> 1);
      connectorLength += gap;
    };
    /** From free end x, keep linking to the nearer free neighbour and crossing that piece. */
    const extend = (x: number) => {
      for (;;) {
        if (partner[x] !== -1) return;
        const opts = options(x);
        if (opts.length === 0) return;
        const [y, gap, forward] = opts.length === 2 && opts[1][1] < opts[0][1] ? opts[1] : opts[0];
        link(x, y, gap, forward);
        x = y ^ 1;
      }
    };
    const degree = (x: number) => neighbours(x).filter(([y, gap]) => gap <= maxGap && y >> 1 !== x >> 1).length;
    const starts: Array<{ piece: number; end: number; deg: number }> = [];
    for (let i = 0; i < P; i++) {
      const d0 = degree(2 * i),
        d1 = degree(2 * i + 1);
      starts.push(d0 <= d1 ? { piece: i, end: 2 * i, deg: d0 } : { piece: i, end: 2 * i + 1, deg: d1 });
    }
    starts.sort((a, b) => a.deg - b.deg || a.piece - b.piece);
    for (const st of starts) {
      if (partner[2 * st.piece] !== -1 || partner[2 * st.piece + 1] !== -1) continue;
      extend(st.end ^ 1);
      extend(st.end);
    }
  }
  // walk the chains from their free ends
  const visited = new Uint8Array(P);
  const lines: Pt[][] = [];
  const walk = (startNode: number) => {
    const chain: Pt[] = [];
    let node = startNode;
    for (;;) {
      const i = node >> 1;
      visited[i] = 1;
      const pts = pieces[i].pts;
      if ((node & 1) === 0) for (let k = 0; k < pts.length; k++) pushPt(chain, pts[k]);
      else for (let k = pts.length - 1; k >= 0; k--) pushPt(chain, pts[k]);
      const exit = node ^ 1;
      const next = partner[exit];
      if (next === -1) break;
      const path = paths[exit] as Pt[];
      for (let k = 1; k < path.length; k++) pushPt(chain, path[k]);
      node = next;
    }
    if (chain.length >= 2) lines.push(chain);
  };
  for (let i = 0; i < P; i++) {
    if (visited[i]) continue;
    if (partner[2 * i] === -1) walk(2 * i);
    else if (partner[2 * i + 1] === -1) walk(2 * i + 1);
  }
  for (let i = 0; i < P; i++) if (!visited[i]) walk(2 * i); // unreachable without cycles; kept for safety
  return { lines, connectorLength };
}
