/**
 * Two rules of the planner's travels (layer-plan.ts):
 * - `zHopOnlyOverParts`: a retracted travel lifts only when its route passes over an island of the layer
 *   printed before it, other than the one the nozzle leaves (the island it goes to is not printed yet);
 *   "over" is any point of the route inside the island's outline and outside its holes.
 * - `retractionCountMax`: at most that many retractions within any `retractionExtrusionWindow` mm of
 *   extruded filament (Cura's retraction_count_max and retraction_extrusion_window); the planner keeps
 *   the filament extruded at each retraction and asks `RetractionWindow.full` before a travel that stays
 *   inside the island retracts. Every retraction counts, the ones it cannot skip too.
 */
import { pointInRing, ringBounds, segmentsMeet } from '../geometry/contain.js';
import type { Bounds, ExPolygon, Pt } from '../geometry/types.js';

/** An island printed on this layer, with its outline's bounding box. */
export interface PrintedIsland {
  area: ExPolygon;
  bounds: Bounds;
}

export function printedIsland(area: ExPolygon): PrintedIsland {
  return { area, bounds: ringBounds(area.outer) };
}

function insideArea(p: Pt, area: ExPolygon): boolean {
  if (!pointInRing(p, area.outer)) return false;
  for (const h of area.holes) if (pointInRing(p, h)) return false;
  return true;
}

function segmentCrossesRing(a: Pt, b: Pt, ring: readonly Pt[]): boolean {
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    if (segmentsMeet(a.x, a.y, b.x, b.y, ring[j].x, ring[j].y, ring[i].x, ring[i].y)) return true;
  }
  return false;
}

/** Whether segment ab has a point over `island` (inside its outline, outside its holes). */
export function segmentOverIsland(a: Pt, b: Pt, island: PrintedIsland): boolean {
  const bb = island.bounds;
  if (
    Math.max(a.x, b.x) < bb.minX ||
    Math.min(a.x, b.x) > bb.maxX ||
    Math.max(a.y, b.y) < bb.minY ||
    Math.min(a.y, b.y) > bb.maxY
  )
    return false;
  if (insideArea(a, island.area) || insideArea(b, island.area)) return true;
  // both ends outside the area: the segment is over it only if it crosses one of its rings
  if (segmentCrossesRing(a, b, island.area.outer)) return true;
  for (const h of island.area.holes) if (segmentCrossesRing(a, b, h)) return true;
  return false;
}

/** Whether the route from `from` through `points` passes over any of `islands` but `except`. */
export function routeOverIslands(
  from: Pt,
  points: readonly Pt[],
  islands: readonly PrintedIsland[],
  except: ExPolygon | null,
): boolean {
  for (const island of islands) {
    if (island.area === except) continue;
    let a = from;
    for (const b of points) {
      if (segmentOverIsland(a, b, island)) return true;
      a = b;
    }
  }
  return false;
}

/** The filament extruded at the latest retractions, for retractionCountMax. */
export class RetractionWindow {
  /** Filament extruded so far, mm. */
  extruded = 0;
  /** `extruded` at each retraction counted, oldest first (at most `countMax` kept). */
  private readonly at: number[] = [];

  constructor(
    private readonly countMax: number,
    private readonly window: number,
  ) {}

  /** Whether `countMax` retractions already happened within the last `window` mm of filament (0: never). */
  full(): boolean {
    if (this.countMax <= 0 || this.at.length < this.countMax) return false;
    return this.extruded < this.at[0]! + this.window;
  }

  /** A retraction happens now. */
  add(): void {
    if (this.countMax <= 0) return;
    this.at.push(this.extruded);
    if (this.at.length > this.countMax) this.at.shift();
  }
}
