/**
 * How much of a wall's line hangs over nothing (dynamic overhang speeds), as areas: a line `w` wide whose
 * centreline lies `s` out from the layer below's edge (negative: inside it) has (s + w/2) / w of its width over
 * nothing. So a quarter of it or more where the centreline is beyond the layer below shrunk by w/4, half
 * beyond the layer below itself, three quarters beyond it grown by w/4, and all of it beyond it grown by w/2
 * (IslandRegions.unsupported, as PrusaSlicer and CuraEngine mark overhanging walls). The planner prints each
 * level at its own speed; the paths stage splits the walls where they cross from one level's area to the next.
 */
import { difference, offset } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';

/** The layer below as measured for levels 1 to 3 (shrunk by a quarter width, as it is, grown by a quarter), each made when first asked for. */
export class BelowLevels {
  readonly #below: readonly ExPolygon[];
  readonly #q: number;
  readonly #made: (ExPolygon[] | undefined)[] = [];

  constructor(below: readonly ExPolygon[], lineWidthUm: number) {
    this.#below = below;
    this.#q = lineWidthUm / 4;
  }

  /** The layer below as measured for level k (1 to 3). */
  at(k: 1 | 2 | 3): readonly ExPolygon[] {
    if (k === 2) return this.#below;
    return (this.#made[k] ??= offset(this.#below, k === 1 ? -this.#q : this.#q));
  }
}

/**
 * The areas of an island's outline where a wall's centreline has a quarter, half and three quarters of its line
 * or more over nothing (levels 1 to 3), or null where there are none.
 */
export function overhangLevels(outline: ExPolygon, measured: BelowLevels, lineWidthUm: number): ExPolygon[][] | null {
  // An outline within a quarter width of the layer below all round (level 3 empty, and so level 4) leaves no
  // wall a quarter of its line over nothing: the outer wall's centreline is half a width in. Most islands stop
  // here, at one clip, which the slivers slicing leaves between an outline and the one below do not survive.
  // (Beads under half a width wide, whose centreline comes closer to the edge, are not graded there.)
  const l3 = difference([outline], measured.at(3));
  if (l3.length === 0) return null;
  // Level 1 is measured inside the outline shrunk by a quarter width: along a vertical side the outline less
  // the layer below shrunk by a quarter is a band a quarter wide at the edge, where no wall's centreline runs.
  // Without that band the paths stage would test every wall edge against it.
  const l1 = difference(offset([outline], -lineWidthUm / 4), measured.at(1));
  const l2 = difference([outline], measured.at(2));
  return [l1, l2, l3];
}
