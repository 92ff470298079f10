/**
 * Variable-width walls: lines whose width follows the part, so thin features print, walls never overlap and
 * no sliver too thin for a line is left between them.
 *
 * Per island, wall by wall from the outside in:
 * - wall k is a loop of the line width wherever the area still to fill (`inside`) is at least two line
 *   widths thick: its outer edge is the opening of `inside` by one width, its centreline half a width in;
 * - what that loop cannot reach (necks and strips of `inside` thinner than two widths: thin fins, the middle
 *   of a wall a little thicker than its loops) is the leftover of level k. Its medial axis (a centre line
 *   with the local half-thickness, medial-axis.ts) says what to do with it, point by point:
 *   - thinner than `minFeatureSize`: nothing prints there (reported as lost area when no wall is beside it);
 *   - thinner than the middle-line threshold and lying against wall k's loops: the walls beside it absorb
 *     it, each side's `wallDistributionCount` innermost walls widening by their share and moving towards it
 *     (as Arachne's distributed beading does), so a 1.0 mm wall prints as two 0.5 mm lines rather than two
 *     0.4 mm lines and a 0.2 mm one;
 *   - otherwise: one middle line along the medial axis, as wide as the strip there (clamped to the minimum
 *     and maximum bead width);
 * - after the last wall, pieces of the inner area thinner than one line all along are leftovers of the same
 *   kind, so skin and infill are left only areas they can fill.
 * Wedges and corners blunter than `wallTransitionAngle` get no middle line into their tip (their walls meet
 * there instead): the medial axis prunes such branches.
 */
import { area, boundsOf, difference, flatten, offset, pointInArea } from '../geometry/clip.js';
import { medialAxis, medialScratch, type MedialChain, type MedialScratch } from '../geometry/medial-axis.js';
import { PointGrid } from '../geometry/point-grid.js';
import { hypot, segmentDistance2, UM_PER_MM, type ExPolygon, type Polygon, type Pt } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import { stripWidthUm } from './strip-width.js';
import type { WallSet } from './types.js';
import { rings, type IslandWalls } from './walls.js';

/** Leftover pieces with less area than this (µm²) are specks: not worth a medial axis. */
const MIN_PIECE_AREA_UM2 = 20 * 20;
/** Leftover pieces inside the walls with less area than this (µm²) are left to the walls round them. */
const MIN_INNER_PIECE_AREA_UM2 = 100 * 100;
/**
 * Longest boundary sample spacing of the medial axis, µm: it refines the spacing itself to a fraction of
 * the local thickness, so thin strips get dense samples and this only bounds the wide parts.
 */
const AXIS_SAMPLE_UM = 200;
const AXIS_MIN_SAMPLE_UM = 30;
/** The loops' cover is grown by this much (µm) before the leftover is cut: the seams of offsets that do not quite meet are no feature. */
const SLIVER_UM = 20;
/** A strip narrower than this fraction of the line width is absorbed by the walls beside it, not given a line of its own. */
const MIDDLE_LINE_FRACTION = 0.75;
/** Loop edges longer than this (µm) are split before widening, so a widening follows the strip beside it. */
const WIDEN_STEP_UM = 250;

/** The resolved limits, µm, and the working memory of one call (one layer's walls). */
interface Limits {
  /** Line width. */
  w: number;
  minFeature: number;
  minBead: number;
  maxBead: number;
  /** Strips at least this thick get a middle line; thinner ones next to a wall widen it. */
  middle: number;
  /** Middle lines shorter than this are not started. */
  minLength: number;
  pruneAngleDeg: number;
  /** Walls on each side that share a strip's width. */
  distribution: number;
  /** The medial axis's working memory, for every leftover piece of the call's islands. */
  axis: MedialScratch;
}

function limitsOf(cfg: Config, w: number, axis: MedialScratch): Limits {
  const nozzle = cfg.nozzleDiameter * UM_PER_MM;
  const minFeature = (cfg.minFeatureSize / 100) * nozzle;
  const minBead = Math.max(minFeature, (cfg.minBeadWidth / 100) * nozzle);
  return {
    w,
    minFeature,
    minBead,
    maxBead: Math.max(minBead, (cfg.maxBeadWidth / 100) * nozzle),
    middle: Math.max(minFeature, MIDDLE_LINE_FRACTION * w),
    minLength: (cfg.wallTransitionLength / 100) * nozzle,
    pruneAngleDeg: cfg.wallTransitionAngle,
    distribution: cfg.wallDistributionCount,
    axis,
  };
}

/** A point of a leftover's medial axis that the walls beside it absorb. */
interface Absorbed {
  x: number;
  y: number;
  /** Half the strip's thickness there, µm. */
  r: number;
}

/** An absorbed point as one wall sees it: `j` walls out from the strip, sharing it among `c` walls. */
interface Share extends Absorbed {
  j: number;
  c: number;
}

/** The absorbed points a level's loops look up, with their grid (ids are indices into `shares`). */
interface Shares {
  grid: PointGrid;
  shares: Share[];
}

/** A middle line: open or closed, with a width per point (µm). */
interface Bead {
  points: Pt[];
  widths: number[];
  closed: boolean;
}

/** What one level's leftover becomes: middle lines, points the loops absorb, and area lost. */
interface LeftoverResult {
  beads: Bead[];
  absorbed: Absorbed[];
  lostUm2: number;
}

/** Distance from (x, y) to the nearest point of the rings, µm, if within `reach`; else Infinity. */
function nearRings(x: number, y: number, loops: readonly Polygon[], reach: number): number {
  let best2 = reach * reach;
  let found = false;
  for (const ring of loops) {
    for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
      const a = ring[j],
        b = ring[i];
      // cheap box rejection
      if (
        Math.min(a.x, b.x) - reach > x ||
        Math.max(a.x, b.x) + reach < x ||
        Math.min(a.y, b.y) - reach > y ||
        Math.max(a.y, b.y) + reach < y
      )
        continue;
      const d2 = segmentDistance2(x, y, a.x, a.y, b.x, b.y);
      if (d2 <= best2) {
        best2 = d2;
        found = true;
      }
    }
  }
  return found ? Math.sqrt(best2) : Infinity;
}

/** Whether a strip's axis point `p` of half-thickness `r` lies against one of the loops (about half a line plus r away). */
function besideLoops(p: Pt, r: number, loops: readonly Polygon[], L: Limits): boolean {
  return loops.length > 0 && nearRings(p.x, p.y, loops, r + L.w / 2 + L.w / 4) < Infinity;
}

/**
 * The leftover of one level: each medial-axis point is printed as a middle line, absorbed by the loops
 * beside it (`loops`, the level's wall centrelines, when it lies against them), or lost.
 */
function leftover(
  pieces: readonly ExPolygon[],
  loops: readonly Polygon[],
  band: readonly Polygon[],
  L: Limits,
): LeftoverResult {
  const out: LeftoverResult = { beads: [], absorbed: [], lostUm2: 0 };
  // inside the walls, a piece this small is a corner's crumb: what it would add to a wall is not worth its axis
  const least = loops.length ? MIN_INNER_PIECE_AREA_UM2 : MIN_PIECE_AREA_UM2;
  let real = pieces.filter((p) => Math.abs(area([p])) >= least);
  if (real.length === 0) return out;
  if (loops.length) real = absorbThin(real, L, out);
  for (const piece of real) {
    // samples about a third of the piece's typical thickness apart: most pieces need no second pass
    const sampleUm = Math.max(AXIS_MIN_SAMPLE_UM, Math.min(AXIS_SAMPLE_UM, stripWidthUm(piece) / 3));
    for (const chain of medialAxis([piece], { pruneAngleDeg: L.pruneAngleDeg, sampleUm, scratch: L.axis })) {
      if (chain.points.length === 1) speck(piece, chain, loops, L, out);
      else classify(chain, loops, band, L, out);
    }
  }
  return out;
}

/**
 * Inside the walls, the pieces thinner everywhere than a middle line need no medial axis: the walls beside
 * them take them whole. Their boundary points stand for the axis (the loops look up the nearest one, on the
 * side facing them), each with the piece's mean half-thickness. Returns the pieces that need the axis.
 */
function absorbThin(pieces: ExPolygon[], L: Limits, out: LeftoverResult): ExPolygon[] {
  // one offset for all the pieces: what survives shrinking by half a middle line is where one could go
  const cores = offset(pieces, -L.middle / 2);
  const thick = new Uint8Array(pieces.length);
  const boxes = pieces.map((p) => boundsOf([p]));
  for (const core of cores) {
    const q = core.outer[0];
    for (let i = 0; i < pieces.length; i++) {
      const b = boxes[i];
      if (q.x < b.minX || q.x > b.maxX || q.y < b.minY || q.y > b.maxY || !pointInArea(q, pieces[i])) continue;
      thick[i] = 1;
      break;
    }
  }
  const rest: ExPolygon[] = [];
  for (let i = 0; i < pieces.length; i++) {
    if (thick[i]) {
      rest.push(pieces[i]);
      continue;
    }
    const r = stripWidthUm(pieces[i]) / 2;
    for (const ring of [pieces[i].outer, ...pieces[i].holes]) {
      for (const p of subdivide(ring, WIDEN_STEP_UM)) out.absorbed.push({ x: p.x, y: p.y, r });
    }
  }
  return rest;
}

/**
 * A compact piece whose axis is one point (a small square, a pin): absorbed by the walls beside it, else a
 * loop half its thickness wide, a quarter of it in from its edge (the two passes cover it), else lost.
 */
function speck(piece: ExPolygon, chain: MedialChain, loops: readonly Polygon[], L: Limits, out: LeftoverResult): void {
  const p = chain.points[0],
    r = chain.radii[0];
  const g = 2 * r;
  if (besideLoops(p, r, loops, L)) {
    out.absorbed.push({ x: p.x, y: p.y, r });
    return;
  }
  if (g >= L.minFeature) {
    const bead = beadWidthUm(g / 2, L);
    const ring = offset([piece], -Math.min(bead / 2, r / 2));
    if (ring.length && ring[0].outer.length >= 3) {
      out.beads.push({ points: ring[0].outer, widths: ring[0].outer.map(() => bead), closed: true });
      return;
    }
  }
  out.lostUm2 += Math.abs(area([piece]));
}

const PRINT = 1,
  ABSORB = 2,
  LOST = 0;

/** Medial-axis edges are split into pieces no longer than this (µm), so a line starts where the strip gets thick enough. */
const AXIS_STEP_UM = 100;

/** The chain with its edges split every AXIS_STEP_UM at most, radii interpolated. */
function resample(chain: MedialChain): { points: Pt[]; radii: number[]; closed: boolean } {
  const { points, radii, closed } = chain;
  const n = points.length;
  const pts: Pt[] = [];
  const rs: number[] = [];
  const edges = closed ? n : n - 1;
  for (let e = 0; e < edges; e++) {
    const a = points[e],
      b = points[(e + 1) % n];
    const ra = radii[e],
      rb = radii[(e + 1) % n];
    const parts = Math.max(1, Math.ceil(dist(a, b) / AXIS_STEP_UM));
    for (let k = 0; k < parts; k++) {
      pts.push(
        k === 0
          ? a
          : { x: Math.round(a.x + ((b.x - a.x) * k) / parts), y: Math.round(a.y + ((b.y - a.y) * k) / parts) },
      );
      rs.push(ra + ((rb - ra) * k) / parts);
    }
  }
  if (!closed) {
    pts.push(points[n - 1]);
    rs.push(radii[n - 1]);
  }
  return { points: pts, radii: rs, closed };
}

function classify(
  chain: MedialChain,
  loops: readonly Polygon[],
  band: readonly Polygon[],
  L: Limits,
  out: LeftoverResult,
): void {
  const { points, radii, closed } = resample(chain);
  const n = points.length;
  if (n < 2) return;
  const kind = new Uint8Array(n);
  for (let i = 0; i < n; i++) {
    const g = 2 * radii[i];
    // thinner than a middle line (or than anything printable) with a wall beside it: the wall takes it
    if (g < L.middle && besideLoops(points[i], radii[i], loops, L)) kind[i] = ABSORB;
    else kind[i] = g < L.minFeature ? LOST : PRINT;
  }
  const edges = closed ? n : n - 1;
  for (let i = 0; i < n; i++)
    if (kind[i] === ABSORB) out.absorbed.push({ x: points[i].x, y: points[i].y, r: radii[i] });
  // lost area: edges with both ends lost
  for (let e = 0; e < edges; e++) {
    const a = e,
      b = (e + 1) % n;
    if (kind[a] === LOST && kind[b] === LOST) out.lostUm2 += dist(points[a], points[b]) * (radii[a] + radii[b]);
  }
  // runs of printed points become middle lines
  const all = kind.every((k) => k === PRINT);
  if (all && closed) {
    out.beads.push(
      simplifyBead(
        points.slice(),
        radii.map((r) => beadWidthUm(2 * r, L)),
        true,
      ),
    );
    return;
  }
  // start a closed chain's walk at a point that is not printed, so no run is split across its end
  let start = 0;
  if (closed) while (start < n && kind[start] === PRINT) start++;
  let run: number[] = [];
  const flush = () => {
    if (run.length >= 2) {
      const pts = run.map((k) => points[k]);
      let len = 0;
      for (let k = 1; k < pts.length; k++) len += dist(pts[k - 1], pts[k]);
      if (len >= L.minLength || touchesEnd(run, n, closed)) {
        if (band.length && !closed) {
          if (run[0] === 0) pts[0] = joinBand(pts[1], pts[0], radii[0], band, L);
          if (run[run.length - 1] === n - 1)
            pts[pts.length - 1] = joinBand(pts[pts.length - 2], pts[pts.length - 1], radii[n - 1], band, L);
        }
        out.beads.push(
          simplifyBead(
            pts,
            run.map((k) => beadWidthUm(2 * radii[k], L)),
            false,
          ),
        );
      } else
        for (let k = 1; k < run.length; k++)
          out.lostUm2 += dist(points[run[k - 1]], points[run[k]]) * (radii[run[k - 1]] + radii[run[k]]);
    }
    run = [];
  };
  const steps = closed ? n + 1 : n;
  for (let s = 0; s < steps; s++) {
    const k = (start + s) % n;
    if (kind[k] === PRINT) run.push(k);
    else flush();
  }
  flush();
}

/**
 * The end `b` of a middle line coming from `a`, moved on along the line when it stops against the loops'
 * cover (a fin standing off a wall): on to the cover's edge, so its round end overlaps the loop's bead by its
 * radius and the two bond with no pocket between them. A free end (a fin's tip) stays.
 */
function joinBand(a: Pt, b: Pt, r: number, band: readonly Polygon[], L: Limits): Pt {
  if (nearRings(b.x, b.y, band, r + SLIVER_UM + L.w / 10) === Infinity) return b;
  const d = dist(a, b);
  if (d === 0) return b;
  const by = r + SLIVER_UM;
  return { x: Math.round(b.x + ((b.x - a.x) / d) * by), y: Math.round(b.y + ((b.y - a.y) / d) * by) };
}

/** A middle line's points may leave the line by this much (µm) and its widths by this much (µm) when simplified. */
const BEAD_TOL_UM = 5;
const BEAD_WIDTH_TOL_UM = 5;
/** Widths of a segment's two ends differ by at most this (µm): the firmware lays a segment at one width. */
const BEAD_WIDTH_STEP_UM = 20;

/**
 * A middle line with the points it does not need (Douglas–Peucker over position and width together: a point
 * goes when it lies within BEAD_TOL_UM of the line between the points kept round it, and its width within
 * BEAD_WIDTH_TOL_UM of the width interpolated there). The axis was resampled finely to find where lines start.
 */
function simplifyBead(points: Pt[], widths: number[], closed: boolean): Bead {
  const n = points.length;
  if (n < 3) return { points, widths, closed };
  const keep = new Uint8Array(n);
  const last = closed ? n : n - 1;
  keep[0] = 1;
  keep[last % n] = 1;
  // a closed line is split at its first point and the point farthest from it
  const stack: [number, number][] = [];
  if (closed) {
    let far = 1,
      fd = -1;
    for (let i = 1; i < n; i++) {
      const d = dist(points[0], points[i]);
      if (d > fd) {
        fd = d;
        far = i;
      }
    }
    keep[far] = 1;
    stack.push([0, far], [far, n]);
  } else stack.push([0, n - 1]);
  while (stack.length) {
    const [a, b] = stack.pop()!;
    if (b - a < 2) continue;
    const pa = points[a],
      pb = points[b % n];
    const wa = widths[a],
      wb = widths[b % n];
    const dx = pb.x - pa.x,
      dy = pb.y - pa.y;
    const len2 = dx * dx + dy * dy;
    let worst = -1,
      at = -1;
    for (let i = a + 1; i < b; i++) {
      const p = points[i];
      const t = len2 > 0 ? Math.max(0, Math.min(1, ((p.x - pa.x) * dx + (p.y - pa.y) * dy) / len2)) : 0;
      const off = Math.hypot(pa.x + t * dx - p.x, pa.y + t * dy - p.y) / BEAD_TOL_UM;
      const wOff = Math.abs(wa + t * (wb - wa) - widths[i]) / BEAD_WIDTH_TOL_UM;
      const e = Math.max(off, wOff);
      if (e > worst) {
        worst = e;
        at = i;
      }
    }
    // a segment prints at one width (its E is spread evenly along it): no segment spans more than one step
    if (worst <= 1 && Math.abs(wb - wa) > BEAD_WIDTH_STEP_UM) {
      worst = 2;
      at = (a + b) >> 1;
    }
    if (worst > 1) {
      keep[at] = 1;
      stack.push([a, at], [at, b]);
    }
  }
  const pts: Pt[] = [],
    ws: number[] = [];
  for (let i = 0; i < n; i++) {
    if (!keep[i]) continue;
    pts.push(points[i]);
    ws.push(widths[i]);
  }
  return { points: pts, widths: ws, closed };
}

/** A run that reaches an open chain's end is a whole thin feature's line: kept however short. */
function touchesEnd(run: readonly number[], n: number, closed: boolean): boolean {
  return !closed && (run[0] === 0 || run[run.length - 1] === n - 1);
}

function beadWidthUm(g: number, L: Limits): number {
  return g < L.minBead ? L.minBead : g > L.maxBead ? L.maxBead : g;
}

function dist(a: Pt, b: Pt): number {
  return hypot(a.x - b.x, a.y - b.y);
}

/**
 * Loops of the line width that absorb the strips beside them. A strip 2r thick is shared by the c walls
 * nearest it on each side (wallDistributionCount, at most as many as there are): each widens by r / c, and
 * each moves towards the strip by what the walls outside it gained plus half its own gain, so the outer
 * surface stays where it is. A loop point takes the share of the absorbed point nearest it, when that point
 * lies where a strip beside this wall would be. Long edges are split first so the widening follows the
 * strip. Returns the loops and their widths (null for a loop that absorbs nothing).
 */
function widenLoops(
  loops: readonly Polygon[],
  found: Shares | null,
  L: Limits,
  reach: number,
): { paths: Polygon[]; widths: (Float64Array | null)[] } {
  if (!found) return { paths: loops.slice(), widths: loops.map(() => null) };
  const { grid, shares } = found;
  const paths: Polygon[] = [];
  const widths: (Float64Array | null)[] = [];
  for (const loop of loops) {
    const dense = subdivide(loop, WIDEN_STEP_UM);
    const ws = new Float64Array(dense.length);
    let any = false;
    const moved: Pt[] = new Array(dense.length);
    for (let i = 0; i < dense.length; i++) {
      const p = dense[i];
      const id = grid.nearest(p.x, p.y, reach);
      const q = id >= 0 ? shares[id] : null;
      // the strip lies against this wall when its axis is about half a line plus its half-thickness away
      const d = q ? Math.sqrt((q.x - p.x) ** 2 + (q.y - p.y) ** 2) : Infinity;
      if (q && d <= L.w / 2 + q.j * L.w + q.r + L.w / 4) {
        const shift = Math.min(((2 * (q.c - 1 - q.j) + 1) * q.r) / (2 * q.c), d);
        moved[i] =
          d > 0
            ? { x: Math.round(p.x + ((q.x - p.x) / d) * shift), y: Math.round(p.y + ((q.y - p.y) / d) * shift) }
            : p;
        ws[i] = (L.w + q.r / q.c) / UM_PER_MM;
        any = true;
      } else {
        moved[i] = p;
        ws[i] = L.w / UM_PER_MM;
      }
    }
    if (!any) {
      paths.push(loop);
      widths.push(null);
      continue;
    }
    const kept = dropStraight(moved, ws);
    paths.push(kept.points);
    widths.push(kept.widths);
  }
  return { paths, widths };
}

/** Points closer than this (µm) to the line through their neighbours, with a width within WIDTH_TOL_MM of theirs interpolated, add nothing. */
const STRAIGHT_TOL_UM = 3;
const WIDTH_TOL_MM = 0.002;

/** A loop without the points that lie on the straight line between their neighbours at the width between theirs. */
function dropStraight(points: Polygon, widths: Float64Array): { points: Polygon; widths: Float64Array } {
  const n = points.length;
  if (n < 4) return { points, widths };
  const keep = new Uint8Array(n).fill(1);
  let prev = n - 1;
  for (let i = 0; i < n; i++) {
    const next = (i + 1) % n;
    const a = points[prev],
      b = points[i],
      c = points[next];
    const dx = c.x - a.x,
      dy = c.y - a.y;
    const len = Math.sqrt(dx * dx + dy * dy);
    if (len > 0) {
      const off = Math.abs((b.x - a.x) * dy - (b.y - a.y) * dx) / len;
      const t = ((b.x - a.x) * dx + (b.y - a.y) * dy) / (len * len);
      const w = widths[prev] + t * (widths[next] - widths[prev]);
      // (and the segment left would not span more than one width step: it prints at one width)
      if (
        off <= STRAIGHT_TOL_UM &&
        t > 0 &&
        t < 1 &&
        Math.abs(w - widths[i]) <= WIDTH_TOL_MM &&
        Math.abs(widths[next] - widths[prev]) * UM_PER_MM <= BEAD_WIDTH_STEP_UM
      ) {
        keep[i] = 0;
        continue;
      }
    }
    prev = i;
  }
  const pts: Pt[] = [];
  const ws: number[] = [];
  for (let i = 0; i < n; i++) {
    if (!keep[i]) continue;
    pts.push(points[i]);
    ws.push(widths[i]);
  }
  return { points: pts, widths: Float64Array.from(ws) };
}

/** The ring with edges longer than `step` split evenly. */
function subdivide(ring: Polygon, step: number): Polygon {
  const out: Pt[] = [];
  for (let i = 0; i < ring.length; i++) {
    const a = ring[i],
      b = ring[(i + 1) % ring.length];
    out.push(a);
    const len = dist(a, b);
    const parts = Math.ceil(len / step);
    for (let k = 1; k < parts; k++)
      out.push({ x: Math.round(a.x + ((b.x - a.x) * k) / parts), y: Math.round(a.y + ((b.y - a.y) * k) / parts) });
  }
  return out;
}

/** One wall level of an island. */
interface Level {
  /** Wall k's loops (centrelines). */
  loops: Polygon[];
  /** Middle lines inside wall k - 1 (wall k's own index). */
  beads: Bead[];
  /** Points of strips beside these loops, which they absorb. */
  absorbed: Absorbed[];
  lostUm2: number;
}

/** Level k's leftover: its middle lines go to level k, what wall k - 1's loops absorb to level k - 1. */
function takeLeftover(
  levels: Level[],
  k: number,
  rest: readonly ExPolygon[],
  band: readonly ExPolygon[],
  L: Limits,
): void {
  const outer = k > 0 ? levels[k - 1] : null;
  const left = leftover(rest, outer ? outer.loops : [], flatten(band), L);
  levels[k].beads.push(...left.beads);
  levels[k].lostUm2 += left.lostUm2;
  if (outer) outer.absorbed.push(...left.absorbed);
}

/** The walls of one island. */
function islandWalls(island: ExPolygon, wallCount: number, L: Limits): IslandWalls {
  const w = L.w;
  const walls: WallSet[] = [];
  let lostUm2 = 0;
  let inside: ExPolygon[] = [island];
  /** Each level's loops (centrelines), the middle lines of its leftover, and the strips its loops absorb. */
  const levels: Level[] = [];
  for (let k = 0; k < wallCount && inside.length > 0; k++) {
    const fit = offset(inside, -w);
    // what the loops cover, grown by a sliver so the seams of offsets that do not quite meet are no leftover
    const band = fit.length ? offset(fit, w + SLIVER_UM) : [];
    const loops = fit.length ? rings(offset(fit, w / 2)) : [];
    // what wall k's loops cannot reach lies between the sides of wall k - 1 (or is the part's outside)
    levels.push({ loops, beads: [], absorbed: [], lostUm2: 0 });
    const rest = band.length ? difference(inside, band) : inside;
    if (rest.length) takeLeftover(levels, k, rest, band, L);
    inside = fit;
  }
  // pieces of the inner area thinner than a line all along (the middle of a wall a little thicker than its
  // loops) are the last walls' to fill, not skin's or infill's: their mean width tells them, no boolean needed
  if (inside.length && levels.length) {
    const thin: ExPolygon[] = [];
    const kept: ExPolygon[] = [];
    for (const piece of inside) (stripWidthUm(piece) < w ? thin : kept).push(piece);
    if (thin.length) {
      levels.push({ loops: [], beads: [], absorbed: [], lostUm2: 0 });
      takeLeftover(levels, levels.length - 1, thin, [], L);
      inside = kept;
    }
  }
  for (const level of levels) lostUm2 += level.lostUm2;
  const levelCount = levels.length;
  levels.forEach((level, k) => {
    // the strips this level's loops share: its own (j = 0) and those of the next c - 1 levels inwards
    let found: Shares | null = null;
    let reach = 0;
    for (let j = 0; j < L.distribution && k + j < levelCount; j++) {
      const c = Math.min(L.distribution, k + j + 1);
      for (const p of levels[k + j].absorbed) {
        found ??= { grid: new PointGrid(w), shares: [] };
        found.grid.add(p.x, p.y);
        found.shares.push({ x: p.x, y: p.y, r: p.r, j, c });
        reach = Math.max(reach, w / 2 + j * w + p.r + w / 4);
      }
    }
    if (level.loops.length) {
      const { paths, widths } = widenLoops(level.loops, found, L, reach);
      walls.push({ role: 'wall', wall: k, closed: true, paths, widths: widths.some((x) => x) ? widths : null });
    }
    const open = level.beads.filter((b) => !b.closed);
    const closedBeads = level.beads.filter((b) => b.closed);
    const toMm = (b: Bead) => Float64Array.from(b.widths, (x) => x / UM_PER_MM);
    // a middle line of the first level is the part's outside: the outer wall
    const wall = Math.min(k, wallCount - 1);
    if (open.length)
      walls.push({ role: 'wall', wall, closed: false, paths: open.map((b) => b.points), widths: open.map(toMm) });
    if (closedBeads.length)
      walls.push({
        role: 'wall',
        wall,
        closed: true,
        paths: closedBeads.map((b) => b.points),
        widths: closedBeads.map(toMm),
      });
  });
  return { outline: island, walls, inner: inside, lostMm2: lostUm2 / (UM_PER_MM * UM_PER_MM) };
}

/**
 * Variable-width walls of each island (see the file's comment).
 * @param scratch the medial axis's working memory: the caller's, to reuse over its layers (one slice's range), or
 *   the call's own
 */
export function variableWalls(
  islands: readonly ExPolygon[],
  cfg: Config,
  lineWidthUm: number,
  scratch: MedialScratch = medialScratch(),
): IslandWalls[] {
  const L = limitsOf(cfg, lineWidthUm, scratch);
  return islands.map((island) => islandWalls(island, cfg.wallCount, L));
}
