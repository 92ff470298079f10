/**
 * Tree support from nodes to areas: each branch's cross-section as a circle, with the roof under the
 * overhang, kept off the part; the roof only where branches (or, in 'everywhere' placement, the part)
 * below hold it. Most cross-sections are lone circles known to be clear of the part: those are taken as
 * they are, and only the rest (overlapping circles, roofs, circles that may touch the part) go through
 * the clipper.
 */
import { boundsOf, difference, intersection, offset, union, unionRings } from '../geometry/clip.js';
import { hypot, type Bounds, type ExPolygon, type Polygon } from '../geometry/types.js';
import { regularPolygon, type RegularPolygon } from '../geometry/regular-polygon.js';
import { MIN_SUPPORT_WIDTHS, printable } from './model-layers.js';
import { AreaIndex } from '../geometry/area-index.js';
import { FixedPointGrid } from '../geometry/point-grid.js';
import { ITEMS_PER_STEP } from './tree-nodes.js';

/**
 * Largest gap between a drawn circle's edge and the true circle, µm. A tenth of a millimetre off a branch is
 * nothing to the support it gives, and coarser circles are fewer and longer moves: at 50 µm (and eight sides
 * at least) BridgeTest's tree support was 40 k moves, 11 k of them shorter than 0.3 mm, all planned, estimated
 * and written (G-code 89.6 k lines, 79.7 k at 100 µm and six sides).
 */
export const CIRCLE_TOLERANCE_UM = 100;

/** How many sides a drawn circle of radius r has (chords within CIRCLE_TOLERANCE_UM of the true circle). */
export function circleSides(r: number): number {
  const half = Math.acos(Math.max(-1, 1 - CIRCLE_TOLERANCE_UM / Math.max(r, CIRCLE_TOLERANCE_UM)));
  return Math.max(6, Math.min(64, Math.ceil(Math.PI / half)));
}

/** A circle as a counter-clockwise polygon inside the true circle (chords within CIRCLE_TOLERANCE_UM). */
export function circle(x: number, y: number, r: number): Polygon {
  return regularPolygon(x, y, r, circleSides(r));
}

export interface Disc {
  x: number;
  y: number;
  r: number;
  /** Known to lie clear of the collision (its centre is outside the collision grown by at least r). */
  clear: boolean;
}

export interface DrawLayer {
  /** Branch cross-sections, µm. */
  discs: readonly Disc[];
  /** The roof wanted on this layer (already off the part). */
  roof: readonly ExPolygon[];
  /** What lies under this layer and may carry a roof: last layer's support (and the part, in 'everywhere'); null on the bed. */
  base: readonly ExPolygon[] | null;
  /** How far from what lies under it a roof may reach, µm. */
  roofReachUm: number;
  /** Where no support may be. */
  collision: readonly ExPolygon[];
  /** The part within the bottom gap below ('everywhere' placement): support is cut away from it too. */
  gapBelow: readonly ExPolygon[];
  /** `gapBelow` as a point index, asked for only when a branch comes near it. */
  gapIndex: () => AreaIndex;
  /** Support line width, µm. */
  widthUm: number;
}

const meets = (a: Bounds, b: Bounds) => a.minX <= b.maxX && a.maxX >= b.minX && a.minY <= b.maxY && a.maxY >= b.minY;

/** Whether `box` meets the bounds of any of `boxes`. */
export function meetsAny(box: Bounds, boxes: readonly Bounds[]): boolean {
  for (let i = 0; i < boxes.length; i++) if (meets(box, boxes[i])) return true;
  return false;
}

/** `a` less `b`, running the clipper only on the islands of a whose bounds meet an island of b. */
export function cutAway(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[] {
  if (a.length === 0 || b.length === 0) return a.slice();
  const boxes = b.map((x) => boundsOf([x]));
  const near: ExPolygon[] = [],
    far: ExPolygon[] = [];
  for (const x of a) (meetsAny(boundsOf([x]), boxes) ? near : far).push(x);
  return near.length ? [...difference(near, b), ...far] : far;
}

/** A roof island no wider than this many reaches is kept or dropped whole. */
const WHOLE_ROOF_REACHES = 2;

/**
 * The part of the roof that what lies under it (within `reach`) can carry: small roof islands (the steps of
 * a sloping overhang) whole when anything is within reach, larger ones cut to the reach of what is under them.
 */
export function carried(roof: readonly ExPolygon[], base: readonly ExPolygon[], reach: number): ExPolygon[] {
  if (base.length === 0) return [];
  const baseBoxes = base.map((x) => boundsOf([x]));
  const index = new AreaIndex(base);
  const out: ExPolygon[] = [];
  const large: ExPolygon[] = [];
  for (const r of roof) {
    const b = boundsOf([r]);
    const grown = { minX: b.minX - reach, minY: b.minY - reach, maxX: b.maxX + reach, maxY: b.maxY + reach };
    if (!meetsAny(grown, baseBoxes)) continue;
    if (Math.max(b.maxX - b.minX, b.maxY - b.minY) > WHOLE_ROOF_REACHES * reach) large.push(r);
    else if (index.meets(r) || r.outer.some((p) => index.edgeWithin(p.x, p.y, reach))) out.push(r);
  }
  if (large.length) {
    const boxes = large
      .map((x) => boundsOf([x]))
      .map((b) => ({ minX: b.minX - reach, minY: b.minY - reach, maxX: b.maxX + reach, maxY: b.maxY + reach }));
    const under = base.filter((_, i) => meetsAny(baseBoxes[i], boxes));
    if (under.length) for (const a of intersection(large, offset(under, reach))) out.push(a);
  }
  return out;
}

/** One layer's support area: printable islands, and for each the circle it draws when it is a lone one. */
export interface DrawnLayer {
  areas: ExPolygon[];
  circles: (RegularPolygon | null)[];
}

/** What drawing a layer's clusters keeps between its steps. */
interface Drawing {
  d: DrawLayer;
  roofIndex: AreaIndex | null;
  onPart: (c: Disc) => boolean;
  /** Narrowest printable branch radius, µm. */
  minR: number;
  /** Islands taken as they are, and for each its circle when it is a lone one. */
  free: ExPolygon[];
  circles: (RegularPolygon | null)[];
  /** Circles of overlapping free clusters, united at each step's end. */
  freeRings: Polygon[];
  /** Circles to be cut to what may and can be printed. */
  rest: Polygon[];
  /** Cross-sections since the last step. */
  count: number;
}

function keep(w: Drawing, a: ExPolygon, c: RegularPolygon | null): void {
  w.free.push(a);
  w.circles.push(c);
}

/**
 * Draw clusters from `g` on, and stop before the first that brings the count of cross-sections to
 * ITEMS_PER_STEP (counted once: `counted` when cluster g already was), after uniting the free clusters so far;
 * returns that cluster's index, or the number of clusters at the end. A plain function, which the engine
 * optimises (a generator's own loop runs unoptimised).
 */
function drawClusters(w: Drawing, groups: readonly Disc[][], g: number, counted: boolean): number {
  const d = w.d;
  for (; g < groups.length; g++) {
    const cluster = groups[g];
    if (!counted && (w.count += cluster.length) >= ITEMS_PER_STEP) {
      // the overlapping free clusters so far in one union (clusters do not meet: each merges on its own)
      if (w.freeRings.length) for (const a of unionRings(w.freeRings.splice(0))) keep(w, a, null);
      w.count = 0;
      return g;
    }
    counted = false;
    let fine = true;
    for (let k = 0; k < cluster.length && fine; k++) {
      const c = cluster[k];
      fine =
        c.clear &&
        c.r >= w.minR &&
        Math.PI * c.r * c.r >= d.widthUm * d.widthUm &&
        !w.roofIndex?.meetsDisc(c.x, c.y, c.r) &&
        !w.onPart(c);
    }
    if (cluster.length === 1) {
      // a lone branch (most of them): its circle as it is
      const c = cluster[0];
      const ring = circle(c.x, c.y, c.r);
      if (fine) keep(w, { outer: ring, holes: [] }, { x: c.x, y: c.y, r: c.r, sides: ring.length });
      else w.rest.push(ring);
      continue;
    }
    // a circle inside another of its cluster adds nothing to their union
    let left = 0,
      last = cluster[0];
    for (let k = 0; k < cluster.length; k++) {
      if (insideAnother(cluster[k], cluster)) continue;
      left++;
      last = cluster[k];
    }
    if (fine && left === 1) {
      // the others all inside one: that one is a lone circle
      const ring = circle(last.x, last.y, last.r);
      keep(w, { outer: ring, holes: [] }, { x: last.x, y: last.y, r: last.r, sides: ring.length });
      continue;
    }
    const into = fine ? w.freeRings : w.rest;
    for (let k = 0; k < cluster.length; k++) {
      const c = cluster[k];
      if (!insideAnother(c, cluster)) into.push(circle(c.x, c.y, c.r));
    }
  }
  return g;
}

/** One layer's support area, printable; yields every ITEMS_PER_STEP cross-sections. */
export function* drawLayer(d: DrawLayer): Generator<void, DrawnLayer> {
  let roof: ExPolygon[] = d.roof.slice();
  if (roof.length && d.base) roof = carried(roof, d.base, d.roofReachUm);
  const gapBoxes = d.gapBelow.map((x) => boundsOf([x]));
  let gapIndex: AreaIndex | null = null;
  const onPart = (c: Disc) =>
    meetsAny({ minX: c.x - c.r, minY: c.y - c.r, maxX: c.x + c.r, maxY: c.y + c.r }, gapBoxes) &&
    (gapIndex ??= d.gapIndex()).meetsDisc(c.x, c.y, c.r);
  // clusters of overlapping circles clear of the collision, printable, and touching neither the roof nor
  // the part below need only their union; the rest are cut to what may and can be printed
  const w: Drawing = {
    d,
    roofIndex: roof.length ? new AreaIndex(roof) : null,
    onPart,
    minR: (MIN_SUPPORT_WIDTHS * d.widthUm) / 2,
    free: [],
    circles: [],
    freeRings: [],
    rest: [],
    count: 0,
  };
  const groups = clusters(d.discs);
  for (let g = drawClusters(w, groups, 0, false); g < groups.length; g = drawClusters(w, groups, g, true)) yield;
  const { free, circles, freeRings, rest } = w;
  if (freeRings.length) for (const a of unionRings(freeRings)) keep(w, a, null);
  if (rest.length === 0 && roof.length === 0) return { areas: free, circles };
  const branches = rest.length ? unionRings(rest) : [];
  let s = branches.length && roof.length ? union(branches, roof) : branches.length ? branches : roof;
  for (const b of [d.collision, d.gapBelow]) if (s.length && b.length) s = cutAway(s, b);
  for (const a of printable(s, d.widthUm)) keep(w, a, null);
  return { areas: free, circles };
}

/** Whether disc c lies inside a wider disc of its cluster. */
function insideAnother(c: Disc, cluster: readonly Disc[]): boolean {
  for (let k = 0; k < cluster.length; k++) {
    const o = cluster[k];
    if (o !== c && o.r > c.r && hypot(o.x - c.x, o.y - c.y) + c.r <= o.r) return true;
  }
  return false;
}

/** The discs in groups that overlap (each group in the discs' order, groups by their first disc). */
export function clusters(discs: readonly Disc[]): Disc[][] {
  const widest = discs.reduce((w, c) => Math.max(w, c.r), 0);
  const xs = new Float64Array(discs.length),
    ys = new Float64Array(discs.length);
  for (let i = 0; i < discs.length; i++) {
    xs[i] = discs[i].x;
    ys[i] = discs[i].y;
  }
  const grid = new FixedPointGrid(xs, ys, Math.max(1000, 2 * widest));
  const root = discs.map((_, i) => i);
  const find = (i: number): number => {
    while (root[i] !== i) i = root[i] = root[root[i]];
    return i;
  };
  const found: number[] = [];
  for (let i = 0; i < discs.length; i++) {
    const c = discs[i];
    // the groups do not depend on the order the overlaps are found in (a group's root is its first disc)
    const count = grid.near(c.x, c.y, c.r + widest, found);
    for (let f = 0; f < count; f++) {
      const k = found[f];
      if (k <= i || hypot(discs[k].x - c.x, discs[k].y - c.y) > c.r + discs[k].r) continue;
      const a = find(i),
        b = find(k);
      if (a !== b) root[Math.max(a, b)] = Math.min(a, b);
    }
  }
  const groups = new Map<number, Disc[]>();
  const out: Disc[][] = [];
  for (let i = 0; i < discs.length; i++) {
    const r = find(i);
    let g = groups.get(r);
    if (!g) {
      groups.set(r, (g = []));
      out.push(g);
    }
    g.push(discs[i]);
  }
  return out;
}
