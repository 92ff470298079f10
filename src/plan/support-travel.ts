/**
 * Travels between support that need no retraction (as CuraEngine's "limit support retractions", on by
 * default there too): a straight travel from support to support on one layer strings, if at all, inside
 * the support, which comes off anyway. It still retracts where the line would pass over the part: across
 * an island of this layer (printed after the support) or of the layer below (whose top would show the
 * string), or along one without crossing its edge.
 */
import { AreaIndex } from '../geometry/area-index.js';
import type { ExPolygon, Pt } from '../geometry/types.js';

/** The part's islands of a layer and the one below, for asking whether a straight travel stays off them. */
export class PartGuard {
  /** One index per layer's islands (each layer's islands lie apart, so its index's even-odd test is theirs). */
  readonly #layers: AreaIndex[];

  /** `layers`: the islands of each layer the travel must keep off (this layer's, the one below's). */
  constructor(layers: readonly (readonly ExPolygon[])[]) {
    this.#layers = layers.filter((l) => l.length > 0).map((l) => new AreaIndex(l));
  }

  /** Whether the straight line from a to b stays clear of every island (neither crosses nor lies over one). */
  clear(a: Pt, b: Pt): boolean {
    // with no edge crossed the whole line lies inside an island or outside it, as its middle does (taken to
    // the whole µm: the index's point queries run on integers, as the part's points are)
    const x = Math.round((a.x + b.x) / 2),
      y = Math.round((a.y + b.y) / 2);
    for (let i = 0; i < this.#layers.length; i++) {
      const ix = this.#layers[i];
      if (ix.crosses(a.x, a.y, b.x, b.y) || ix.contains(x, y)) return false;
    }
    return true;
  }
}
