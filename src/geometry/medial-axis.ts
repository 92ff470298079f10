/**
 * Medial axis (centre line with local radius) of thin areas, for variable-width walls: a strip of thickness
 * t becomes one line along its middle whose width at each point is twice the radius given there.
 *
 * Method: the boundary rings are sampled densely, the samples are Delaunay-triangulated (delaunator), and
 * the circumcentres of the triangles inside the area are the Voronoi vertices of the samples, which lie
 * close to the medial axis when the samples are dense compared with the local thickness. Each node's
 * radius is its distance to the boundary segments next to its triangle. Neighbouring inside triangles are
 * linked (never across a boundary interval, two consecutive samples of a ring: the Voronoi edges across
 * those run out to the boundary and are sampling noise), giving the axis graph. It is cut into chains
 * between junctions and leaves; leaf branches into corners blunter than the prune angle and short noise
 * branches are pruned until nothing changes, blunt tips are trimmed, and each chain is simplified.
 *
 * Sampling is adaptive, in a few passes of re-triangulation: a boundary interval is split when it is
 * longer than 2/3 of the circumradius of the inside triangle resting on it (so a strip gets at least three
 * samples per thickness along each side), when it is missing from the triangulation (the triangulation must
 * conform to the boundary for the inside/outside flood to be exact), or when the opposite vertex of that
 * triangle sees it at an obtuse angle (its circumcentre would lie beyond the boundary). Samples are graded
 * towards sharp corners from the start, which usually leaves one pass.
 *
 * Accuracy, for a strip of thickness t sampled at spacing s ≤ t/3: the nodes lie within s²/(8t) ≤ t/72 of
 * the centre line and their radii are at most s²/(4t²) ≤ 3 % short of t/2.
 */
import Delaunator from 'delaunator';
import { pointInRing, twiceArea } from './contain.js';
import { hypot, type ExPolygon, type Pt } from './types.js';

export interface MedialChain {
  /** Points along the axis, integer µm (rounded). */
  points: Pt[];
  /** Distance from each point to the area's boundary, µm (half the local thickness). Same length as points. */
  radii: Float64Array;
  /** True for a closed cycle (the centreline of a ring-shaped strip); points do not repeat the first. */
  closed: boolean;
}

export interface MedialOptions {
  /** Longest boundary sample spacing, µm (default 50). */
  sampleUm?: number;
  /** Leaf branches into corners blunter than this full angle (degrees) are pruned (default 10). */
  pruneAngleDeg?: number;
  /** Simplification tolerance, µm (default 10). */
  toleranceUm?: number;
}

/** Options resolved to the numbers the passes use. */
interface Settings {
  /** Longest sample spacing, µm. */
  sampleUm: number;
  /** Shortest sample spacing refinement goes down to, µm. */
  minSpacingUm: number;
  /** sin(pruneAngle / 2): the radius slope of a wedge of the prune angle. */
  slopeLimit: number;
  toleranceUm: number;
}

/** Largest sample spacing as a fraction of the local radius: at least three samples per thickness. */
const SPACING_PER_RADIUS = 2 / 3;
/**
 * Corners sharper than this (radians) get samples graded towards them from the start; the refinement would
 * ask for that at corners below about 87° (where the triangle next to the corner's ear gets a circumradius
 * under 3/2 of the spacing).
 */
const GRADED_CORNER = (85 * Math.PI) / 180;
/** Re-triangulation passes of the adaptive sampling, at most. */
const MAX_PASSES = 8;
/** Voronoi vertices of neighbouring triangles closer than this are one node (co-circular samples), µm. */
const MERGE_UM = 0.5;
/**
 * The radius slope at a tip is measured over at least this many of the shortest sample spacings: nodes
 * near a tip, where the radius falls below the spacing, are a few per cent off and need averaging.
 */
const TIP_WINDOW = 16;
/** Steps of a walk through the triangulation before it falls back to a point-in-area test. */
const MAX_WALK = 4096;

/**
 * The medial axis of `areas` as chains with radii.
 *
 * Open chains run between junctions and leaves; chains meeting at a junction share that end point exactly.
 * Closed chains are cycles: the centreline of a ring-shaped strip, or a loop hanging on one junction (which
 * is then one of its points). Branches into corners blunter than `pruneAngleDeg` are removed, and a line
 * running into a blunt point ends where the point starts narrowing; a wedge sharper than that keeps its line
 * to a few µm from the tip. An area whose branches all go (a blob such as a square or a disc) leaves one
 * chain of a single point, its centre, with the radius there.
 *
 * Each area is done on its own; the output is sorted by the chains' points (open chains run from their
 * lower end by x then y, cycles start at their lowest point and run counter-clockwise), so the same areas
 * give the same chains in any order.
 */
export function medialAxis(areas: readonly ExPolygon[], opts: MedialOptions = {}): MedialChain[] {
  const sampleUm = opts.sampleUm !== undefined && opts.sampleUm > 0 ? opts.sampleUm : 50;
  const angle = opts.pruneAngleDeg ?? 10;
  const toleranceUm = opts.toleranceUm !== undefined && opts.toleranceUm >= 0 ? opts.toleranceUm : 10;
  const set: Settings = {
    sampleUm,
    minSpacingUm: Math.min(sampleUm, Math.max(1, toleranceUm / 4)),
    slopeLimit: Math.sin(((Math.min(Math.max(angle, 0), 180) / 2) * Math.PI) / 180),
    toleranceUm,
  };
  const out: MedialChain[] = [];
  for (const area of areas) for (const c of areaAxis(area, set)) out.push(c);
  out.sort(compareChains);
  return out;
}

// ---------------------------------------------------------------------------------------------------------
// Boundary samples

/** Boundary samples of one area: coordinates and each sample's neighbours along its ring. */
interface Samples {
  /** x0, y0, x1, y1, ... */
  xy: Float64Array;
  /** Next sample along the ring (interior on the left of the ring's direction). */
  next: Int32Array;
  prev: Int32Array;
}

/**
 * A ring with repeated points dropped, oriented so that the area's interior lies on its left (outer rings
 * counter-clockwise, holes clockwise, whatever the input's orientation); null for a ring of no area.
 */
function orientedRing(ring: readonly Pt[], outer: boolean): Pt[] | null {
  const pts: Pt[] = [];
  for (const p of ring) {
    const q = pts[pts.length - 1];
    if (!q || q.x !== p.x || q.y !== p.y) pts.push(p);
  }
  while (pts.length > 1 && pts[0].x === pts[pts.length - 1].x && pts[0].y === pts[pts.length - 1].y) pts.pop();
  if (pts.length < 3) return null;
  const a = twiceArea(pts);
  if (a === 0) return null;
  if (a > 0 !== outer) pts.reverse();
  return pts;
}

/**
 * A ring sampled with every vertex kept and edges split into pieces no longer than the longest spacing.
 * Towards a convex vertex sharper than GRADED_CORNER the spacing shrinks in proportion to the distance
 * from it, as the refinement would ask: at distance d from a corner of angle β the local radius is at most
 * d·tan(β/2), and the spacing is kept within SPACING_PER_RADIUS of that (down to the shortest spacing).
 * This saves re-triangulation passes at sharp corners.
 */
function sampleRing(ring: readonly Pt[], set: Settings): number[] {
  const n = ring.length;
  // grading rate per vertex: spacing / distance from it (Infinity: none)
  const rate = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const o = ring[(i + n - 1) % n], p = ring[i], q = ring[(i + 1) % n];
    const ux = o.x - p.x, uy = o.y - p.y, vx = q.x - p.x, vy = q.y - p.y;
    // the interior lies left of the ring: the vertex is convex when the ring turns left there
    const convex = orient(o.x, o.y, p.x, p.y, q.x, q.y) > 0;
    const angle = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
    rate[i] = convex && angle < GRADED_CORNER ? SPACING_PER_RADIUS * Math.tan(angle / 2) : Infinity;
  }
  const out: number[] = [];
  const at: number[] = [];
  for (let i = 0; i < n; i++) {
    const p = ring[i], q = ring[(i + 1) % n];
    const len = hypot(q.x - p.x, q.y - p.y);
    const gp = rate[i], gq = rate[(i + 1) % n];
    at.length = 0;
    if (gp === Infinity && gq === Infinity) {
      const k = Math.max(1, Math.ceil(len / set.sampleUm));
      for (let s = 0; s < k; s++) at.push(s / k);
    } else {
      // march from p; towards q the step is sized for where it lands
      at.push(0);
      for (let x = 0; ; ) {
        const fromP = gp === Infinity ? Infinity : gp * x;
        const towardsQ = gq === Infinity ? Infinity : (gq * (len - x)) / (1 + gq);
        const h = Math.max(set.minSpacingUm, Math.min(set.sampleUm, fromP, towardsQ));
        if (x + h > len - 0.5 * set.minSpacingUm) {
          // a last piece much shorter than the step: the last two pieces share what is left
          if (len - x < 0.5 * h && at.length > 1) at[at.length - 1] = (at[at.length - 2] + 1) / 2;
          break;
        }
        x += h;
        at.push(x / len);
      }
    }
    for (const f of at) out.push(p.x + (q.x - p.x) * f, p.y + (q.y - p.y) * f);
  }
  return out;
}

/** The samples of all rings (flat coordinates each) as one set with ring neighbours. */
function collect(rings: readonly number[][]): Samples {
  let n = 0;
  for (const r of rings) n += r.length / 2;
  const xy = new Float64Array(2 * n), next = new Int32Array(n), prev = new Int32Array(n);
  let base = 0;
  for (const r of rings) {
    const m = r.length / 2;
    xy.set(r, 2 * base);
    for (let i = 0; i < m; i++) {
      next[base + i] = base + ((i + 1) % m);
      prev[base + i] = base + ((i + m - 1) % m);
    }
    base += m;
  }
  return { xy, next, prev };
}

/** The rings with interval i (sample i to the next) split into pieces[i] equal parts. */
function splitIntervals(rings: readonly number[][], pieces: Int32Array): number[][] {
  let base = 0;
  return rings.map((r) => {
    const m = r.length / 2, out: number[] = [];
    for (let i = 0; i < m; i++) {
      const j = (i + 1) % m;
      const x0 = r[2 * i], y0 = r[2 * i + 1], x1 = r[2 * j], y1 = r[2 * j + 1];
      out.push(x0, y0);
      const k = pieces[base + i];
      for (let s = 1; s < k; s++) out.push(x0 + ((x1 - x0) * s) / k, y0 + ((y1 - y0) * s) / k);
    }
    base += m;
    return out;
  });
}

// ---------------------------------------------------------------------------------------------------------
// Small geometry

/** Twice the signed area of triangle abc (positive when c is left of a→b). */
function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/** Distance from p to segment ab. */
function segDist(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  let t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const ex = ax + t * dx - px, ey = ay + t * dy - py;
  return Math.sqrt(ex * ex + ey * ey);
}

/** Circumcentre and circumradius of triangle t, into `out`; false for a degenerate triangle. */
function circumcentre(xy: Float64Array, tri: Uint32Array, t: number, out: Float64Array): boolean {
  const a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
  const ax = xy[2 * a], ay = xy[2 * a + 1];
  const bx = xy[2 * b] - ax, by = xy[2 * b + 1] - ay, cx = xy[2 * c] - ax, cy = xy[2 * c + 1] - ay;
  const d = 2 * (bx * cy - by * cx);
  const b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  if (Math.abs(d) <= 1e-12 * (b2 + c2)) return false;
  const ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  out[0] = ax + ux;
  out[1] = ay + uy;
  out[2] = Math.sqrt(ux * ux + uy * uy);
  return true;
}

const nextHalf = (e: number): number => (e % 3 === 2 ? e - 2 : e + 1);
const prevHalf = (e: number): number => (e % 3 === 0 ? e + 2 : e - 1);

/** Whether p lies inside an area given by its rings (outer first). */
function inArea(rings: readonly Pt[][], p: Pt): boolean {
  if (!pointInRing(p, rings[0])) return false;
  for (let i = 1; i < rings.length; i++) if (pointInRing(p, rings[i])) return false;
  return true;
}

// ---------------------------------------------------------------------------------------------------------
// Triangulation

/** A triangulation of an area's samples, with the ring structure. */
interface Mesh {
  s: Samples;
  tri: Uint32Array;
  half: Int32Array;
  /** Number of triangles. */
  nt: number;
  /** Per half-edge: the sample the boundary interval it lies on starts at (in ring order), or -1. */
  ivl: Int32Array;
  /**
   * Triangles of no area (three samples of one straight edge, which rounding left a hair off a line: the
   * triangulation makes such slivers along the convex hull). They get no node and link nothing.
   */
  flat: Uint8Array;
}

/** A triangle whose area is below this fraction of its longest edge squared is a sliver of collinear samples. */
const FLAT = 1e-9;

/** Delaunay triangulation of the samples, with each half-edge's boundary interval and the slivers. */
function triangulate(s: Samples): Mesh {
  const { xy, next } = s;
  const d = new Delaunator(xy);
  const tri = d.triangles, nt = tri.length / 3;
  const ivl = new Int32Array(tri.length), flat = new Uint8Array(nt);
  for (let e = 0; e < tri.length; e++) {
    const u = tri[e], v = tri[nextHalf(e)];
    ivl[e] = next[u] === v ? u : next[v] === u ? v : -1;
  }
  for (let t = 0; t < nt; t++) {
    const a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
    const ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1], cx = xy[2 * c], cy = xy[2 * c + 1];
    const abx = bx - ax, aby = by - ay, bcx = cx - bx, bcy = cy - by, cax = ax - cx, cay = ay - cy;
    const l2 = Math.max(abx * abx + aby * aby, bcx * bcx + bcy * bcy, cax * cax + cay * cay);
    if (Math.abs(orient(ax, ay, bx, by, cx, cy)) <= FLAT * l2) flat[t] = 1;
  }
  return { s, tri, half: d.halfedges, nt, ivl, flat };
}

/** Whether the triangle of half-edge e, which lies on the interval starting at sample a, is on its inner side. */
function innerSide(m: Mesh, e: number, a: number): boolean {
  const { xy } = m.s;
  const b = m.s.next[a], w = m.tri[prevHalf(e)];
  return orient(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], xy[2 * w], xy[2 * w + 1]) > 0;
}

/**
 * How many parts each boundary interval should be split into for the next pass (see the file comment),
 * or null when the sampling is fine as it is.
 */
function refinement(m: Mesh, set: Settings): Int32Array | null {
  const { xy, next, prev } = m.s;
  const n = next.length;
  const pieces = new Int32Array(n).fill(1);
  const seen = new Uint8Array(n);
  const cc = new Float64Array(3);
  let any = false;
  const minSplit = 2 * set.minSpacingUm;
  for (let e = 0; e < m.tri.length; e++) {
    const a = m.ivl[e];
    // only the triangle on the interval's inner side counts
    if (a < 0 || !innerSide(m, e, a)) continue;
    seen[a] = 1;
    if (m.flat[Math.floor(e / 3)]) continue;
    const b = next[a], w = m.tri[prevHalf(e)];
    const ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1], wx = xy[2 * w], wy = xy[2 * w + 1];
    const len = hypot(bx - ax, by - ay);
    if (len < minSplit) continue;
    let k = 1;
    // the opposite vertex sees the interval at an obtuse angle: the circumcentre is beyond the boundary
    if ((ax - wx) * (bx - wx) + (ay - wy) * (by - wy) <= 0) k = 2;
    // the local radius asks for closer samples (not at a corner's ear, whose radius is the spacing's)
    if (w !== prev[a] && w !== next[b] && circumcentre(xy, m.tri, Math.floor(e / 3), cc)) {
      const target = Math.max(set.minSpacingUm, Math.min(set.sampleUm, SPACING_PER_RADIUS * cc[2]));
      if (len > target * 1.001) k = Math.max(k, Math.ceil(len / target));
    }
    k = Math.min(k, Math.floor(len / set.minSpacingUm));
    if (k > 1) {
      pieces[a] = k;
      any = true;
    }
  }
  // intervals the triangulation lacks are halved until it conforms
  for (let a = 0; a < n; a++) {
    if (seen[a]) continue;
    const b = next[a];
    if (hypot(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]) >= minSplit) {
      pieces[a] = 2;
      any = true;
    }
  }
  return any ? pieces : null;
}

/**
 * Inside (1) or outside (2) for each triangle: seeded by the triangles on either side of the boundary
 * intervals and by hull edges, flooded across the other edges. Where the triangulation does not conform to
 * the boundary (the seeds disagree or some triangle is unreached), centroids are tested against the rings.
 */
function classify(m: Mesh, rings: readonly Pt[][]): Uint8Array {
  const { xy } = m.s;
  const label = new Uint8Array(m.nt);
  const queue = new Int32Array(m.nt);
  let qn = 0, clash = false;
  const mark = (t: number, l: number): void => {
    if (label[t] === 0) {
      label[t] = l;
      queue[qn++] = t;
    } else if (label[t] !== l) clash = true;
  };
  for (let e = 0; e < m.tri.length; e++) {
    const a = m.ivl[e], t = Math.floor(e / 3);
    if (a >= 0) mark(t, innerSide(m, e, a) ? 1 : 2);
    else if (m.half[e] < 0) mark(t, 2);
  }
  for (let q = 0; q < qn; q++) {
    const t = queue[q];
    for (let k = 0; k < 3; k++) {
      const e = 3 * t + k, o = m.half[e];
      if (o >= 0 && m.ivl[e] < 0) mark(Math.floor(o / 3), label[t]);
    }
  }
  for (let t = 0; t < m.nt; t++) {
    if (label[t] !== 0 && !clash) continue;
    const a = m.tri[3 * t], b = m.tri[3 * t + 1], c = m.tri[3 * t + 2];
    const p = { x: (xy[2 * a] + xy[2 * b] + xy[2 * c]) / 3, y: (xy[2 * a + 1] + xy[2 * b + 1] + xy[2 * c + 1]) / 3 };
    label[t] = inArea(rings, p) ? 1 : 2;
  }
  return label;
}

/**
 * Whether point (px, py) is inside the area, walking from inside triangle t0 towards it: false as soon as
 * the walk would cross the boundary or leave the inside triangles.
 */
function reaches(m: Mesh, label: Uint8Array, rings: readonly Pt[][], t0: number, px: number, py: number): boolean {
  const { xy } = m.s;
  let t = t0;
  for (let step = 0; step < MAX_WALK; step++) {
    let crossed = -1;
    for (let k = 0; k < 3; k++) {
      const e = 3 * t + k;
      const u = m.tri[e], v = m.tri[nextHalf(e)], w = m.tri[prevHalf(e)];
      const ux = xy[2 * u], uy = xy[2 * u + 1], vx = xy[2 * v], vy = xy[2 * v + 1];
      const sp = orient(ux, uy, vx, vy, px, py), sw = orient(ux, uy, vx, vy, xy[2 * w], xy[2 * w + 1]);
      if ((sp < 0 && sw > 0) || (sp > 0 && sw < 0)) {
        crossed = e;
        break;
      }
    }
    if (crossed < 0) return true;
    if (m.ivl[crossed] >= 0) return false;
    const o = m.half[crossed];
    if (o < 0) return false;
    t = Math.floor(o / 3);
    if (label[t] !== 1 || m.flat[t]) return false;
  }
  return inArea(rings, { x: px, y: py });
}

// ---------------------------------------------------------------------------------------------------------
// The axis graph

/** Nodes of the axis graph, indexed by triangle: position and radius. */
interface Nodes {
  x: Float64Array;
  y: Float64Array;
  r: Float64Array;
}

/** Distance from p to the boundary intervals next to triangle t's corners (the boundary nearest to it). */
function boundaryDistance(m: Mesh, t: number, px: number, py: number): number {
  const { xy, next, prev } = m.s;
  let d = Infinity;
  for (let k = 0; k < 3; k++) {
    const a = m.tri[3 * t + k], b = next[a], c = prev[a];
    const ax = xy[2 * a], ay = xy[2 * a + 1];
    d = Math.min(d, segDist(px, py, ax, ay, xy[2 * b], xy[2 * b + 1]), segDist(px, py, xy[2 * c], xy[2 * c + 1], ax, ay));
  }
  return d;
}

/** One area's medial chains. */
function areaAxis(area: ExPolygon, set: Settings): MedialChain[] {
  const outer = orientedRing(area.outer, true);
  if (!outer) return [];
  const rings: Pt[][] = [outer];
  for (const h of area.holes) {
    const r = orientedRing(h, false);
    if (r) rings.push(r);
  }
  // adaptive sampling
  let coords = rings.map((r) => sampleRing(r, set));
  let mesh = triangulate(collect(coords));
  for (let pass = 1; pass < MAX_PASSES && mesh.nt > 0; pass++) {
    const pieces = refinement(mesh, set);
    if (!pieces) break;
    coords = splitIntervals(coords, pieces);
    mesh = triangulate(collect(coords));
  }
  if (mesh.nt === 0) return [];
  const { nodes, edges, points } = axisGraph(mesh, classify(mesh, rings), rings);
  const chains = prune(relink(edges, mesh.nt), nodes, mesh.nt, set, points);
  return chainsOut(chains, points, nodes, mesh.nt, set);
}

/**
 * The axis graph of a classified triangulation: a node per inside triangle (its circumcentre, or its
 * centroid where the circumcentre falls outside the area), links between inside triangles sharing an edge
 * that is not a boundary interval, with nodes closer than MERGE_UM merged; `points` are the nodes left
 * without any link.
 */
function axisGraph(mesh: Mesh, label: Uint8Array, rings: readonly Pt[][]): { nodes: Nodes; edges: number[][]; points: Set<number> } {
  const { xy } = mesh.s;
  const nodes: Nodes = { x: new Float64Array(mesh.nt), y: new Float64Array(mesh.nt), r: new Float64Array(mesh.nt) };
  const cc = new Float64Array(3);
  // slivers are left out of the graph by counting them as not inside from here on
  for (let t = 0; t < mesh.nt; t++) if (mesh.flat[t]) label[t] = 2;
  for (let t = 0; t < mesh.nt; t++) {
    if (label[t] !== 1) continue;
    let px: number, py: number;
    if (circumcentre(xy, mesh.tri, t, cc) && reaches(mesh, label, rings, t, cc[0], cc[1])) {
      px = cc[0];
      py = cc[1];
    } else {
      const a = mesh.tri[3 * t], b = mesh.tri[3 * t + 1], c = mesh.tri[3 * t + 2];
      px = (xy[2 * a] + xy[2 * b] + xy[2 * c]) / 3;
      py = (xy[2 * a + 1] + xy[2 * b + 1] + xy[2 * c + 1]) / 3;
    }
    nodes.x[t] = px;
    nodes.y[t] = py;
    nodes.r[t] = boundaryDistance(mesh, t, px, py);
  }

  // links; nodes of (nearly) co-circular samples coincide and are merged (union-find, lowest index leads)
  const root = new Int32Array(mesh.nt);
  for (let t = 0; t < mesh.nt; t++) root[t] = t;
  const find = (t: number): number => {
    while (root[t] !== t) t = root[t] = root[root[t]];
    return t;
  };
  const links: number[] = [];
  let merged = false;
  for (let t = 0; t < mesh.nt; t++) {
    if (label[t] !== 1) continue;
    for (let k = 0; k < 3; k++) {
      const e = 3 * t + k, o = mesh.half[e];
      if (o < 0) continue;
      const u = Math.floor(o / 3);
      if (u <= t || label[u] !== 1 || mesh.ivl[e] >= 0) continue;
      links.push(t, u);
      if (hypot(nodes.x[t] - nodes.x[u], nodes.y[t] - nodes.y[u]) <= MERGE_UM) {
        merged = true;
        const ra = find(t), rb = find(u);
        if (ra < rb) root[rb] = ra;
        else if (rb < ra) root[ra] = rb;
      }
    }
  }
  // (two triangles share at most one edge, so only merged nodes can be linked twice)
  const edges: number[][] = [];
  const seenLink = new Set<number>();
  for (let i = 0; i < links.length; i += 2) {
    let a = find(links[i]), b = find(links[i + 1]);
    if (a === b) continue;
    if (merged) {
      if (a > b) [a, b] = [b, a];
      const key = a * mesh.nt + b;
      if (seenLink.has(key)) continue;
      seenLink.add(key);
    }
    edges.push([a, b]);
  }
  const points = new Set<number>();
  const linked = new Uint8Array(mesh.nt);
  for (const [a, b] of edges) linked[a] = linked[b] = 1;
  for (let t = 0; t < mesh.nt; t++) if (label[t] === 1 && find(t) === t && !linked[t]) points.add(t);
  return { nodes, edges, points };
}

// ---------------------------------------------------------------------------------------------------------
// Chains: paths of nodes between nodes of degree other than two

/** Degree of each node: how many path ends meet there. */
function degrees(paths: readonly number[][], n: number): Int32Array {
  const deg = new Int32Array(n);
  for (const p of paths) {
    deg[p[0]]++;
    deg[p[p.length - 1]]++;
  }
  return deg;
}

/**
 * The paths joined through every node of degree two: open chains from each node of other degree (in node
 * order), then the cycles left over (first node repeated at the end).
 */
function relink(paths: readonly number[][], n: number): number[][] {
  const deg = degrees(paths, n);
  // incidences per node, as 2 * path + (0 at its start, 1 at its end)
  const start = new Int32Array(n + 1);
  for (let v = 0; v < n; v++) start[v + 1] = start[v] + deg[v];
  const fill = start.slice(0, n);
  const inc = new Int32Array(start[n]);
  paths.forEach((p, i) => {
    inc[fill[p[0]]++] = 2 * i;
    inc[fill[p[p.length - 1]]++] = 2 * i + 1;
  });
  const used = new Uint8Array(paths.length);
  /** Unused incidence at node v, or -1. */
  const freeAt = (v: number): number => {
    for (let k = start[v]; k < start[v + 1]; k++) if (!used[inc[k] >> 1]) return inc[k];
    return -1;
  };
  /** Append path (inc >> 1), entered at its end (inc & 1), to `out` (its first node already there). */
  const extend = (out: number[], i: number): void => {
    used[i >> 1] = 1;
    const p = paths[i >> 1];
    if (i & 1) for (let k = p.length - 2; k >= 0; k--) out.push(p[k]);
    else for (let k = 1; k < p.length; k++) out.push(p[k]);
  };
  const out: number[][] = [];
  for (let v = 0; v < n; v++) {
    if (deg[v] === 0 || deg[v] === 2) continue;
    for (let i = freeAt(v); i >= 0; i = freeAt(v)) {
      const path = [v];
      extend(path, i);
      for (let cur = path[path.length - 1]; deg[cur] === 2; cur = path[path.length - 1]) {
        const j = freeAt(cur);
        if (j < 0) break;
        extend(path, j);
      }
      out.push(path);
    }
  }
  for (let i = 0; i < paths.length; i++) {
    if (used[i]) continue;
    const first = paths[i][0];
    const path = [first];
    extend(path, 2 * i);
    for (let cur = path[path.length - 1]; cur !== first; cur = path[path.length - 1]) {
      const j = freeAt(cur);
      if (j < 0) break;
      extend(path, j);
    }
    out.push(path);
  }
  return out;
}

function pathLength(p: readonly number[], nodes: Nodes): number {
  let l = 0;
  for (let k = 1; k < p.length; k++) l += hypot(nodes.x[p[k]] - nodes.x[p[k - 1]], nodes.y[p[k]] - nodes.y[p[k - 1]]);
  return l;
}

/**
 * Prunes the chains until stable. Each round does the first of these that applies:
 * 1. contracts links shorter than the tolerance between two junctions into one node (the one of larger
 *    radius), so that a junction split by the sampling is one point;
 * 2. removes leaf branches (a leaf at one end, a junction at the other) whose radius shrinks towards the
 *    leaf faster than the prune slope on average over the leaf's half of the branch, i.e. that run into a
 *    corner blunter than the prune angle (the half next to the junction is left out of the average: there
 *    the radius also changes because the branch leaves a wider or narrower part, as where a thin sharp
 *    spike stands on a thicker strip);
 * 3. removes, at each junction, the shortest leaf branch shorter than the junction's radius (noise).
 * The chains are then relinked through nodes left with degree two. A junction left with no chain at all
 * becomes a point (added to `points`).
 */
function prune(paths: number[][], nodes: Nodes, n: number, set: Settings, points: Set<number>): number[][] {
  for (;;) {
    const deg = degrees(paths, n);
    const lengths = paths.map((p) => pathLength(p, nodes));
    const drop = new Uint8Array(paths.length);

    // 1. short links between junctions
    let contracted = false;
    const alias = new Map<number, number>();
    const keeper = (v: number): number => {
      for (let a = alias.get(v); a !== undefined; a = alias.get(v)) v = a;
      return v;
    };
    paths.forEach((p, i) => {
      const a = keeper(p[0]), b = keeper(p[p.length - 1]);
      if (p[0] === p[p.length - 1] || deg[p[0]] < 3 || deg[p[p.length - 1]] < 3 || lengths[i] > set.toleranceUm) return;
      drop[i] = 1;
      contracted = true;
      if (a === b) return;
      const keep = nodes.r[a] > nodes.r[b] || (nodes.r[a] === nodes.r[b] && a < b) ? a : b;
      alias.set(keep === a ? b : a, keep);
    });
    if (contracted) {
      const kept: number[][] = [];
      paths.forEach((p, i) => {
        if (drop[i]) return;
        const q = p.slice();
        q[0] = keeper(q[0]);
        q[q.length - 1] = keeper(q[q.length - 1]);
        if (q.length === 2 && q[0] === q[1]) return;
        kept.push(q);
      });
      paths = relink(kept, n);
      continue;
    }

    // 2. leaf branches into blunt corners; 3. short noise branches
    let removed = false;
    const shortest = new Map<number, number>();
    paths.forEach((p, i) => {
      const a = p[0], b = p[p.length - 1];
      if (a === b) return;
      let leaf: number, junction: number;
      if (deg[a] === 1 && deg[b] >= 3) [leaf, junction] = [a, b];
      else if (deg[b] === 1 && deg[a] >= 3) [leaf, junction] = [b, a];
      else return;
      const len = lengths[i];
      if (leafSlope(leaf === a ? p : p.slice().reverse(), len, nodes) > set.slopeLimit) {
        drop[i] = 1;
        removed = true;
      } else if (len < nodes.r[junction]) {
        const s = shortest.get(junction);
        if (s === undefined || len < lengths[s]) shortest.set(junction, i);
      }
    });
    if (!removed) for (const i of shortest.values()) drop[i] = 1;
    if (!removed && shortest.size === 0) return paths;
    const kept = paths.filter((_, i) => !drop[i]);
    const left = degrees(kept, n);
    paths.forEach((p, i) => {
      if (!drop[i]) return;
      for (const v of [p[0], p[p.length - 1]]) if (deg[v] >= 3 && left[v] === 0) points.add(v);
    });
    paths = relink(kept, n);
  }
}

/** Growth of the radius per unit length over the first half of path p (of length len), from its start. */
function leafSlope(p: readonly number[], len: number, nodes: Nodes): number {
  if (!(len > 0)) return 0;
  const half = len / 2, r0 = nodes.r[p[0]];
  for (let k = 1, d = 0; k < p.length; k++) {
    const u = p[k - 1], v = p[k];
    const seg = hypot(nodes.x[v] - nodes.x[u], nodes.y[v] - nodes.y[u]);
    if (d + seg >= half) {
      const f = seg > 0 ? (half - d) / seg : 1;
      return (nodes.r[u] + f * (nodes.r[v] - nodes.r[u]) - r0) / half;
    }
    d += seg;
  }
  return (nodes.r[p[p.length - 1]] - r0) / len;
}

/**
 * How many nodes to cut from the start of path p: the tip is trimmed while the radius, over a window as long
 * as the local radius, grows away from it faster than the prune slope (a blunt tip, such as the 40° point of
 * a strip, ends where the strip stops narrowing; a sharp one keeps its line to the tip).
 */
function tipCut(p: readonly number[], nodes: Nodes, set: Settings): number {
  const n = p.length;
  const dist = new Float64Array(n);
  for (let k = 1; k < n; k++) dist[k] = dist[k - 1] + hypot(nodes.x[p[k]] - nodes.x[p[k - 1]], nodes.y[p[k]] - nodes.y[p[k - 1]]);
  let i = 0;
  while (i < n - 1) {
    const window = Math.max(nodes.r[p[i]], TIP_WINDOW * set.minSpacingUm);
    let j = i + 1;
    while (j < n && dist[j] - dist[i] < window) j++;
    if (j >= n) break;
    if (nodes.r[p[j]] - nodes.r[p[i]] <= set.slopeLimit * (dist[j] - dist[i])) break;
    i++;
  }
  return i;
}

/** Final chains: leaf tips trimmed, simplified, rounded, in a canonical direction and start. */
function chainsOut(paths: number[][], points: Set<number>, nodes: Nodes, n: number, set: Settings): MedialChain[] {
  const deg = degrees(paths, n);
  const out: MedialChain[] = [];
  for (let p of paths) {
    const a = p[0], b = p[p.length - 1];
    const closed = a === b;
    if (closed) {
      if (p.length <= 2) {
        points.add(a);
        continue;
      }
      p = p.slice(0, -1);
    } else {
      const cutA = deg[a] === 1 ? tipCut(p, nodes, set) : 0;
      const cutB = deg[b] === 1 ? tipCut(p.slice().reverse(), nodes, set) : 0;
      if (cutA + cutB >= p.length) {
        // trimmed from both ends to nothing: the widest node stays, as a point
        let best = p[0];
        for (const v of p) if (nodes.r[v] > nodes.r[best]) best = v;
        points.add(best);
        continue;
      }
      p = p.slice(cutA, p.length - cutB);
    }
    const c = finish(p, closed, closed && deg[p[0]] > 2 ? p[0] : -1, nodes, set.toleranceUm);
    if (c) out.push(c);
  }
  for (const v of points) out.push({ points: [{ x: round(nodes.x[v]), y: round(nodes.y[v]) }], radii: Float64Array.of(nodes.r[v]), closed: false });
  return out;
}

const round = (v: number): number => Math.round(v) || 0;

/** Whether (ax, ay) comes before (bx, by): by x, then y. */
const before = (ax: number, ay: number, bx: number, by: number): boolean => ax < bx || (ax === bx && ay < by);

/**
 * One chain as output: canonical start and direction, simplified, rounded. `pin` is a node the
 * simplification must keep (the junction a cycle hangs on, where another chain ends), or -1.
 */
function finish(p: readonly number[], closed: boolean, pin: number, nodes: Nodes, tol: number): MedialChain | null {
  const n = p.length;
  // node order: open chains run from their lower end (by x, then y); cycles start at their lowest node and
  // run counter-clockwise
  const order = new Int32Array(n);
  for (let k = 0; k < n; k++) order[k] = p[k];
  if (closed) {
    let s = 0, area = 0;
    for (let k = 0; k < n; k++) {
      const a = p[k], b = p[(k + 1) % n];
      if (before(nodes.x[a], nodes.y[a], nodes.x[p[s]], nodes.y[p[s]])) s = k;
      area += nodes.x[a] * nodes.y[b] - nodes.x[b] * nodes.y[a];
    }
    for (let k = 0; k < n; k++) order[k] = p[area < 0 ? (s - k + n) % n : (s + k) % n];
  } else if (before(nodes.x[p[n - 1]], nodes.y[p[n - 1]], nodes.x[p[0]], nodes.y[p[0]])) order.reverse();
  // a cycle is simplified as a path from its start round to its start again
  const m = closed ? n + 1 : n;
  const xs = new Float64Array(m), ys = new Float64Array(m), rs = new Float64Array(m);
  for (let k = 0; k < m; k++) {
    const v = order[k % n];
    xs[k] = nodes.x[v];
    ys[k] = nodes.y[v];
    rs[k] = nodes.r[v];
  }
  // simplify between fixed nodes: the ends; for a cycle also the node farthest from its start, and the pin
  const keep = new Uint8Array(m);
  keep[0] = keep[m - 1] = 1;
  if (closed) {
    let far = 0, fd = -1;
    for (let k = 1; k < n; k++) {
      const d = hypot(xs[k] - xs[0], ys[k] - ys[0]);
      if (d > fd) [far, fd] = [k, d];
    }
    keep[far] = 1;
    for (let k = 0; k < n; k++) if (order[k] === pin) keep[k] = 1;
  }
  for (let a = 0, b = 1; b < m; b++) {
    if (!keep[b]) continue;
    simplify(xs, ys, rs, a, b, tol, keep);
    a = b;
  }
  const points: Pt[] = [], radii: number[] = [];
  for (let k = 0; k < n; k++) {
    if (!keep[k]) continue;
    const q = { x: round(xs[k]), y: round(ys[k]) };
    const last = points[points.length - 1];
    if (last && last.x === q.x && last.y === q.y) continue;
    points.push(q);
    radii.push(rs[k]);
  }
  if (closed && points.length > 1 && points[0].x === points[points.length - 1].x && points[0].y === points[points.length - 1].y) {
    points.pop();
    radii.pop();
  }
  if (points.length === 0) return null;
  return { points, radii: Float64Array.from(radii), closed: closed && points.length >= 3 };
}

/**
 * Douglas–Peucker between kept indices i0 < i1: a node stays when it is farther than `tol` from the chord
 * or its radius differs from the chord's interpolated radius by more than `tol`.
 */
function simplify(xs: Float64Array, ys: Float64Array, rs: Float64Array, i0: number, i1: number, tol: number, keep: Uint8Array): void {
  const stack = [i0, i1];
  while (stack.length) {
    const b = stack.pop()!, a = stack.pop()!;
    if (b - a < 2) continue;
    const dx = xs[b] - xs[a], dy = ys[b] - ys[a], l2 = dx * dx + dy * dy;
    let worst = -1, err = tol;
    for (let k = a + 1; k < b; k++) {
      let t = l2 > 0 ? ((xs[k] - xs[a]) * dx + (ys[k] - ys[a]) * dy) / l2 : 0;
      t = t < 0 ? 0 : t > 1 ? 1 : t;
      const e = Math.max(hypot(xs[a] + t * dx - xs[k], ys[a] + t * dy - ys[k]), Math.abs(rs[a] + t * (rs[b] - rs[a]) - rs[k]));
      if (e > err) [worst, err] = [k, e];
    }
    if (worst < 0) continue;
    keep[worst] = 1;
    stack.push(a, worst, worst, b);
  }
}

/** Order of chains: by their points (x, then y), then by length, open before closed. */
function compareChains(a: MedialChain, b: MedialChain): number {
  const n = Math.min(a.points.length, b.points.length);
  for (let k = 0; k < n; k++) {
    const p = a.points[k], q = b.points[k];
    if (p.x !== q.x) return p.x - q.x;
    if (p.y !== q.y) return p.y - q.y;
  }
  if (a.points.length !== b.points.length) return a.points.length - b.points.length;
  return Number(a.closed) - Number(b.closed);
}
