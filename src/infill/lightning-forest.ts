/**
 * The tree machinery of lightning infill, top layer first. A forest is a set of trees of 2D nodes; every
 * root lies on the region boundary (the walls carry it). Going one layer down:
 *  1. prune: every branch tip retracts by h·tan(overhang angle), so the layer above overhangs this one by
 *     at most that angle; trees shrink towards their roots and vanish where nothing above needs them;
 *  2. straighten: every node with one child moves (at most h·tan(straightening angle)) towards the line
 *     between its parent and its child, so crooked branches become straight lower down;
 *  3. fit: nodes outside this layer's region go, branches crossing the boundary are cut, and each loose
 *     subtree or root is grounded again on the nearest boundary point (snapped when the wall only moved a
 *     little, otherwise joined to it by a new segment, which stays inside by construction);
 *  4. grow: this layer's newly needed support (the top skin directly above) is sampled on a grid of half
 *     the support radius anchored at the bed origin; samples within the radius of the walls are held by
 *     the walls. The rest are taken farthest from the walls first, and each one farther than the radius
 *     from the forest is joined to whichever is nearer, the forest or the boundary (a new tree): the first
 *     ones make trunks, later ones branch off them. Every point of the skin is then within 1.35 radii of
 *     a branch or the wall.
 * All plain arrays; one forest value per layer is handed to the next.
 */
import { hypot, type ExPolygon, type Polyline, type Pt } from '../geometry/types.js';
import { type Hit, type RegionIndex, nearestBoundary, pointInside, segmentCrosses } from './region-index.js';
import { closestOnSegment, ringsOf, rowCrossings } from './geom-util.js';

export interface Forest {
  xs: number[];
  ys: number[];
  /** Parent node, −1 for a root. */
  par: number[];
}

export interface ForestParams {
  /** Support radius: every point of a skin must lie within it of a branch, µm. */
  radius: number;
  /** How far tips retract per layer, µm (h·tan overhang angle). */
  pruneDist: number;
  /** How far a node may move per layer when straightening, µm. */
  straightenDist: number;
  /** Sampling grid anchor, µm (the bed origin: the same grid for every layer and object). */
  origin: Pt;
}

/** Boundary tolerance: a node this close to the boundary counts as on it, µm. */
const ON_BOUNDARY_UM = 5;
/** Search limit for grounding on the boundary, µm. */
const FAR_UM = 1e9;

export function emptyForest(): Forest {
  return { xs: [], ys: [], par: [] };
}

function copyForest(f: Forest): Forest {
  return { xs: f.xs.slice(), ys: f.ys.slice(), par: f.par.slice() };
}

function childCounts(f: Forest): Int32Array {
  const k = new Int32Array(f.par.length);
  for (const p of f.par) if (p >= 0) k[p]++;
  return k;
}

/** Remove dead nodes, remapping parents (a live node whose parent died becomes a root). */
function compact(f: Forest, dead: Uint8Array): Forest {
  const map = new Int32Array(f.par.length).fill(-1);
  const out = emptyForest();
  for (let v = 0; v < f.par.length; v++) {
    if (dead[v]) continue;
    map[v] = out.xs.length;
    out.xs.push(f.xs[v]);
    out.ys.push(f.ys[v]);
    out.par.push(f.par[v]);
  }
  for (let v = 0; v < out.par.length; v++) {
    const p = out.par[v];
    out.par[v] = p >= 0 ? map[p] : -1;
  }
  return out;
}

/** Tips retract by `dist` along their branches; bare roots disappear. */
export function prune(f: Forest, dist: number): Forest {
  const n = f.par.length;
  const kids = childCounts(f);
  const dead = new Uint8Array(n);
  const done = new Uint8Array(n);
  for (let leaf = 0; leaf < n; leaf++) {
    if (kids[leaf] !== 0 || done[leaf]) continue;
    let v = leaf;
    let rem = dist;
    for (;;) {
      done[v] = 1;
      const p = f.par[v];
      if (p < 0) {
        dead[v] = 1;
        break;
      }
      const dx = f.xs[p] - f.xs[v],
        dy = f.ys[p] - f.ys[v];
      const len = hypot(dx, dy);
      if (len <= rem) {
        dead[v] = 1;
        rem -= len;
        if (--kids[p] === 0) {
          v = p;
          continue;
        }
        break;
      }
      const t = rem / len;
      f.xs[v] += dx * t;
      f.ys[v] += dy * t;
      break;
    }
  }
  return compact(f, dead);
}

/** Nodes with one child move towards the segment parent–child by at most `dist`. */
export function straighten(f: Forest, dist: number): void {
  const n = f.par.length;
  const kids = childCounts(f);
  const only = new Int32Array(n).fill(-1);
  for (let v = 0; v < n; v++) if (f.par[v] >= 0 && kids[f.par[v]] === 1) only[f.par[v]] = v;
  for (let v = 0; v < n; v++) {
    const p = f.par[v],
      c = only[v];
    if (p < 0 || c < 0) continue;
    const ax = f.xs[p],
      ay = f.ys[p],
      ux = f.xs[c] - ax,
      uy = f.ys[c] - ay;
    const l2 = ux * ux + uy * uy;
    if (l2 === 0) continue;
    const t = Math.max(0, Math.min(1, ((f.xs[v] - ax) * ux + (f.ys[v] - ay) * uy) / l2));
    const tx = ax + t * ux - f.xs[v],
      ty = ay + t * uy - f.ys[v];
    const d = hypot(tx, ty);
    if (d === 0) continue;
    const s = Math.min(1, dist / d);
    f.xs[v] += tx * s;
    f.ys[v] += ty * s;
  }
}

/** Keep what lies inside the region; cut branches at the boundary; ground loose roots on the boundary. */
export function fitToRegion(f: Forest, ix: RegionIndex, snapDist: number): Forest {
  const n = f.par.length;
  const dead = new Uint8Array(n);
  const scratch: Hit[] = [];
  for (let v = 0; v < n; v++) {
    const x = f.xs[v],
      y = f.ys[v];
    if (!pointInside(ix, x, y) && !nearestBoundary(ix, x, y, ON_BOUNDARY_UM)) dead[v] = 1;
  }
  for (let v = 0; v < n; v++) {
    const p = f.par[v];
    if (dead[v] || p < 0) continue;
    if (dead[p] || segmentCrosses(ix, f.xs[v], f.ys[v], f.xs[p], f.ys[p], ON_BOUNDARY_UM, scratch)) f.par[v] = -1;
  }
  const g = compact(f, dead);
  // ground every root
  const m = g.par.length;
  for (let v = 0; v < m; v++) {
    if (g.par[v] !== -1) continue;
    const nb = nearestBoundary(ix, g.xs[v], g.ys[v], FAR_UM);
    if (!nb) continue;
    if (nb.dist <= snapDist) {
      g.xs[v] = nb.x;
      g.ys[v] = nb.y;
    } else {
      const r = g.xs.length;
      g.xs.push(nb.x);
      g.ys.push(nb.y);
      g.par.push(-1);
      g.par[v] = r;
    }
  }
  return g;
}

/** Spatial hash of forest edges (child → parent), for distance queries. Edges are only ever added. */
class EdgeGrid {
  private readonly cells = new Map<number, number[]>();
  constructor(
    private readonly f: Forest,
    private readonly cell: number,
  ) {
    for (let v = 0; v < f.par.length; v++) if (f.par[v] >= 0) this.add(v);
  }
  private key(cx: number, cy: number): number {
    return (cx + 1048576) * 2097152 + (cy + 1048576);
  }
  add(v: number): void {
    const f = this.f,
      p = f.par[v];
    const x0 = Math.min(f.xs[v], f.xs[p]),
      x1 = Math.max(f.xs[v], f.xs[p]);
    const y0 = Math.min(f.ys[v], f.ys[p]),
      y1 = Math.max(f.ys[v], f.ys[p]);
    for (let cx = Math.floor(x0 / this.cell); cx <= Math.floor(x1 / this.cell); cx++) {
      for (let cy = Math.floor(y0 / this.cell); cy <= Math.floor(y1 / this.cell); cy++) {
        const k = this.key(cx, cy);
        const list = this.cells.get(k);
        if (list) list.push(v);
        else this.cells.set(k, [v]);
      }
    }
  }
  /** Nearest point on any edge within maxDist: the edge's child node, parameter from child to parent, point. */
  nearest(x: number, y: number, maxDist: number): { v: number; t: number; x: number; y: number; d: number } | null {
    const f = this.f;
    let best: { v: number; t: number; x: number; y: number; d: number } | null = null;
    let bestD = maxDist;
    const r = Math.ceil(maxDist / this.cell);
    const cx0 = Math.floor(x / this.cell),
      cy0 = Math.floor(y / this.cell);
    for (let cx = cx0 - r; cx <= cx0 + r; cx++) {
      for (let cy = cy0 - r; cy <= cy0 + r; cy++) {
        const list = this.cells.get(this.key(cx, cy));
        if (!list) continue;
        for (const v of list) {
          const p = f.par[v];
          if (p < 0) continue;
          const q = closestOnSegment(f.xs[v], f.ys[v], f.xs[p], f.ys[p], x, y);
          const d = Math.sqrt(q.d2);
          if (d < bestD || (d === bestD && best && v < best.v)) {
            bestD = d;
            best = { v, t: q.t, x: q.x, y: q.y, d };
          }
        }
      }
    }
    return best;
  }
}

/** Grid points (spacing g, anchored at origin) inside the areas, row by row. */
function samplePoints(areas: readonly ExPolygon[], g: number, origin: Pt): Pt[] {
  const rings = ringsOf(areas);
  let minY = Infinity,
    maxY = -Infinity;
  for (const r of rings)
    for (const p of r) {
      if (p.y < minY) minY = p.y;
      if (p.y > maxY) maxY = p.y;
    }
  const out: Pt[] = [];
  const xs: number[] = [];
  for (let j = Math.ceil((minY - origin.y) / g); origin.y + j * g <= maxY; j++) {
    const y = origin.y + j * g;
    rowCrossings(rings, y, xs);
    for (let k = 0; k + 1 < xs.length; k += 2) {
      for (let i = Math.ceil((xs[k] - origin.x) / g); origin.x + i * g <= xs[k + 1]; i++)
        out.push({ x: origin.x + i * g, y });
    }
  }
  return out;
}

/** Add branches so every point of `need` (inside the region) is within the support radius of the forest. */
export function grow(f: Forest, need: readonly ExPolygon[], ix: RegionIndex, fp: ForestParams): void {
  if (need.length === 0) return;
  // sample at half the radius: every sample within R of a branch keeps every point within R + g/√2 ≈ 1.35 R
  const g = fp.radius / 2;
  const reach = fp.radius;
  // the walls hold up whatever lies within the radius of them; farthest samples first, so long trunks
  // come first and later samples branch off them
  const samples = samplePoints(need, g, fp.origin)
    .filter((p) => pointInside(ix, p.x, p.y))
    .map((p) => ({ p, b: nearestBoundary(ix, p.x, p.y, FAR_UM) }))
    .filter((s) => s.b !== null && s.b.dist > reach) as Array<{
    p: Pt;
    b: NonNullable<ReturnType<typeof nearestBoundary>>;
  }>;
  samples.sort((a, b) => b.b.dist - a.b.dist || a.p.y - b.p.y || a.p.x - b.p.x);
  const grid = new EdgeGrid(f, fp.radius);
  const scratch: Hit[] = [];
  for (const { p, b } of samples) {
    if (grid.nearest(p.x, p.y, reach)) continue;
    const t = grid.nearest(p.x, p.y, b.dist);
    let attach = -1;
    if (t && !segmentCrosses(ix, p.x, p.y, t.x, t.y, ON_BOUNDARY_UM, scratch)) {
      const c = t.v,
        q = f.par[c];
      const len = hypot(f.xs[q] - f.xs[c], f.ys[q] - f.ys[c]);
      if (t.t * len < 1) attach = c;
      else if ((1 - t.t) * len < 1) attach = q;
      else {
        // split the edge c → q at the nearest point
        attach = f.xs.length;
        f.xs.push(t.x);
        f.ys.push(t.y);
        f.par.push(q);
        f.par[c] = attach;
        grid.add(attach);
      }
    } else {
      attach = f.xs.length;
      f.xs.push(b.x);
      f.ys.push(b.y);
      f.par.push(-1);
    }
    const v = f.xs.length;
    f.xs.push(p.x);
    f.ys.push(p.y);
    f.par.push(attach);
    grid.add(v);
  }
}

/** One layer down: prune, straighten, fit to the new region. */
export function propagate(above: Forest, ix: RegionIndex, fp: ForestParams): Forest {
  if (above.par.length === 0) return emptyForest();
  const f = prune(copyForest(above), fp.pruneDist);
  straighten(f, fp.straightenDist);
  return fitToRegion(f, ix, Math.max(fp.pruneDist, 2 * ON_BOUNDARY_UM));
}

/** The forest as polylines: from each root, a branch continues through the first child; others start anew. */
export function forestPolylines(f: Forest): Polyline[] {
  const n = f.par.length;
  const children: number[][] = Array.from({ length: n }, () => []);
  for (let v = 0; v < n; v++) if (f.par[v] >= 0) children[f.par[v]].push(v);
  const out: Polyline[] = [];
  const pt = (v: number): Pt => ({ x: Math.round(f.xs[v]), y: Math.round(f.ys[v]) });
  for (let r = 0; r < n; r++) {
    if (f.par[r] !== -1 || children[r].length === 0) continue;
    const starts: Array<[number, number]> = children[r].map((c) => [r, c]);
    while (starts.length) {
      const [from, first] = starts.shift() as [number, number];
      const line: Pt[] = [pt(from)];
      let v = first;
      for (;;) {
        line.push(pt(v));
        const ch = children[v];
        if (ch.length === 0) break;
        for (let k = 1; k < ch.length; k++) starts.push([v, ch[k]]);
        v = ch[0];
      }
      out.push(line);
    }
  }
  return out;
}
