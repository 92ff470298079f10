/**
 * Medial axis (centre line with local radius) of thin areas, for variable-width walls: a strip of thickness
 * t becomes one line along its middle whose width at each point is twice the radius given there.
 *
 * Method: the boundary rings are sampled densely, the samples are Delaunay-triangulated, and the
 * circumcentres of the triangles inside the area are the Voronoi vertices of the samples, which lie close
 * to the medial axis when the samples are dense compared with the local thickness. Each node's radius is
 * its distance to the boundary segments next to its triangle. Neighbouring inside triangles are linked
 * (never across a boundary interval, two consecutive samples of a ring: the Voronoi edges across those run
 * out to the boundary and are sampling noise), giving the axis graph. It is cut into chains between
 * junctions and leaves; leaf branches into corners blunter than the prune angle and short noise branches
 * are pruned until nothing changes, blunt tips are trimmed, and each chain is simplified.
 *
 * Triangulation: only the area's triangles are built, as a constrained Delaunay triangulation: the rings'
 * vertices are ear-clipped (holes bridged in) and flipped to Delaunay, and the samples between them go in
 * one by one, each splitting its boundary interval, with Lawson flips. Where the samples conform to the
 * boundary (every interval an edge of the Delaunay triangulation of all the samples, which the refinement
 * below ensures) these are exactly the inside triangles of that triangulation. Areas with too many vertices
 * for ear clipping (EAR_MAX), or degenerate ones, are triangulated whole by delaunator instead and the
 * inside triangles found by a flood from the boundary.
 *
 * Sampling is adaptive: a boundary interval is split when it is longer than SPACING_PER_RADIUS of the
 * circumradius of the inside triangle resting on it (so a strip gets more than two samples per thickness
 * along each side), when it is missing from the triangulation (delaunator's only: the flood must be exact),
 * or when the opposite vertex of that triangle sees it at an obtuse angle (its circumcentre would lie beyond
 * the boundary). The new samples are inserted into the triangulation where it stands, and only the
 * intervals whose triangles changed are looked at again. Samples are graded towards sharp corners from the
 * start, which usually leaves nothing to refine.
 *
 * Accuracy, for a strip of thickness t sampled at spacing s of about 0.75 · t/2 at most on each side: a
 * circumcentre lies up to s²/(8t) ≤ t/57 off the centre line, nearer the side two of its samples are on,
 * when the samples of the two sides are staggered; its node is moved back to where it is as far from either
 * side (centred), so that the nodes of a straight strip lie on its centre line with radius t/2 (uncentred,
 * they would zigzag about it with radii up to s²/(4t²) ≤ 3.5 % short).
 */
import Delaunator from 'delaunator';
import { pointInRing, twiceArea } from './contain.js';
import { hypot, segmentDistance2, type ExPolygon, type Pt } from './types.js';

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
  /**
   * Working memory to reuse (medialScratch): a caller with many calls to make (the areas of one layer) makes
   * one for them all; without it a call makes its own.
   */
  scratch?: MedialScratch;
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
  /** The call's working memory. */
  sc: MedialScratch;
}

/**
 * Largest sample spacing as a fraction of the circumradius of the triangle resting on the interval (about
 * the local radius): more than 2.5 samples per thickness. (Centring the nodes makes up for what a coarser
 * spacing costs in accuracy; coarser still, the pruning starts to decide differently now and then.)
 */
const SPACING_PER_RADIUS = 0.75;
/**
 * Spacing as a fraction of the local radius that samples are graded by towards sharp corners, from the
 * start: finer than the refinement asks for elsewhere, as the radius slope near a tip decides its trimming.
 */
const GRADE_PER_RADIUS = 2 / 3;
/**
 * Corners sharper than this (radians) get samples graded towards them from the start; the refinement would
 * ask for that at corners below about 87° (where the triangle next to the corner's ear gets a circumradius
 * under 3/2 of the spacing).
 */
const GRADED_CORNER = (85 * Math.PI) / 180;
/** A node is centred only where that moves it by at most this fraction of its distance from the interval. */
const CENTRING_LIMIT = 0.15;
/** Refinement passes of the adaptive sampling, at most. */
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

// ---------------------------------------------------------------------------------------------------------
// Scratch memory

/**
 * The typed arrays of the work (allocating them is a large part of a small area's time), grown as needed:
 * slot k of each kind holds one array at a time, so two arrays alive together use different slots. Views
 * handed out are valid until the slot is asked for again; nothing in the output refers to them. A call of
 * medialAxis works in its own set, or in its caller's (MedialOptions.scratch), which the caller hands to
 * one call after another (never shared beyond it: nothing of a slice lives at module level).
 */
export interface MedialScratch {
  readonly f64: Float64Array[];
  readonly i32: Int32Array[];
  readonly u8: Uint8Array[];
  /** The edges legalize has still to check. */
  flips: Int32Array;
}

/** Empty working memory for medialAxis, to reuse over many calls (MedialOptions.scratch). */
export function medialScratch(): MedialScratch {
  return { f64: [], i32: [], u8: [], flips: new Int32Array(256) };
}

/** Slots of the scratch arrays. */
const enum F {
  XY,
  NX,
  NY,
  NR,
  DIST,
  XS,
  YS,
  RS,
}
const enum I {
  TRI,
  HALF,
  NEXT,
  PREV,
  IVL,
  PIECES,
  WHERE,
  BND,
  VN,
  VP,
  SIDE,
  PEND,
  QUEUE,
  ROOT,
  ENDS,
  START,
  FILL,
  INC,
  DEG,
  DEG2,
  DEG3,
  RSTART,
  RFILL,
  RINC,
  ORDER,
}
const enum U {
  FLAT,
  LABEL,
  USED,
  DROP,
  KEEP,
  RUSED,
  DUP,
  DIRTY,
}

/** Scratch arrays above this many elements are not kept once the call is done with them. */
const SCRATCH_KEEP = 1 << 16;

/** Size of a scratch array that needs n elements and had old. */
function grow(n: number, old: number): number {
  return Math.max(n, 2 * old, 256);
}

/** A Float64Array of n elements from slot k (contents undefined). */
function f64(sc: MedialScratch, k: F, n: number): Float64Array {
  let b = sc.f64[k];
  if (!b || b.length < n) {
    b = new Float64Array(grow(n, b ? b.length : 0));
    if (b.length <= SCRATCH_KEEP) sc.f64[k] = b;
  }
  return b.subarray(0, n);
}

/** An Int32Array of n elements from slot k (contents undefined). */
function i32(sc: MedialScratch, k: I, n: number): Int32Array {
  let b = sc.i32[k];
  if (!b || b.length < n) {
    b = new Int32Array(grow(n, b ? b.length : 0));
    if (b.length <= SCRATCH_KEEP) sc.i32[k] = b;
  }
  return b.subarray(0, n);
}

/** A Uint8Array of n zeros from slot k. */
function u8(sc: MedialScratch, k: U, n: number): Uint8Array {
  let b = sc.u8[k];
  if (!b || b.length < n) {
    b = new Uint8Array(grow(n, b ? b.length : 0));
    if (b.length <= SCRATCH_KEEP) sc.u8[k] = b;
    return b.subarray(0, n);
  }
  return b.subarray(0, n).fill(0);
}

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
    sc: opts.scratch ?? medialScratch(),
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
 * A ring sampled (flat coordinates) with every vertex kept and edges split into pieces no longer than the
 * longest spacing; `corners` gets the sample index of each vertex. Towards a convex vertex sharper than
 * GRADED_CORNER the spacing shrinks in proportion to the distance from it, as the refinement would ask: at
 * distance d from a corner of angle β the local radius is at most d·tan(β/2), and the spacing is kept within
 * GRADE_PER_RADIUS of that (down to the shortest spacing). This saves refinement passes at sharp corners.
 */
function sampleRing(ring: readonly Pt[], set: Settings, corners: number[]): number[] {
  const n = ring.length;
  // grading rate per vertex: spacing / distance from it (Infinity: none)
  const rate = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const o = ring[(i + n - 1) % n],
      p = ring[i],
      q = ring[(i + 1) % n];
    const ux = o.x - p.x,
      uy = o.y - p.y,
      vx = q.x - p.x,
      vy = q.y - p.y;
    // the interior lies left of the ring: the vertex is convex when the ring turns left there
    const convex = orient(o.x, o.y, p.x, p.y, q.x, q.y) > 0;
    const angle = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
    rate[i] = convex && angle < GRADED_CORNER ? GRADE_PER_RADIUS * Math.tan(angle / 2) : Infinity;
  }
  const out: number[] = [];
  const at: number[] = [];
  for (let i = 0; i < n; i++) {
    const p = ring[i],
      q = ring[(i + 1) % n];
    const len = hypot(q.x - p.x, q.y - p.y);
    const gp = rate[i],
      gq = rate[(i + 1) % n];
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
    corners.push(out.length / 2);
    for (const f of at) out.push(p.x + (q.x - p.x) * f, p.y + (q.y - p.y) * f);
  }
  return out;
}

/**
 * The rings of a mesh's samples (flat coordinates each, from each ring's first sample on), with the interval
 * from sample a to the next split into pieces[a] equal parts.
 */
function splitRings(m: Mesh, pieces: Int32Array): number[][] {
  const { xy, next } = m.s;
  return m.ringStart.map((first) => {
    const out: number[] = [];
    let a = first;
    do {
      const b = next[a];
      const x0 = xy[2 * a],
        y0 = xy[2 * a + 1],
        x1 = xy[2 * b],
        y1 = xy[2 * b + 1];
      out.push(x0, y0);
      const k = pieces[a];
      for (let s = 1; s < k; s++) out.push(x0 + ((x1 - x0) * s) / k, y0 + ((y1 - y0) * s) / k);
      a = b;
    } while (a !== first);
    return out;
  });
}

// ---------------------------------------------------------------------------------------------------------
// Small geometry

/** Twice the signed area of triangle abc (positive when c is left of a→b). */
function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/**
 * A triangle whose doubled area is at most this share of the squared lengths of two of its sides is degenerate:
 * its circumcentre is too far off to compute. Dimensionless.
 */
const DEGENERATE = 1e-12;

/** Circumcentre and circumradius of triangle t, into `out`; false for a degenerate triangle. */
function circumcentre(xy: Float64Array, tri: Int32Array, t: number, out: Float64Array): boolean {
  const a = tri[3 * t],
    b = tri[3 * t + 1],
    c = tri[3 * t + 2];
  const ax = xy[2 * a],
    ay = xy[2 * a + 1];
  const bx = xy[2 * b] - ax,
    by = xy[2 * b + 1] - ay,
    cx = xy[2 * c] - ax,
    cy = xy[2 * c + 1] - ay;
  const d = 2 * (bx * cy - by * cx);
  const b2 = bx * bx + by * by,
    c2 = cx * cx + cy * cy;
  if (Math.abs(d) <= DEGENERATE * (b2 + c2)) return false;
  const ux = (cy * b2 - by * c2) / d,
    uy = (bx * c2 - cx * b2) / d;
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

/**
 * A triangulation of an area's samples, with the ring structure. The arrays have room beyond the counts
 * for samples inserted by the refinement (two triangles per sample).
 */
interface Mesh {
  /** The working memory the mesh's arrays come from. */
  sc: MedialScratch;
  s: Samples;
  /** Number of samples. */
  n: number;
  /** Each ring's first sample. */
  ringStart: number[];
  /**
   * Corners of each triangle in delaunator's layout (half-edge e runs from tri[e] to the next corner of its
   * triangle) and order (clockwise with y up).
   */
  tri: Int32Array;
  /** Opposite half-edge of each half-edge, or -1 on the convex hull (or the area's boundary). */
  half: Int32Array;
  /** Number of triangles. */
  nt: number;
  /**
   * Per half-edge: the sample the boundary interval it lies on starts at (in ring order), or -1. Delaunator's
   * triangulations only: in a constrained one the intervals are the half-edges without opposite.
   */
  ivl: Int32Array;
  /**
   * Triangles of no area (three samples of one straight edge, which rounding left a hair off a line: the
   * triangulation makes such slivers along the convex hull). They get no node and link nothing.
   */
  flat: Uint8Array;
  /**
   * For a constrained triangulation (only the area's triangles, boundary intervals without opposite):
   * the half-edge of the interval from each sample (it runs from the next sample back to this one). Null
   * for a Delaunay triangulation of the convex hull.
   */
  bnd: Int32Array | null;
  /** For a constrained triangulation: the triangles made or changed since the refinement last looked. */
  dirty: Uint8Array | null;
}

/** A triangle whose area is below this fraction of its longest edge squared is a sliver of collinear samples. */
const FLAT = 1e-9;

/**
 * Delaunay triangulation (delaunator) of the rings' samples (flat coordinates each), with room for `extra`
 * more samples.
 */
function triangulate(rings: readonly number[][], extra: number, sc: MedialScratch): Mesh {
  let n = 0;
  for (const r of rings) n += r.length / 2;
  const cap = n + extra;
  const xy = f64(sc, F.XY, 2 * cap),
    next = i32(sc, I.NEXT, cap),
    prev = i32(sc, I.PREV, cap);
  const ringStart: number[] = [];
  let base = 0;
  for (const r of rings) {
    const k = r.length / 2;
    ringStart.push(base);
    xy.set(r, 2 * base);
    for (let i = 0; i < k; i++) {
      next[base + i] = base + ((i + 1) % k);
      prev[base + i] = base + ((i + k - 1) % k);
    }
    base += k;
  }
  const d = new Delaunator(xy.subarray(0, 2 * n));
  const nt = d.triangles.length / 3,
    tcap = nt + 2 * extra;
  const tri = i32(sc, I.TRI, 3 * tcap),
    half = i32(sc, I.HALF, 3 * tcap);
  tri.set(d.triangles);
  half.set(d.halfedges);
  const m: Mesh = {
    sc,
    s: { xy, next, prev },
    n,
    ringStart,
    tri,
    half,
    nt,
    ivl: i32(sc, I.IVL, 3 * tcap),
    flat: u8(sc, U.FLAT, tcap),
    bnd: null,
    dirty: null,
  };
  intervals(m);
  return m;
}

/**
 * Ring vertices (and two per hole) up to which the constrained triangulation is used: ear clipping takes
 * quadratic time, and beyond this delaunator is faster.
 */
const EAR_MAX = 128;

/**
 * Constrained Delaunay triangulation of an area from its rings' samples (flat coordinates each, outer ring
 * first; `corners`: the samples of each ring that are its vertices, ascending from 0), with room for `extra`
 * more samples. The vertices are ear-clipped (holes bridged in) and flipped to Delaunay, then the other
 * samples go in by splitting boundary intervals, each edge's samples bisected level by level. Only the
 * area's triangles exist. Null where ear clipping fails (a degenerate ring): delaunator then triangulates.
 *
 * Where the samples are dense enough that the Delaunay triangulation of all of them has every boundary
 * interval as an edge (which the refinement ensures), its triangles inside the area are these.
 */
function constrained(
  rings: readonly number[][],
  corners: readonly number[][],
  extra: number,
  sc: MedialScratch,
): Mesh | null {
  let n = 0;
  for (const r of rings) n += r.length / 2;
  const cap = n + extra;
  const xy = f64(sc, F.XY, 2 * cap),
    next = i32(sc, I.NEXT, cap),
    prev = i32(sc, I.PREV, cap);
  const ringStart: number[] = [];
  const vertices: number[][] = [];
  let base = 0;
  for (let r = 0; r < rings.length; r++) {
    const k = rings[r].length / 2;
    ringStart.push(base);
    xy.set(rings[r], 2 * base);
    for (let i = 0; i < k; i++) {
      next[base + i] = i + 1 < k ? base + i + 1 : base;
      prev[base + i] = i > 0 ? base + i - 1 : base + k - 1;
    }
    vertices.push(corners[r].map((c) => base + c));
    base += k;
  }
  const tcap = n + 2 * rings.length + 2 * extra;
  const tri = i32(sc, I.TRI, 3 * tcap),
    half = i32(sc, I.HALF, 3 * tcap),
    bnd = i32(sc, I.BND, cap);
  const m: Mesh = {
    sc,
    s: { xy, next, prev },
    n,
    ringStart,
    tri,
    half,
    nt: 0,
    ivl: i32(sc, I.IVL, 3 * tcap),
    flat: u8(sc, U.FLAT, tcap),
    bnd,
    dirty: u8(sc, U.DIRTY, tcap),
  };
  const poly = bridged(xy, vertices);
  if (!poly || !clipEars(m, poly)) return null;
  // to Delaunay: flip until every edge is locally Delaunay (a bound on the flips guards against rounding
  // cycling them)
  const stack: number[] = [];
  for (let e = 0; e < 3 * m.nt; e++) if (half[e] > e) stack.push(e);
  for (let flips = 0; stack.length; ) {
    const a = stack.pop()!,
      b = half[a];
    if (b < 0 || !illegal(m, a, b)) continue;
    if (++flips > MAX_FLIPS) return null;
    flip(m, a, b);
    const a0 = a - (a % 3),
      b0 = b - (b % 3);
    stack.push(a, a0 + ((a + 1) % 3), b, b0 + ((b + 1) % 3));
  }
  // the samples between the vertices, by bisection: (first sample, lo, hi) of each range still to split
  const ranges: number[] = [];
  for (let r = 0; r < rings.length; r++) {
    const vs = vertices[r],
      end = ringStart[r] + rings[r].length / 2;
    for (let j = 0; j < vs.length; j++) {
      const len = (j + 1 < vs.length ? vs[j + 1] : end) - vs[j];
      if (len >= 2) ranges.push(vs[j], 0, len);
    }
  }
  for (let q = 0; q < ranges.length; q += 3) {
    const s0 = ranges[q],
      lo = ranges[q + 1],
      hi = ranges[q + 2],
      mid = (lo + hi) >> 1;
    splitEdge(m, bnd[s0 + lo], s0 + mid);
    if (mid - lo >= 2) ranges.push(s0, lo, mid);
    if (hi - mid >= 2) ranges.push(s0, mid, hi);
  }
  return m;
}

/** A polygon for ear clipping: the sample at each position, the next position, and bridges. */
interface EarPolygon {
  /** Sample at each position (a sample where a bridge joins a hole in has two positions). */
  at: number[];
  /** Next position along the polygon (counter-clockwise round the outer ring, clockwise round holes). */
  nxt: number[];
  /** For the two positions whose edge to the next is one side of a bridge: the other side's; else -1. */
  partner: number[];
}

/**
 * The vertices of an area's rings (samples; the outer ring counter-clockwise, holes clockwise) as one
 * polygon: each hole joined to what is already joined by a bridge, two opposite edges from its rightmost
 * vertex to a vertex it sees on its right (holes from right to left). Null where no bridge is found.
 */
function bridged(xy: Float64Array, vertices: readonly number[][]): EarPolygon | null {
  const outer = vertices[0];
  const at = outer.slice(),
    nxt = outer.map((_, i) => (i + 1) % outer.length),
    partner = outer.map(() => -1);
  // holes by their rightmost vertex, right to left
  const holes = vertices.slice(1).map((h) => {
    let best = 0;
    for (let i = 1; i < h.length; i++) if (xy[2 * h[i]] > xy[2 * h[best]]) best = i;
    return { h, best, x: xy[2 * h[best]] };
  });
  holes.sort((a, b) => b.x - a.x);
  for (const { h, best } of holes) {
    const mx = xy[2 * h[best]],
      my = xy[2 * h[best] + 1];
    // the nearest edge on the right running upwards across y = my (the area lies left of it)
    let qx = Infinity,
      target = -1;
    for (let a = 0; a < at.length; a++) {
      const b = nxt[a];
      const ax = xy[2 * at[a]],
        ay = xy[2 * at[a] + 1],
        bx = xy[2 * at[b]],
        by = xy[2 * at[b] + 1];
      if (!(ay <= my && my <= by && ay < by)) continue;
      const x = ax + ((my - ay) * (bx - ax)) / (by - ay);
      if (x < mx || x >= qx) continue;
      qx = x;
      target = ay === my && ax === x ? a : by === my && bx === x ? b : ax > bx ? a : b;
    }
    if (target < 0) return null;
    // a vertex inside the triangle (hole vertex, crossing, target) would block the view: the one seen at the
    // least angle from the ray is visible
    const tx = xy[2 * at[target]],
      ty = xy[2 * at[target] + 1];
    let tan = Infinity;
    for (let v = 0; v < at.length; v++) {
      if (v === target) continue;
      const vx = xy[2 * at[v]],
        vy = xy[2 * at[v] + 1];
      if (!(vx > mx) || !inTriangle(mx, my, qx, my, tx, ty, vx, vy)) continue;
      const t = Math.abs(vy - my) / (vx - mx);
      if (t < tan && locallyInside(xy, at, nxt, v, mx, my)) {
        tan = t;
        target = v;
      }
    }
    // splice: target → hole (from its rightmost vertex round to it again) → target again → on
    const first = at.length;
    for (let i = 0; i < h.length; i++) {
      at.push(h[(best + i) % h.length]);
      nxt.push(first + i + 1);
      partner.push(-1);
    }
    const m2 = at.length,
      t2 = m2 + 1;
    at.push(h[best], at[target]);
    nxt.push(t2, nxt[target]);
    // the target's own edge on goes from its second position
    partner.push(target, partner[target]);
    if (partner[target] >= 0) partner[partner[target]] = t2;
    nxt[target] = first;
    partner[target] = m2;
  }
  return { at, nxt, partner };
}

/** Whether p lies in triangle abc or on its boundary (either orientation). */
function inTriangle(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  cx: number,
  cy: number,
  px: number,
  py: number,
): boolean {
  const d1 = orient(ax, ay, bx, by, px, py),
    d2 = orient(bx, by, cx, cy, px, py),
    d3 = orient(cx, cy, ax, ay, px, py);
  return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}

/** Whether the direction from position v to p points into the polygon's inside at v. */
function locallyInside(
  xy: Float64Array,
  at: readonly number[],
  nxt: readonly number[],
  v: number,
  px: number,
  py: number,
): boolean {
  let u = v;
  while (nxt[u] !== v) u = nxt[u];
  const ux = xy[2 * at[u]],
    uy = xy[2 * at[u] + 1],
    vx = xy[2 * at[v]],
    vy = xy[2 * at[v] + 1],
    wx = xy[2 * at[nxt[v]]],
    wy = xy[2 * at[nxt[v]] + 1];
  const left1 = orient(ux, uy, vx, vy, px, py) > 0,
    left2 = orient(vx, vy, wx, wy, px, py) > 0;
  return orient(ux, uy, vx, vy, wx, wy) > 0 ? left1 && left2 : left1 || left2;
}

/**
 * Ear clipping of a polygon of samples (counter-clockwise) into m's triangles (clockwise, as delaunator's),
 * with the half-edges linked and the boundary's noted in m.bnd. False when no ear is left to clip (a
 * degenerate ring).
 */
function clipEars(m: Mesh, poly: EarPolygon): boolean {
  const { sc } = m;
  const { xy } = m.s;
  const { tri, half } = m;
  const bnd = m.bnd!;
  const { at, partner } = poly;
  const nv = at.length;
  // the remaining polygon as a linked list, and for each position the half-edge beyond its edge to the
  // next: -1 while that edge is the boundary's, -2 while it is a bridge side (pend: its half-edge once a
  // triangle has it)
  const vn = i32(sc, I.VN, nv),
    vp = i32(sc, I.VP, nv),
    side = i32(sc, I.SIDE, nv),
    pend = i32(sc, I.PEND, nv);
  for (let i = 0; i < nv; i++) {
    vn[i] = poly.nxt[i];
    vp[poly.nxt[i]] = i;
    side[i] = partner[i] >= 0 ? -2 : -1;
    pend[i] = -1;
  }
  /** Links half-edge h (the reverse of position a's edge to the next) to what lies beyond. */
  const edge = (h: number, a: number): void => {
    const s = side[a];
    if (s >= 0) link(half, h, s);
    else if (s === -1) {
      half[h] = -1;
      bnd[at[a]] = h;
    } else {
      const o = pend[partner[a]];
      if (o >= 0) link(half, h, o);
      else {
        half[h] = -1;
        pend[a] = h;
      }
    }
  };
  let left = nv,
    i = 0;
  for (let miss = 0; left > 3; ) {
    const u = vp[i],
      w = vn[i];
    if (isEar(xy, at, vn, u, i, w)) {
      // (u, i, w) is counter-clockwise: stored as (u, w, i)
      const t = 3 * m.nt++;
      tri[t] = at[u];
      tri[t + 1] = at[w];
      tri[t + 2] = at[i];
      half[t] = -1;
      edge(t + 1, i);
      edge(t + 2, u);
      // u→w is an edge of what is left, with this triangle beyond it
      side[u] = t;
      vn[u] = w;
      vp[w] = u;
      left--;
      i = u;
      miss = 0;
    } else {
      i = w;
      if (++miss > left) return false;
    }
  }
  // the last triangle (i, j, k) counter-clockwise: stored as (i, k, j)
  const j = vn[i],
    k = vn[j];
  const t = 3 * m.nt++;
  tri[t] = at[i];
  tri[t + 1] = at[k];
  tri[t + 2] = at[j];
  edge(t, k);
  edge(t + 1, j);
  edge(t + 2, i);
  return true;
}

/**
 * Whether position i (between u and w on the remaining polygon) is an ear: convex, and no other vertex in
 * it (other than the positions of its own three samples).
 */
function isEar(xy: Float64Array, at: readonly number[], vn: Int32Array, u: number, i: number, w: number): boolean {
  const cu = at[u],
    ci = at[i],
    cw = at[w];
  const ux = xy[2 * cu],
    uy = xy[2 * cu + 1],
    ix = xy[2 * ci],
    iy = xy[2 * ci + 1],
    wx = xy[2 * cw],
    wy = xy[2 * cw + 1];
  if (!(orient(ux, uy, ix, iy, wx, wy) > 0)) return false;
  for (let v = vn[w]; v !== u; v = vn[v]) {
    const c = at[v];
    if (c === cu || c === ci || c === cw) continue;
    const px = xy[2 * c],
      py = xy[2 * c + 1];
    if (
      orient(ux, uy, ix, iy, px, py) >= 0 &&
      orient(ix, iy, wx, wy, px, py) >= 0 &&
      orient(wx, wy, ux, uy, px, py) >= 0
    )
      return false;
  }
  return true;
}

/** Each half-edge's boundary interval and the slivers, for a Delaunay triangulation of the convex hull. */
function intervals(m: Mesh): void {
  const { next } = m.s;
  const { tri, ivl } = m;
  for (let e = 0; e < 3 * m.nt; e++) {
    const u = tri[e],
      v = tri[nextHalf(e)];
    ivl[e] = next[u] === v ? u : next[v] === u ? v : -1;
  }
  flats(m);
}

/** The slivers among the triangles. */
function flats(m: Mesh): void {
  for (let t = 0; t < m.nt; t++) m.flat[t] = isFlat(m.s.xy, m.tri, t) ? 1 : 0;
}

/** Whether triangle t is a sliver: its area below FLAT of its longest edge squared. */
function isFlat(xy: Float64Array, tri: Int32Array, t: number): boolean {
  const a = tri[3 * t],
    b = tri[3 * t + 1],
    c = tri[3 * t + 2];
  const ax = xy[2 * a],
    ay = xy[2 * a + 1],
    bx = xy[2 * b],
    by = xy[2 * b + 1],
    cx = xy[2 * c],
    cy = xy[2 * c + 1];
  const abx = bx - ax,
    aby = by - ay,
    bcx = cx - bx,
    bcy = cy - by,
    cax = ax - cx,
    cay = ay - cy;
  const l2 = Math.max(abx * abx + aby * aby, bcx * bcx + bcy * bcy, cax * cax + cay * cay);
  return Math.abs(orient(ax, ay, bx, by, cx, cy)) <= FLAT * l2;
}

/** Room in the mesh's arrays for `more` samples (and their triangles). */
function makeRoom(m: Mesh, more: number): void {
  const cap = m.s.next.length;
  if (m.n + more <= cap && m.nt + 2 * more <= m.flat.length) return;
  const n2 = Math.max(m.n + more, 2 * cap),
    t2 = m.nt + 2 * (n2 - m.n);
  const moved = <T extends Float64Array | Int32Array | Uint8Array>(old: T, fresh: T, used: number): T => {
    fresh.set(old.subarray(0, used));
    return fresh;
  };
  // the new arrays go to other slots first: a slot's array may be the very one being copied
  m.s.xy = moved(m.s.xy, new Float64Array(2 * n2), 2 * m.n);
  m.s.next = moved(m.s.next, new Int32Array(n2), m.n);
  m.s.prev = moved(m.s.prev, new Int32Array(n2), m.n);
  m.tri = moved(m.tri, new Int32Array(3 * t2), 3 * m.nt);
  m.half = moved(m.half, new Int32Array(3 * t2), 3 * m.nt);
  m.ivl = new Int32Array(3 * t2);
  m.flat = new Uint8Array(t2);
  if (m.bnd) m.bnd = moved(m.bnd, new Int32Array(n2), m.n);
  if (m.dirty) m.dirty = moved(m.dirty, new Uint8Array(t2), m.nt);
  if (2 * n2 <= SCRATCH_KEEP) {
    const { sc } = m;
    sc.f64[F.XY] = m.s.xy;
    sc.i32[I.NEXT] = m.s.next;
    sc.i32[I.PREV] = m.s.prev;
    sc.i32[I.TRI] = m.tri;
    sc.i32[I.HALF] = m.half;
    sc.i32[I.IVL] = m.ivl;
    sc.u8[U.FLAT] = m.flat;
    if (m.bnd) sc.i32[I.BND] = m.bnd;
    if (m.dirty) sc.u8[U.DIRTY] = m.dirty;
  }
}

/** Makes half-edges a and b opposite each other (b may be -1). */
function link(half: Int32Array, a: number, b: number): void {
  half[a] = b;
  if (b >= 0) half[b] = a;
}

/** Edge flips an insertion (or the ear-clipped vertices) may take at most: a guard against rounding cycling them. */
const MAX_FLIPS = 100000;

/**
 * Whether the edge of half-edges a and b (opposite each other) is not Delaunay: b's far corner lies inside
 * the circumcircle of a's triangle.
 */
function illegal(m: Mesh, a: number, b: number): boolean {
  const { tri } = m;
  const xy = m.s.xy;
  const p0 = tri[prevHalf(a)],
    pr = tri[a],
    pl = tri[nextHalf(a)],
    p1 = tri[prevHalf(b)];
  return inCircle(
    xy[2 * p0],
    xy[2 * p0 + 1],
    xy[2 * pr],
    xy[2 * pr + 1],
    xy[2 * pl],
    xy[2 * pl + 1],
    xy[2 * p1],
    xy[2 * p1 + 1],
  );
}

/**
 * Flips the edge of half-edges a and b (opposite each other): a's triangle (pr, pl, p0) and b's (pl, pr,
 * p1) become (p1, pl, p0) and (p0, pr, p1), as in delaunator's _legalize. Boundary half-edges that move
 * are noted in m.bnd.
 */
function flip(m: Mesh, a: number, b: number): void {
  const { tri, half, bnd } = m;
  const a0 = a - (a % 3),
    b0 = b - (b % 3);
  const ar = a0 + ((a + 2) % 3),
    bl = b0 + ((b + 2) % 3);
  const p0 = tri[ar],
    p1 = tri[bl];
  tri[a] = p1;
  tri[b] = p0;
  const hbl = half[bl],
    har = half[ar];
  link(half, a, hbl);
  link(half, b, har);
  link(half, ar, bl);
  if (bnd) {
    // a boundary half-edge runs from the interval's end back to its start
    if (hbl < 0) bnd[tri[a0 + ((a + 1) % 3)]] = a;
    if (har < 0) bnd[tri[b0 + ((b + 1) % 3)]] = b;
  }
  if (m.dirty) m.dirty[a0 / 3] = m.dirty[b0 / 3] = 1;
}

/**
 * Lawson flips after inserting sample p: edge a (of a triangle with corner p, opposite p) and the edges
 * that come opposite p by flipping are flipped while p lies inside the circumcircle across them (as
 * delaunator's _legalize).
 */
function legalize(m: Mesh, a: number): void {
  const { half, sc } = m;
  let stack = sc.flips,
    top = 0;
  for (let flips = 0; flips < MAX_FLIPS; ) {
    const b = half[a];
    if (b >= 0 && illegal(m, a, b)) {
      flip(m, a, b);
      if (top === stack.length) {
        const bigger = new Int32Array(2 * top);
        bigger.set(stack);
        stack = sc.flips = bigger;
      }
      stack[top++] = b - (b % 3) + ((b + 1) % 3);
      flips++;
      continue;
    }
    if (top === 0) return;
    a = stack[--top];
  }
}

/** Whether p lies inside the circumcircle of a, b, c (counter-clockwise), as delaunator tests it. */
function inCircle(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  cx: number,
  cy: number,
  px: number,
  py: number,
): boolean {
  const dx = ax - px,
    dy = ay - py,
    ex = bx - px,
    ey = by - py,
    fx = cx - px,
    fy = cy - py;
  const ap = dx * dx + dy * dy,
    bp = ex * ex + ey * ey,
    cp = fx * fx + fy * fy;
  return dx * (ey * cp - bp * fy) - dy * (ex * cp - bp * fx) + ap * (ex * fy - ey * fx) < 0;
}

/**
 * Inserts sample p, which lies on the edge of half-edge e (from sample a to sample b), splitting the
 * triangles on either side and flipping edges until the triangulation is Delaunay again. Half-edge e runs
 * from a to p afterwards (the flips only turn edges opposite p: half-edges into p stay as they are).
 */
function splitEdge(m: Mesh, e: number, p: number): void {
  const { tri, half } = m;
  const en = nextHalf(e),
    ep = prevHalf(e),
    e1 = half[e];
  const b = tri[en],
    w = tri[ep];
  // (a, b, w) becomes (a, p, w) and (p, b, w)
  const f0 = 3 * m.nt++;
  tri[f0] = p;
  tri[f0 + 1] = b;
  tri[f0 + 2] = w;
  tri[en] = p;
  const hen = half[en];
  link(half, f0 + 1, hen);
  link(half, en, f0 + 2);
  const bnd = m.bnd;
  if (bnd && hen < 0) bnd[w] = f0 + 1;
  if (m.dirty) m.dirty[(e / 3) | 0] = m.dirty[f0 / 3] = 1;
  if (e1 >= 0) {
    // (b, a, z) becomes (p, a, z) and (b, p, z)
    const e1p = prevHalf(e1),
      z = tri[e1p];
    const g0 = 3 * m.nt++;
    tri[g0] = b;
    tri[g0 + 1] = p;
    tri[g0 + 2] = z;
    tri[e1] = p;
    link(half, g0 + 2, half[e1p]);
    link(half, e1p, g0 + 1);
    link(half, f0, g0);
    legalize(m, nextHalf(e1));
    legalize(m, g0 + 2);
  } else {
    half[f0] = -1;
    if (bnd) {
      // the intervals (b, p) and (p, a), when a→b runs from an interval's end back to its start
      bnd[b] = f0;
      bnd[p] = e;
    }
  }
  legalize(m, ep);
  legalize(m, f0 + 1);
}

/** Whether the triangle of half-edge e, which lies on the interval starting at sample a, is on its inner side. */
function innerSide(m: Mesh, e: number, a: number): boolean {
  const { xy } = m.s;
  const b = m.s.next[a],
    w = m.tri[prevHalf(e)];
  return orient(xy[2 * a], xy[2 * a + 1], xy[2 * b], xy[2 * b + 1], xy[2 * w], xy[2 * w + 1]) > 0;
}

/** What the refinement asks for: parts per interval, and each interval's half-edge on its inner side. */
interface Refinement {
  /** How many parts the interval from each sample should be split into. */
  pieces: Int32Array;
  /** Half-edge of the interval from each sample in the triangle on its inner side, or -1 where there is none. */
  where: Int32Array;
  /** Whether some interval to be split is missing from the triangulation. */
  missing: boolean;
}

/**
 * How many parts each boundary interval should be split into for the next pass (see the file comment),
 * or null when the sampling is fine as it is. In a constrained triangulation only the intervals whose
 * triangles changed are looked at, unless `all`.
 */
function refinement(m: Mesh, set: Settings, all: boolean): Refinement | null {
  const { sc } = m;
  const { xy, next } = m.s;
  const n = m.n;
  const pieces = i32(sc, I.PIECES, n).fill(1);
  const cc = new Float64Array(3);
  let any = false,
    missing = false;
  if (m.bnd && m.dirty) {
    // every interval has its triangle; after the first look, only those of changed triangles can ask for
    // more samples
    const { bnd, dirty } = m;
    for (let a = 0; a < n; a++) {
      const e = bnd[a];
      if (!all && !dirty[(e / 3) | 0]) continue;
      const k = split(m, a, e, set, cc);
      if (k > 1) {
        pieces[a] = k;
        any = true;
      }
    }
    dirty.fill(0, 0, m.nt);
    return any ? { pieces, where: bnd, missing } : null;
  }
  const where = i32(sc, I.WHERE, n).fill(-1);
  for (let e = 0; e < 3 * m.nt; e++) {
    const a = m.ivl[e];
    // only the triangle on the interval's inner side counts
    if (a < 0 || !innerSide(m, e, a)) continue;
    where[a] = e;
    const k = split(m, a, e, set, cc);
    if (k > 1) {
      pieces[a] = k;
      any = true;
    }
  }
  // intervals the triangulation lacks are halved until it conforms
  const minSplit = 2 * set.minSpacingUm;
  for (let a = 0; a < n; a++) {
    if (where[a] >= 0) continue;
    const b = next[a];
    if (hypot(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]) >= minSplit) {
      pieces[a] = 2;
      any = missing = true;
    }
  }
  return any ? { pieces, where, missing } : null;
}

/** Parts the interval from sample a should be split into, by its triangle on the inner side (half-edge e). */
function split(m: Mesh, a: number, e: number, set: Settings, cc: Float64Array): number {
  const t = (e / 3) | 0;
  if (m.bnd ? isFlat(m.s.xy, m.tri, t) : m.flat[t]) return 1;
  const { xy, next, prev } = m.s;
  const b = next[a],
    w = m.tri[prevHalf(e)];
  const ax = xy[2 * a],
    ay = xy[2 * a + 1],
    bx = xy[2 * b],
    by = xy[2 * b + 1],
    wx = xy[2 * w],
    wy = xy[2 * w + 1];
  const len = hypot(bx - ax, by - ay);
  if (len < 2 * set.minSpacingUm) return 1;
  let k = 1;
  // the opposite vertex sees the interval at an obtuse angle: the circumcentre is beyond the boundary
  if ((ax - wx) * (bx - wx) + (ay - wy) * (by - wy) <= 0) k = 2;
  // the local radius asks for closer samples (not at a corner's ear, whose radius is the spacing's)
  if (w !== prev[a] && w !== next[b] && circumcentre(xy, m.tri, t, cc)) {
    const target = Math.max(set.minSpacingUm, Math.min(set.sampleUm, SPACING_PER_RADIUS * cc[2]));
    if (len > target * 1.001) k = Math.max(k, Math.ceil(len / target));
  }
  return Math.min(k, Math.floor(len / set.minSpacingUm));
}

/**
 * Splits the intervals as the refinement asks, inserting the new samples into the triangulation (or
 * triangulating afresh where it lacks an interval to split). In delaunator's triangulation, an interval
 * whose half-edge a previous insertion has flipped is left for the next pass.
 */
function refine(m: Mesh, r: Refinement): Mesh {
  if (r.missing) return triangulate(splitRings(m, r.pieces), (m.n >> 2) + 16, m.sc);
  let more = 0;
  for (let a = 0; a < m.n; a++) more += r.pieces[a] - 1;
  makeRoom(m, more);
  const { pieces, where } = r;
  const n0 = m.n;
  for (let a = 0; a < n0; a++) {
    const k = pieces[a];
    if (k < 2) continue;
    const { xy, next, prev } = m.s;
    const e = m.bnd ? m.bnd[a] : where[a],
      b = next[a],
      u = m.tri[e],
      v = m.tri[nextHalf(e)];
    if (!((u === a && v === b) || (u === b && v === a))) continue;
    const x0 = xy[2 * a],
      y0 = xy[2 * a + 1],
      x1 = xy[2 * b],
      y1 = xy[2 * b + 1];
    // the new samples go in from e's far end (v) back towards its start (u): e keeps running from u to the
    // newest sample, the part still to split
    const fromB = v === b;
    let last = fromB ? b : a;
    for (let j = 1; j < k; j++) {
      const s = fromB ? k - j : j;
      const p = m.n++;
      xy[2 * p] = x0 + ((x1 - x0) * s) / k;
      xy[2 * p + 1] = y0 + ((y1 - y0) * s) / k;
      if (fromB) {
        next[p] = last;
        prev[last] = p;
        next[a] = p;
        prev[p] = a;
      } else {
        prev[p] = last;
        next[last] = p;
        prev[b] = p;
        next[p] = b;
      }
      splitEdge(m, e, p);
      last = p;
    }
  }
  if (!m.bnd) intervals(m);
  return m;
}

/**
 * Inside (1) or outside (2) for each triangle: seeded by the triangles on either side of the boundary
 * intervals and by hull edges, flooded across the other edges. Where the triangulation does not conform to
 * the boundary (the seeds disagree or some triangle is unreached), centroids are tested against the rings.
 * A constrained triangulation has only inside triangles.
 */
function classify(m: Mesh, rings: readonly Pt[][]): Uint8Array {
  const { sc } = m;
  const { xy } = m.s;
  const label = u8(sc, U.LABEL, m.nt);
  if (m.bnd) return label.fill(1);
  const queue = i32(sc, I.QUEUE, m.nt);
  let qn = 0,
    clash = false;
  const mark = (t: number, l: number): void => {
    if (label[t] === 0) {
      label[t] = l;
      queue[qn++] = t;
    } else if (label[t] !== l) clash = true;
  };
  for (let e = 0; e < 3 * m.nt; e++) {
    const a = m.ivl[e],
      t = Math.floor(e / 3);
    if (a >= 0) mark(t, innerSide(m, e, a) ? 1 : 2);
    else if (m.half[e] < 0) mark(t, 2);
  }
  for (let q = 0; q < qn; q++) {
    const t = queue[q];
    for (let k = 0; k < 3; k++) {
      const e = 3 * t + k,
        o = m.half[e];
      if (o >= 0 && m.ivl[e] < 0) mark(Math.floor(o / 3), label[t]);
    }
  }
  for (let t = 0; t < m.nt; t++) {
    if (label[t] !== 0 && !clash) continue;
    const a = m.tri[3 * t],
      b = m.tri[3 * t + 1],
      c = m.tri[3 * t + 2];
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
      const u = m.tri[e],
        v = m.tri[nextHalf(e)],
        w = m.tri[prevHalf(e)];
      const ux = xy[2 * u],
        uy = xy[2 * u + 1],
        vx = xy[2 * v],
        vy = xy[2 * v + 1];
      const sp = orient(ux, uy, vx, vy, px, py),
        sw = orient(ux, uy, vx, vy, xy[2 * w], xy[2 * w + 1]);
      if ((sp < 0 && sw > 0) || (sp > 0 && sw < 0)) {
        crossed = e;
        break;
      }
    }
    if (crossed < 0) return true;
    const o = m.half[crossed];
    if (o < 0 || (!m.bnd && m.ivl[crossed] >= 0)) return false;
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
  let d2 = Infinity;
  for (let k = 0; k < 3; k++) {
    const a = m.tri[3 * t + k],
      b = next[a],
      c = prev[a];
    const ax = xy[2 * a],
      ay = xy[2 * a + 1];
    d2 = Math.min(
      d2,
      segmentDistance2(px, py, ax, ay, xy[2 * b], xy[2 * b + 1]),
      segmentDistance2(px, py, xy[2 * c], xy[2 * c + 1], ax, ay),
    );
  }
  return Math.sqrt(d2);
}

/**
 * A strip's triangle (two corners a boundary interval, the third elsewhere on the boundary) has its
 * circumcentre (px, py) nearer the interval than the far side when the samples on the two sides are
 * staggered, by about s²/(8t) for spacing s and thickness t: the node is moved along the interval's normal
 * to where it is as far from the interval as from the far corner's boundary, into `centre`. False where this
 * does not apply (no interval, an ear, or a move of more than CENTRING_LIMIT).
 */
function centred(m: Mesh, t: number, px: number, py: number, centre: Float64Array): boolean {
  const { xy, next, prev } = m.s;
  for (let k = 0; k < 3; k++) {
    const u = m.tri[3 * t + k],
      v = m.tri[3 * t + ((k + 1) % 3)],
      w = m.tri[3 * t + ((k + 2) % 3)];
    let a = u,
      b = v;
    if (next[v] === u) {
      a = v;
      b = u;
    } else if (next[u] !== v) continue;
    if (w === next[b] || w === prev[a]) return false;
    // the interval a→b has the area on its left
    const ax = xy[2 * a],
      ay = xy[2 * a + 1],
      dx = xy[2 * b] - ax,
      dy = xy[2 * b + 1] - ay;
    const len = Math.sqrt(dx * dx + dy * dy);
    const nx = -dy / len,
      ny = dx / len;
    const db = (px - ax) * nx + (py - ay) * ny;
    const wx = xy[2 * w],
      wy = xy[2 * w + 1],
      pw = prev[w],
      nw = next[w];
    const dw = Math.sqrt(
      Math.min(
        segmentDistance2(px, py, xy[2 * pw], xy[2 * pw + 1], wx, wy),
        segmentDistance2(px, py, wx, wy, xy[2 * nw], xy[2 * nw + 1]),
      ),
    );
    const shift = (dw - db) / 2;
    if (!(db > 0) || Math.abs(shift) > CENTRING_LIMIT * db) return false;
    centre[0] = px + shift * nx;
    centre[1] = py + shift * ny;
    return true;
  }
  return false;
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
  // adaptive sampling: room for a quarter more samples from the refinement before the arrays grow
  const corners: number[][] = rings.map(() => []);
  const coords = rings.map((r, k) => sampleRing(r, set, corners[k]));
  let n = 0,
    positions = -2;
  for (const c of coords) n += c.length / 2;
  for (const r of rings) positions += r.length + 2;
  const extra = (n >> 2) + 16;
  let mesh = positions <= EAR_MAX ? constrained(coords, corners, extra, set.sc) : null;
  if (!mesh) mesh = triangulate(coords, extra, set.sc);
  for (let pass = 1; pass < MAX_PASSES && mesh.nt > 0; pass++) {
    const r = refinement(mesh, set, pass === 1);
    if (!r) break;
    mesh = refine(mesh, r);
  }
  if (mesh.nt === 0) return [];
  if (mesh.bnd) flats(mesh);
  const { nodes, paths, points } = axisGraph(mesh, classify(mesh, rings), rings);
  const chains = prune(paths, nodes, mesh.nt, set, points);
  return chainsOut(chains, points, nodes, mesh.nt, set);
}

/**
 * The axis graph of a classified triangulation: a node per inside triangle (its circumcentre, centred where
 * that applies, or its centroid where the circumcentre falls outside the area), links between inside
 * triangles sharing an edge that is not a boundary interval, with nodes closer than MERGE_UM merged; the
 * links joined into paths through nodes of degree two (as relink does); `points` are the nodes left without
 * any link.
 */
function axisGraph(
  mesh: Mesh,
  label: Uint8Array,
  rings: readonly Pt[][],
): { nodes: Nodes; paths: number[][]; points: Set<number> } {
  const { sc } = mesh;
  const { xy } = mesh.s;
  const nt = mesh.nt;
  const nodes: Nodes = { x: f64(sc, F.NX, nt), y: f64(sc, F.NY, nt), r: f64(sc, F.NR, nt) };
  const cc = new Float64Array(3),
    centre = new Float64Array(2);
  // slivers are left out of the graph by counting them as not inside from here on
  for (let t = 0; t < nt; t++) if (mesh.flat[t]) label[t] = 2;
  for (let t = 0; t < nt; t++) {
    if (label[t] !== 1) continue;
    let px: number, py: number;
    if (circumcentre(xy, mesh.tri, t, cc) && reaches(mesh, label, rings, t, cc[0], cc[1])) {
      px = cc[0];
      py = cc[1];
      if (centred(mesh, t, px, py, centre)) {
        px = centre[0];
        py = centre[1];
      }
    } else {
      const a = mesh.tri[3 * t],
        b = mesh.tri[3 * t + 1],
        c = mesh.tri[3 * t + 2];
      px = (xy[2 * a] + xy[2 * b] + xy[2 * c]) / 3;
      py = (xy[2 * a + 1] + xy[2 * b + 1] + xy[2 * c + 1]) / 3;
    }
    nodes.x[t] = px;
    nodes.y[t] = py;
    nodes.r[t] = boundaryDistance(mesh, t, px, py);
  }

  // links (each inside triangle has three at most, each found once); nodes of (nearly) co-circular samples
  // coincide and are merged (union-find, lowest index leads)
  const root = i32(sc, I.ROOT, nt);
  for (let t = 0; t < nt; t++) root[t] = t;
  const find = (t: number): number => findRoot(root, t);
  const ends = i32(sc, I.ENDS, 3 * nt);
  let ne = 0;
  let merged = false;
  for (let t = 0; t < nt; t++) {
    if (label[t] !== 1) continue;
    for (let k = 0; k < 3; k++) {
      const e = 3 * t + k,
        o = mesh.half[e];
      if (o < 0) continue;
      const u = (o / 3) | 0;
      if (u <= t || label[u] !== 1 || (!mesh.bnd && mesh.ivl[e] >= 0)) continue;
      ends[2 * ne] = t;
      ends[2 * ne + 1] = u;
      ne++;
      const dx = nodes.x[t] - nodes.x[u],
        dy = nodes.y[t] - nodes.y[u];
      if (dx * dx + dy * dy <= MERGE_UM * MERGE_UM) {
        merged = true;
        const ra = find(t),
          rb = find(u);
        if (ra < rb) root[rb] = ra;
        else if (rb < ra) root[ra] = rb;
      }
    }
  }
  if (merged) {
    let m = 0;
    for (let i = 0; i < ne; i++) {
      let a = find(ends[2 * i]),
        b = find(ends[2 * i + 1]);
      if (a === b) continue;
      if (a > b) [a, b] = [b, a];
      ends[2 * m] = a;
      ends[2 * m + 1] = b;
      m++;
    }
    ne = m;
  }

  // the links as paths, joined through nodes of degree two (the order relink gives): incidences per node
  // as 2 * link + (0 at its first end, 1 at its second), in link order
  const start = i32(sc, I.START, nt + 1);
  const fill = i32(sc, I.FILL, nt);
  let inc = incidences(ends, ne, nt, start, fill, sc);
  if (merged) {
    // two triangles share at most one edge, so only merged nodes can be linked twice: the later links
    // between the same two nodes go
    const dup = u8(sc, U.DUP, ne);
    let any = false;
    for (let v = 0; v < nt; v++) {
      for (let k = start[v]; k < start[v + 1]; k++) {
        const w = ends[inc[k] ^ 1];
        for (let j = start[v]; j < k; j++) {
          if (ends[inc[j] ^ 1] === w) {
            dup[inc[k] >> 1] = 1;
            any = true;
            break;
          }
        }
      }
    }
    if (any) {
      let m = 0;
      for (let i = 0; i < ne; i++) {
        if (dup[i]) continue;
        ends[2 * m] = ends[2 * i];
        ends[2 * m + 1] = ends[2 * i + 1];
        m++;
      }
      ne = m;
      inc = incidences(ends, ne, nt, start, fill, sc);
    }
  }
  const used = u8(sc, U.USED, ne);
  const freeAt = (v: number): number => unused(start, inc, used, v);
  const paths: number[][] = [];
  for (let v = 0; v < nt; v++) {
    const dv = start[v + 1] - start[v];
    if (dv === 0 || dv === 2) continue;
    for (let i = freeAt(v); i >= 0; i = freeAt(v)) {
      const path = [v];
      for (let cur = v, j = i; ; ) {
        used[j >> 1] = 1;
        cur = ends[j ^ 1];
        path.push(cur);
        if (start[cur + 1] - start[cur] !== 2) break;
        j = freeAt(cur);
        if (j < 0) break;
      }
      paths.push(path);
    }
  }
  for (let i = 0; i < ne; i++) {
    if (used[i]) continue;
    const first = ends[2 * i];
    const path = [first];
    for (let cur = first, j = 2 * i; ; ) {
      used[j >> 1] = 1;
      cur = ends[j ^ 1];
      path.push(cur);
      if (cur === first) break;
      j = freeAt(cur);
      if (j < 0) break;
    }
    paths.push(path);
  }
  const points = new Set<number>();
  for (let t = 0; t < nt; t++) if (label[t] === 1 && find(t) === t && start[t + 1] === start[t]) points.add(t);
  return { nodes, paths, points };
}

/**
 * Incidences of links (their two ends at ends[2i], ends[2i + 1]) per node, as 2 * link + (0 at its first
 * end, 1 at its second), in link order: node v's are inc[start[v]] .. inc[start[v + 1] - 1].
 */
function incidences(
  ends: Int32Array,
  ne: number,
  nt: number,
  start: Int32Array,
  fill: Int32Array,
  sc: MedialScratch,
): Int32Array {
  start.fill(0);
  for (let i = 0; i < 2 * ne; i++) start[ends[i] + 1]++;
  for (let v = 0; v < nt; v++) start[v + 1] += start[v];
  fill.set(start.subarray(0, nt));
  const inc = i32(sc, I.INC, 2 * ne);
  for (let i = 0; i < 2 * ne; i++) inc[fill[ends[i]]++] = i;
  return inc;
}

/** Union-find root of t (halving the path on the way). */
function findRoot(root: Int32Array, t: number): number {
  while (root[t] !== t) t = root[t] = root[root[t]];
  return t;
}

/** The first incidence at node v (inc[start[v]] ..) whose link (inc >> 1) is not used yet, or -1. */
function unused(start: Int32Array, inc: Int32Array, used: Uint8Array, v: number): number {
  for (let k = start[v]; k < start[v + 1]; k++) if (!used[inc[k] >> 1]) return inc[k];
  return -1;
}

// ---------------------------------------------------------------------------------------------------------
// Chains: paths of nodes between nodes of degree other than two

/** Degree of each node: how many path ends meet there. */
function degrees(sc: MedialScratch, paths: readonly number[][], n: number, slot: I = I.DEG): Int32Array {
  const deg = i32(sc, slot, n).fill(0);
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
function relink(sc: MedialScratch, paths: readonly number[][], n: number): number[][] {
  const deg = degrees(sc, paths, n, I.DEG3);
  // incidences per node, as 2 * path + (0 at its start, 1 at its end)
  const start = i32(sc, I.RSTART, n + 1);
  start[0] = 0;
  for (let v = 0; v < n; v++) start[v + 1] = start[v] + deg[v];
  const fill = i32(sc, I.RFILL, n);
  fill.set(start.subarray(0, n));
  const inc = i32(sc, I.RINC, start[n]);
  paths.forEach((p, i) => {
    inc[fill[p[0]]++] = 2 * i;
    inc[fill[p[p.length - 1]]++] = 2 * i + 1;
  });
  const used = u8(sc, U.RUSED, paths.length);
  const freeAt = (v: number): number => unused(start, inc, used, v);
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

function pathLengthUm(p: readonly number[], nodes: Nodes): number {
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
  const { sc } = set;
  for (;;) {
    const deg = degrees(sc, paths, n);
    const lengths = paths.map((p) => pathLengthUm(p, nodes));
    const drop = u8(sc, U.DROP, paths.length);

    // 1. short links between junctions
    let contracted = false;
    const alias = new Map<number, number>();
    const keeper = (v: number): number => {
      for (let a = alias.get(v); a !== undefined; a = alias.get(v)) v = a;
      return v;
    };
    paths.forEach((p, i) => {
      const a = keeper(p[0]),
        b = keeper(p[p.length - 1]);
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
      paths = relink(sc, kept, n);
      continue;
    }

    // 2. leaf branches into blunt corners; 3. short noise branches
    let removed = false;
    const shortest = new Map<number, number>();
    paths.forEach((p, i) => {
      const a = p[0],
        b = p[p.length - 1];
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
    const left = degrees(sc, kept, n, I.DEG2);
    paths.forEach((p, i) => {
      if (!drop[i]) return;
      for (const v of [p[0], p[p.length - 1]]) if (deg[v] >= 3 && left[v] === 0) points.add(v);
    });
    paths = relink(sc, kept, n);
  }
}

/** Growth of the radius per unit length over the first half of path p (of length len), from its start. */
function leafSlope(p: readonly number[], len: number, nodes: Nodes): number {
  if (!(len > 0)) return 0;
  const half = len / 2,
    r0 = nodes.r[p[0]];
  for (let k = 1, d = 0; k < p.length; k++) {
    const u = p[k - 1],
      v = p[k];
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
  const { sc } = set;
  const n = p.length;
  const dist = f64(sc, F.DIST, n);
  dist[0] = 0;
  for (let k = 1; k < n; k++)
    dist[k] = dist[k - 1] + hypot(nodes.x[p[k]] - nodes.x[p[k - 1]], nodes.y[p[k]] - nodes.y[p[k - 1]]);
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
  const deg = degrees(set.sc, paths, n);
  const out: MedialChain[] = [];
  for (let p of paths) {
    const a = p[0],
      b = p[p.length - 1];
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
    const c = finish(set.sc, p, closed, closed && deg[p[0]] > 2 ? p[0] : -1, nodes, set.toleranceUm);
    if (c) out.push(c);
  }
  for (const v of points)
    out.push({
      points: [{ x: round(nodes.x[v]), y: round(nodes.y[v]) }],
      radii: Float64Array.of(nodes.r[v]),
      closed: false,
    });
  return out;
}

const round = (v: number): number => Math.round(v) || 0;

/** Whether (ax, ay) comes before (bx, by): by x, then y. */
const before = (ax: number, ay: number, bx: number, by: number): boolean => ax < bx || (ax === bx && ay < by);

/**
 * One chain as output: canonical start and direction, simplified, rounded. `pin` is a node the
 * simplification must keep (the junction a cycle hangs on, where another chain ends), or -1.
 */
function finish(
  sc: MedialScratch,
  p: readonly number[],
  closed: boolean,
  pin: number,
  nodes: Nodes,
  tol: number,
): MedialChain | null {
  const n = p.length;
  // node order: open chains run from their lower end (by x, then y); cycles start at their lowest node and
  // run counter-clockwise
  const order = i32(sc, I.ORDER, n);
  for (let k = 0; k < n; k++) order[k] = p[k];
  if (closed) {
    let s = 0,
      area = 0;
    for (let k = 0; k < n; k++) {
      const a = p[k],
        b = p[(k + 1) % n];
      if (before(nodes.x[a], nodes.y[a], nodes.x[p[s]], nodes.y[p[s]])) s = k;
      area += nodes.x[a] * nodes.y[b] - nodes.x[b] * nodes.y[a];
    }
    for (let k = 0; k < n; k++) order[k] = p[area < 0 ? (s - k + n) % n : (s + k) % n];
  } else if (before(nodes.x[p[n - 1]], nodes.y[p[n - 1]], nodes.x[p[0]], nodes.y[p[0]])) order.reverse();
  // a cycle is simplified as a path from its start round to its start again
  const m = closed ? n + 1 : n;
  const xs = f64(sc, F.XS, m),
    ys = f64(sc, F.YS, m),
    rs = f64(sc, F.RS, m);
  for (let k = 0; k < m; k++) {
    const v = order[k % n];
    xs[k] = nodes.x[v];
    ys[k] = nodes.y[v];
    rs[k] = nodes.r[v];
  }
  // simplify between fixed nodes: the ends; for a cycle also the node farthest from its start, and the pin
  const keep = u8(sc, U.KEEP, m);
  keep[0] = keep[m - 1] = 1;
  if (closed) {
    let far = 0,
      fd = -1;
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
  const points: Pt[] = [],
    radii: number[] = [];
  for (let k = 0; k < n; k++) {
    if (!keep[k]) continue;
    const q = { x: round(xs[k]), y: round(ys[k]) };
    const last = points[points.length - 1];
    if (last && last.x === q.x && last.y === q.y) continue;
    points.push(q);
    radii.push(rs[k]);
  }
  if (
    closed &&
    points.length > 1 &&
    points[0].x === points[points.length - 1].x &&
    points[0].y === points[points.length - 1].y
  ) {
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
function simplify(
  xs: Float64Array,
  ys: Float64Array,
  rs: Float64Array,
  i0: number,
  i1: number,
  tol: number,
  keep: Uint8Array,
): void {
  const stack = [i0, i1];
  while (stack.length) {
    const b = stack.pop()!,
      a = stack.pop()!;
    if (b - a < 2) continue;
    const dx = xs[b] - xs[a],
      dy = ys[b] - ys[a],
      l2 = dx * dx + dy * dy;
    let worst = -1,
      err = tol;
    for (let k = a + 1; k < b; k++) {
      let t = l2 > 0 ? ((xs[k] - xs[a]) * dx + (ys[k] - ys[a]) * dy) / l2 : 0;
      t = t < 0 ? 0 : t > 1 ? 1 : t;
      const e = Math.max(
        hypot(xs[a] + t * dx - xs[k], ys[a] + t * dy - ys[k]),
        Math.abs(rs[a] + t * (rs[b] - rs[a]) - rs[k]),
      );
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
    const p = a.points[k],
      q = b.points[k];
    if (p.x !== q.x) return p.x - q.x;
    if (p.y !== q.y) return p.y - q.y;
  }
  if (a.points.length !== b.points.length) return a.points.length - b.points.length;
  return Number(a.closed) - Number(b.closed);
}
