/**
 * Travels between support that need no retraction (as CuraEngine's "limit support retractions", on by
 * default there too): a straight travel from support to support on one layer strings, if at all, inside
 * the support, which comes off anyway. It still retracts where the line would pass over the part: across
 * an island of this layer (printed after the support) or of the layer below (whose top would show the
 * string), or along one without crossing its edge.
 */
import { AreaIndex } from '../geometry/area-index.js';
import { boundsOf, pointInArea } from '../geometry/clip.js';
import type { Bounds, ExPolygon, Pt } from '../geometry/types.js';

/** The part's islands of a layer and the one below, for asking whether a straight travel stays off them. */
export class PartGuard {
  readonly #areas: readonly ExPolygon[];
  readonly #boxes: Bounds[];
  /** Every edge of the islands, for crossing tests. */
  readonly #edges: AreaIndex;

  constructor(areas: readonly ExPolygon[]) {
    this.#areas = areas;
    this.#boxes = areas.map((a) => boundsOf([a]));
    this.#edges = new AreaIndex(areas);
  }

  /** Whether the straight line from a to b stays clear of every island (neither crosses nor lies over one). */
  clear(a: Pt, b: Pt): boolean {
    if (this.#edges.crosses(a.x, a.y, b.x, b.y)) return false;
    // no edge crossed: the whole line is inside an island or outside it, as its middle is
    const x = (a.x + b.x) / 2, y = (a.y + b.y) / 2;
    for (let i = 0; i < this.#areas.length; i++) {
      const box = this.#boxes[i];
      if (x < box.minX || x > box.maxX || y < box.minY || y > box.maxY) continue;
      if (pointInArea({ x, y }, this.#areas[i])) return false;
    }
    return true;
  }
}
