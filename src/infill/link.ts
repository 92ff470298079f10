/**
 * Linking: join the end of one infill piece to the start of another along the region boundary, so the
 * nozzle keeps extruding instead of travelling (the zig-zag of rectilinear infill). Only ends that are
 * neighbours along a boundary ring are candidates, so connectors never overlap each other or pass another
 * line's end; they are taken shortest first, only when no longer than `maxGap`, never closing a loop.
 */
import type { Pt } from '../geometry/types.js';
import { type Anchor, type RegionGeom, boundaryPath } from './region-index.js';
import { type Piece, pushPt, rnd } from './piece.js';

export interface LinkResult {
  lines: Pt[][];
  /** Total length of the boundary connectors added, µm. */
  connectorLength: number;
}

interface Candidate {
  gap: number;
  ring: number;
  k: number;
  a: number;
  b: number;
  anchorA: Anchor;
  anchorB: Anchor;
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
    const perRing: Array<Array<{ node: number; pos: number }>> = geom.rings.map(() => []);
    for (let i = 0; i < P; i++) {
      const p = pieces[i];
      if (p.a0) perRing[p.a0.ring].push({ node: 2 * i, pos: p.a0.pos });
      if (p.a1) perRing[p.a1.ring].push({ node: 2 * i + 1, pos: p.a1.pos });
    }
    const cands: Candidate[] = [];
    for (let r = 0; r < perRing.length; r++) {
      const list = perRing[r];
      const m = list.length;
      if (m < 2) continue;
      list.sort((p, q) => p.pos - q.pos || p.node - q.node);
      const L = geom.rings[r].length;
      for (let k = 0; k < m; k++) {
        const A = list[k], B = list[(k + 1) % m];
        const gap = k + 1 < m ? B.pos - A.pos : B.pos + L - A.pos;
        if (gap > maxGap) continue;
        cands.push({ gap, ring: r, k, a: A.node, b: B.node, anchorA: { ring: r, pos: A.pos }, anchorB: { ring: r, pos: B.pos } });
      }
    }
    cands.sort((p, q) => p.gap - q.gap || p.ring - q.ring || p.k - q.k);
    const uf = new Int32Array(P);
    for (let i = 0; i < P; i++) uf[i] = i;
    for (const c of cands) {
      if (partner[c.a] !== -1 || partner[c.b] !== -1) continue;
      const ra = find(uf, c.a >> 1), rb = find(uf, c.b >> 1);
      if (ra === rb) continue;
      uf[ra] = rb;
      partner[c.a] = c.b;
      partner[c.b] = c.a;
      const raw = boundaryPath(geom, c.anchorA, c.anchorB);
      const path: Pt[] = [];
      for (const q of raw) pushPt(path, rnd(q.x, q.y));
      paths[c.a] = path;
      paths[c.b] = path.slice().reverse();
      connectorLength += c.gap;
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
