/**
 * Pockets, for tree support in 'everywhere' placement: overhang pieces a tree holds no better than a straight
 * column, which get the column normal support would give them while the tree holds the rest:
 * - pieces with no room under them for a tip that is to reach the bed (the top of a recess in a wall, a
 *   band of overhang right above a wall): such a tip is pushed out beside the piece and down to the bed,
 *   carrying the roof from outside, where a column needs only to reach what is below it;
 * - pieces whose column ends within POCKET_MAX_MM below them (it stands on the part, or the part closes in
 *   on it): a branch there is no shorter than the column and cannot be thinner than a tip.
 * In 'buildPlate' placement there are none: a column there must reach the bed, which the tree does better.
 * Nor with no roof (supportInterfaceLayers 0), where the tips hold the part themselves, 1.5 mm apart.
 */
import { area, boundsOf, difference, offset, union } from '../geometry/clip.js';
import { UM_PER_MM, type Bounds, type ExPolygon, type Pt } from '../geometry/types.js';
import type { SupportAreas } from '../regions/types.js';
import { printable, type ModelLayers } from './model-layers.js';
import { EXPAND_WIDTHS } from './normal.js';
import { meetsAny } from './tree-draw.js';
import type { AreaIndex } from '../geometry/area-index.js';

/** An overhang piece whose column ends within this height (mm) below it is a pocket. */
export const POCKET_MAX_MM = 4;
/** Room for a tip under a piece: where a tip's centre may be, at least a square this many tip radii a side. */
const ROOM_SIDE_TIP_RADII = 0.5;

/** Each layer's overhang split into what the tree holds and the pockets' columns. */
export interface Pockets {
  /** Per layer m, the overhang left to the tree's tips and roof. */
  overhangs: ExPolygon[][];
  /** Per layer j, the pockets' columns, [] on most layers. */
  columns: ExPolygon[][];
}

/** What finding pockets reads. */
export interface PocketModel {
  model: ModelLayers;
  /** Where no support may be on layer j. */
  collision: (j: number) => ExPolygon[];
  /** collision(j) as a point index. */
  collisionIndex: (j: number) => AreaIndex;
  /** Where a tip's centre may not be on layer j if it is to reach the bed. */
  avoidance: (j: number) => ExPolygon[];
  /** A tip's radius, µm. */
  tipRUm: number;
}

/**
 * Split every layer's overhang into pockets and the rest (all of it the rest in 'buildPlate' placement or with
 * no roof); yields per layer with overhang.
 */
export function* findPockets(src: PocketModel, overhangs: readonly ExPolygon[][]): Generator<void, Pockets> {
  const { model } = src;
  const n = model.count;
  const columns: ExPolygon[][] = [];
  for (let j = 0; j < n; j++) columns.push([]);
  // with no roof the tips hold the part themselves, touching it: a column's sparse lines would not
  if (model.cfg.supportPlacement !== 'everywhere' || model.cfg.supportInterfaceLayers === 0)
    return { overhangs: overhangs.slice(), columns };
  const kept: ExPolygon[][] = [];
  for (let m = 0; m < n; m++) {
    const over = overhangs[m];
    if (over.length === 0 || model.supportTop(m) < 0) {
      kept.push(over);
      continue;
    }
    const rest: ExPolygon[] = [];
    for (const piece of over) {
      const column = pocketColumn(src, piece, m);
      if (column) addColumn(columns, column, model.supportTop(m));
      else rest.push(piece);
    }
    kept.push(rest.length === over.length ? over : rest);
    yield;
  }
  return { overhangs: kept, columns };
}

function addColumn(columns: ExPolygon[][], column: readonly ExPolygon[][], top: number): void {
  for (let k = 0; k < column.length; k++) for (const a of column[k]) columns[top - k].push(a);
}

/**
 * The column under overhang piece `piece` of layer m, from the top Z gap down, as normal support prints it
 * (cut to what a line prints; what it leaves is carried on down), when the piece is a pocket; else null.
 */
export function pocketColumn(src: PocketModel, piece: ExPolygon, m: number): ExPolygon[][] | null {
  const { model, collision } = src;
  const cfg = model.cfg;
  const w = model.widthUm;
  const top = model.supportTop(m);
  const tipLayer = top - cfg.supportInterfaceLayers;
  const box = boundsOf([piece]);
  const roomless = tipLayer >= 0 && !hasRoom(src, piece, tipLayer);
  // how far down a column that ends makes a pocket (the whole way when no tip can reach the bed)
  const zTop = model.layers[m].z * UM_PER_MM;
  let lowest = top;
  if (roomless) lowest = 0;
  else while (lowest > 0 && zTop - model.layers[lowest - 1].z * UM_PER_MM <= POCKET_MAX_MM * UM_PER_MM) lowest--;
  if (!roomless && !partNear(model, box, top, lowest - 1 - model.bottomGap(lowest))) return null;
  let s: ExPolygon[] = offset([piece], EXPAND_WIDTHS * w);
  if (!roomless && survives(src, s, top, lowest)) return null;
  const out: ExPolygon[][] = [];
  for (let j = top; j >= lowest; j--) {
    const blocked = collision(j);
    if (blocked.length) s = difference(s, blocked);
    // the bottom Z gap: no support in the layers right above the part
    const bottom = model.bottomGap(j);
    const under = bottom > 0 && s.length ? model.sectionsBetween(j, -bottom, -1) : [];
    if (under.length) s = difference(s, under);
    if (s.length === 0) return out.map((a) => printable(a, w));
    out.push(s);
  }
  // a column that reaches the bed is a pocket only when no tip from under the piece could
  return roomless ? out.map((a) => printable(a, w)) : null;
}

/** At most this many corners of a column's outline (and the midpoints of the edges after them) are tried by `survives`. */
const SURVIVOR_SAMPLES = 16;

/**
 * Whether a corner or edge midpoint of the column (at its top) stays free of the collision and the part under it on
 * every layer from `top` down to `lowest`: then the column cannot end there (what it loses it loses for good),
 * and the booleans need not be run to know it.
 */
function survives(src: PocketModel, column: readonly ExPolygon[], top: number, lowest: number): boolean {
  for (const a of column) if (cornerSurvives(src, a.outer, top, lowest)) return true;
  return false;
}

/** Whether a corner or an edge's midpoint of `ring` survives (see survives). */
function cornerSurvives(src: PocketModel, ring: readonly Pt[], top: number, lowest: number): boolean {
  const step = Math.max(1, Math.floor(ring.length / SURVIVOR_SAMPLES));
  for (let i = 0; i < ring.length; i += step) {
    const a = ring[i],
      b = ring[(i + 1) % ring.length];
    if (pointSurvives(src, a.x, a.y, top, lowest) || pointSurvives(src, (a.x + b.x) / 2, (a.y + b.y) / 2, top, lowest))
      return true;
  }
  return false;
}

function pointSurvives(src: PocketModel, x: number, y: number, top: number, lowest: number): boolean {
  const { model } = src;
  for (let j = top; j >= lowest; j--) {
    if (src.collisionIndex(j).contains(x, y)) return false;
    const bottom = model.bottomGap(j);
    for (let k = Math.max(0, j - bottom); k < j; k++) if (model.sectionIndex(k).contains(x, y)) return false;
  }
  return true;
}

/** Whether any layer from `from` down to `to` has part within the bounds `box`. */
function partNear(model: ModelLayers, box: Bounds, from: number, to: number): boolean {
  for (let k = from; k >= Math.max(0, to); k--) if (meetsAny(box, model.sectionBoxes(k))) return true;
  return false;
}

/** Whether a tip under `piece` on layer j may reach the bed: its centre outside the avoidance. */
function hasRoom(src: PocketModel, piece: ExPolygon, j: number): boolean {
  const avoid = src.avoidance(j);
  const free = avoid.length ? difference([piece], avoid) : [piece];
  return area(free) >= (ROOM_SIDE_TIP_RADII * src.tipRUm) ** 2;
}

/**
 * Layer j's pocket columns as support areas: off the tree's own areas `tree`, cut to what a line prints; their
 * body printed as normal support's.
 */
export function pocketAreas(
  model: ModelLayers,
  j: number,
  columns: readonly ExPolygon[],
  tree: readonly ExPolygon[],
): SupportAreas | null {
  if (columns.length === 0) return null;
  let s = union(columns);
  if (tree.length) s = difference(s, tree);
  s = printable(s, model.widthUm);
  if (s.length === 0) return null;
  const split = model.split(j, s);
  return { ...split, whole: s, columnBody: split.body };
}
