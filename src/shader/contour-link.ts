/**
 * Linking label crossings into polylines, marching-squares style. Each grid cell with crossings on
 * its edges connects them: two crossings make a segment; three (three labels meet) or four (four
 * labels, or an ambiguous saddle) meet at a junction point inside the cell, except a saddle whose
 * centre sample shows which pair of opposite corners is connected. The resulting graph is walked
 * into maximal polylines between junctions/ends, plus closed loops.
 */
import type { LabelGrid, LabelFn } from './label-grid.js';

/** A polyline in mm: flat [x0, y0, x1, y1, …]; closed loops repeat their first point at the end. */
export type MmPath = number[];

class Graph {
  xs: number[] = [];
  ys: number[] = [];
  adj: number[][] = [];

  add(x: number, y: number): number {
    this.xs.push(x);
    this.ys.push(y);
    this.adj.push([]);
    return this.xs.length - 1;
  }

  link(a: number, b: number): void {
    if (a === b) return;
    const la = this.adj[a];
    if (la.includes(b)) return;
    la.push(b);
    this.adj[b].push(a);
  }
}

/** Build the crossing graph of a sampled grid. `label` is used for the centre of saddle cells. */
export function linkCrossings(grid: LabelGrid, label: LabelFn): MmPath[] {
  const { nx, ny, h, x0, y0, labels, hx, vy } = grid;
  const g = new Graph();
  const hNode = new Int32Array(hx.length).fill(-1);
  const vNode = new Int32Array(vy.length).fill(-1);
  const hNodeOf = (i: number, j: number): number => {
    const k = j * (nx - 1) + i;
    let n = hNode[k];
    if (n < 0) n = hNode[k] = g.add(hx[k], y0 + j * h);
    return n;
  };
  const vNodeOf = (i: number, j: number): number => {
    const k = j * nx + i;
    let n = vNode[k];
    if (n < 0) n = vNode[k] = g.add(x0 + i * h, vy[k]);
    return n;
  };
  const ids = [0, 0, 0, 0];
  const on = [false, false, false, false];
  for (let j = 0; j + 1 < ny; j++) {
    for (let i = 0; i + 1 < nx; i++) {
      const c0 = labels[j * nx + i];
      const c1 = labels[j * nx + i + 1];
      const c2 = labels[(j + 1) * nx + i + 1];
      const c3 = labels[(j + 1) * nx + i];
      if (c0 !== c0 || c1 !== c1 || c2 !== c2 || c3 !== c3) continue;
      // Edges: 0 bottom (c0-c1), 1 right (c1-c2), 2 top (c3-c2), 3 left (c0-c3).
      on[0] = c0 !== c1;
      on[1] = c1 !== c2;
      on[2] = c3 !== c2;
      on[3] = c0 !== c3;
      const count = (on[0] ? 1 : 0) + (on[1] ? 1 : 0) + (on[2] ? 1 : 0) + (on[3] ? 1 : 0);
      if (count === 0) continue;
      if (on[0]) ids[0] = hNodeOf(i, j);
      if (on[1]) ids[1] = vNodeOf(i + 1, j);
      if (on[2]) ids[2] = hNodeOf(i, j + 1);
      if (on[3]) ids[3] = vNodeOf(i, j);
      if (count === 2) {
        let a = -1;
        for (let e = 0; e < 4; e++) {
          if (!on[e]) continue;
          if (a < 0) a = ids[e];
          else g.link(a, ids[e]);
        }
        continue;
      }
      if (count === 4) {
        const cx = x0 + (i + 0.5) * h;
        const cy = y0 + (j + 0.5) * h;
        const lc = label(cx, cy);
        const m0 = c0 === lc;
        const m1 = c1 === lc;
        const m2 = c2 === lc;
        const m3 = c3 === lc;
        if (m0 && m2 && !m1 && !m3) {
          // Corners 0 and 2 connect through the centre: corners 1 and 3 are cut off.
          g.link(ids[0], ids[1]);
          g.link(ids[2], ids[3]);
          continue;
        }
        if (m1 && m3 && !m0 && !m2) {
          g.link(ids[3], ids[0]);
          g.link(ids[1], ids[2]);
          continue;
        }
      }
      // Three or more labels meet: a junction at the centroid of the crossings.
      let sx = 0;
      let sy = 0;
      for (let e = 0; e < 4; e++) {
        if (!on[e]) continue;
        sx += g.xs[ids[e]];
        sy += g.ys[ids[e]];
      }
      const jn = g.add(sx / count, sy / count);
      for (let e = 0; e < 4; e++) if (on[e]) g.link(jn, ids[e]);
    }
  }
  return tracePolylines(g);
}

function tracePolylines(g: Graph): MmPath[] {
  const n = g.xs.length;
  const visited = new Uint8Array(n);
  const usedEdges = new Set<number>();
  const edgeKey = (a: number, b: number) => (a < b ? a * n + b : b * n + a);
  const out: MmPath[] = [];
  const walk = (start: number, next: number): MmPath => {
    const path: MmPath = [g.xs[start], g.ys[start]];
    let prev = start;
    let cur = next;
    for (;;) {
      path.push(g.xs[cur], g.ys[cur]);
      const adj = g.adj[cur];
      if (adj.length !== 2 || visited[cur]) break;
      visited[cur] = 1;
      const nxt = adj[0] === prev ? adj[1] : adj[0];
      prev = cur;
      cur = nxt;
      if (cur === start) {
        path.push(g.xs[cur], g.ys[cur]);
        break;
      }
    }
    return path;
  };
  // Paths that start at ends or junctions.
  for (let v = 0; v < n; v++) {
    const adj = g.adj[v];
    if (adj.length === 2 || adj.length === 0) continue;
    for (const w of adj) {
      if (g.adj[w].length === 2) {
        if (visited[w]) continue;
      } else {
        const k = edgeKey(v, w);
        if (usedEdges.has(k)) continue;
        usedEdges.add(k);
      }
      out.push(walk(v, w));
    }
  }
  // Closed loops: every node has degree 2.
  for (let v = 0; v < n; v++) {
    if (visited[v] || g.adj[v].length !== 2) continue;
    visited[v] = 1;
    const path: MmPath = [g.xs[v], g.ys[v]];
    let prev = v;
    let cur = g.adj[v][0];
    while (cur !== v) {
      path.push(g.xs[cur], g.ys[cur]);
      if (visited[cur] || g.adj[cur].length !== 2) break;
      visited[cur] = 1;
      const nxt = g.adj[cur][0] === prev ? g.adj[cur][1] : g.adj[cur][0];
      prev = cur;
      cur = nxt;
    }
    path.push(g.xs[v], g.ys[v]);
    out.push(path);
  }
  return out;
}
