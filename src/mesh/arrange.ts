/**
 * Arranging objects on the bed without overlap, by their footprints (bounding rectangles, mm):
 * the largest first, each at the free spot nearest the bed centre, next to what is placed already.
 * One object alone goes to the bed centre, where `strata slice` puts a model.
 */
import { LENGTH_EPS_MM } from '../geometry/tolerances.js';

/** What arranging knows of an object: the size of its bounding rectangle on the bed. */
export interface Footprint {
  /** Size in X and Y, mm. */
  width: number;
  depth: number;
}

/** The bed's rectangle, to arrange on. */
export interface Bed {
  /** Centre of the bed, mm (bed coordinates). */
  center: [number, number];
  width: number;
  depth: number;
}

/** A footprint where it stands: its middle on the bed, mm. */
export interface PlacedFootprint extends Footprint {
  center: [number, number];
}

/** Gap kept between arranged objects, mm. */
export const ARRANGE_GAP_MM = 5;

function overlaps(a: PlacedFootprint, b: PlacedFootprint, gap: number): boolean {
  return (
    Math.abs(a.center[0] - b.center[0]) < (a.width + b.width) / 2 + gap - LENGTH_EPS_MM &&
    Math.abs(a.center[1] - b.center[1]) < (a.depth + b.depth) / 2 + gap - LENGTH_EPS_MM
  );
}

function insideBed(f: PlacedFootprint, bed: Bed): boolean {
  return (
    Math.abs(f.center[0] - bed.center[0]) <= (bed.width - f.width) / 2 + LENGTH_EPS_MM &&
    Math.abs(f.center[1] - bed.center[1]) <= (bed.depth - f.depth) / 2 + LENGTH_EPS_MM
  );
}

/** Spots for `f` beside each placed footprint (touching edges aligned or centred), and the bed centre. */
function candidates(f: Footprint, placed: readonly PlacedFootprint[], bed: Bed, gap: number): Array<[number, number]> {
  const out: Array<[number, number]> = [bed.center];
  for (const p of placed) {
    const dx = (p.width + f.width) / 2 + gap,
      dy = (p.depth + f.depth) / 2 + gap;
    const ax = (p.width - f.width) / 2,
      ay = (p.depth - f.depth) / 2;
    for (const sx of [-1, 1])
      for (const y of [p.center[1], p.center[1] - ay, p.center[1] + ay]) out.push([p.center[0] + sx * dx, y]);
    for (const sy of [-1, 1])
      for (const x of [p.center[0], p.center[0] - ax, p.center[0] + ax]) out.push([x, p.center[1] + sy * dy]);
  }
  return out;
}

/**
 * A free spot for `f` among `placed`, nearest the bed centre; null when there is none on the bed.
 */
export function findSpot(
  f: Footprint,
  placed: readonly PlacedFootprint[],
  bed: Bed,
  gap = ARRANGE_GAP_MM,
): [number, number] | null {
  let best: [number, number] | null = null;
  let bestD = Infinity;
  for (const c of candidates(f, placed, bed, gap)) {
    const here = { ...f, center: c };
    if (!insideBed(here, bed) || placed.some((p) => overlaps(here, p, gap))) continue;
    const d = Math.hypot(c[0] - bed.center[0], c[1] - bed.center[1]);
    if (d < bestD - LENGTH_EPS_MM) {
      bestD = d;
      best = c;
    }
  }
  return best;
}

/**
 * Centres for every footprint (in input order): largest first, each at the free spot nearest the
 * bed centre. A footprint with no free spot goes to the bed centre (and so overlaps: the caller warns).
 */
export function arrange(items: readonly Footprint[], bed: Bed, gap = ARRANGE_GAP_MM): Array<[number, number]> {
  return arrangeWith(items, bed, gap, true)!;
}

/** As `arrange`, but null when a footprint finds no free spot (the models do not fit together). */
export function arrangeAll(
  items: readonly Footprint[],
  bed: Bed,
  gap = ARRANGE_GAP_MM,
): Array<[number, number]> | null {
  return arrangeWith(items, bed, gap, false);
}

function arrangeWith(
  items: readonly Footprint[],
  bed: Bed,
  gap: number,
  fallBack: boolean,
): Array<[number, number]> | null {
  const order = items
    .map((_, i) => i)
    .sort((a, b) => items[b].width * items[b].depth - items[a].width * items[a].depth || a - b);
  const placed: PlacedFootprint[] = [];
  const out: Array<[number, number]> = new Array(items.length);
  for (const i of order) {
    const spot = findSpot(items[i], placed, bed, gap) ?? (fallBack ? bed.center : null);
    if (spot === null) return null;
    out[i] = spot;
    placed.push({ ...items[i], center: spot });
  }
  return out;
}

/** Whether two placed footprints overlap (touching is fine). */
export function footprintsOverlap(a: PlacedFootprint, b: PlacedFootprint): boolean {
  return overlaps(a, b, 0);
}
