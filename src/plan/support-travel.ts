/**
 * Travels between support that need no retraction (as CuraEngine's "limit support retractions", on by
 * default there too): a straight travel from support to support on one layer strings, if at all, inside
 * the support, which comes off anyway. It still retracts where the line would pass over the part: across
 * an island of this layer (printed after the support) or of the layer below (whose top would show the
 * string), or along one without crossing its edge.
 */
import { pointInArea } from '../geometry/clip.js';
import { ringBounds, segmentsMeet } from '../geometry/contain.js';
import type { Bounds, ExPolygon, Pt } from '../geometry/types.js';

interface GuardArea {
  area: ExPolygon;
  box: Bounds;
  rings: { ring: readonly Pt[]; box: Bounds }[];
}

/** The part's islands of a layer and the one below, for asking whether a straight travel stays off them. */
export class PartGuard {
  readonly #areas: GuardArea[];

  constructor(areas: readonly ExPolygon[]) {
    this.#areas = areas.map((area) => {
      const rings = [area.outer, ...area.holes].map((ring) => ({ ring, box: ringBounds(ring) }));
      return { area, box: rings[0].box, rings };
    });
  }

  /** Whether the straight line from a to b stays clear of every island (neither crosses nor lies over one). */
  clear(a: Pt, b: Pt): boolean {
    const minX = Math.min(a.x, b.x), maxX = Math.max(a.x, b.x), minY = Math.min(a.y, b.y), maxY = Math.max(a.y, b.y);
    for (const g of this.#areas) {
      const box = g.box;
      if (box.maxX < minX || box.minX > maxX || box.maxY < minY || box.minY > maxY) continue;
      for (const { ring, box: rb } of g.rings) {
        if (rb.maxX < minX || rb.minX > maxX || rb.maxY < minY || rb.minY > maxY) continue;
        for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
          if (segmentsMeet(a.x, a.y, b.x, b.y, ring[j].x, ring[j].y, ring[i].x, ring[i].y)) return false;
        }
      }
      // no edge crossed: the whole line is inside the island or outside it, as its middle is
      if (pointInArea({ x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 }, g.area)) return false;
    }
    return true;
  }
}
