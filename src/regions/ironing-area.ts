/**
 * Where a region of an island irons (RegionFill.ironing). The top surface of an island is its outline less
 * the object's section on the layer above (nothing is printed on it), walls included, as CuraEngine and
 * PrusaSlicer find it. By the region's ironingType:
 * - `top`: the top surface, on every layer that has one;
 * - `topmost`: the same, only on the object's last layer with material (the caller decides which that is);
 * - `all`: the top surface and every skin of the region (top skin under the surface, bottom skin); where the
 *   region's inside is skin throughout, the whole island, walls included (OrcaSlicer's "all solid").
 * Within the region's piece of the island, half a line width in from the island's edge (so the nozzle does
 * not push a bead over it), and never over air (a bridge's skin would sag under the nozzle).
 */
import { difference, intersection, offset, union } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import type { RegionFill } from './types.js';

/** The island the regions of which iron: its outline and its top surface. */
export interface IroningIsland {
  outline: ExPolygon;
  /** The outline less the object's section on the layer above, µm. */
  topSurface: ExPolygon[];
}

/**
 * The area a region irons.
 * @param piece the region's part of the island (null: the whole island)
 * @param solid the region's inside (within the walls) is skin throughout, no sparse infill
 * @param insetUm distance kept from the island's edge, µm
 */
export function ironingArea(
  type: Config['ironingType'],
  island: IroningIsland,
  piece: readonly ExPolygon[] | null,
  fill: RegionFill,
  solid: boolean,
  insetUm: number,
): ExPolygon[] {
  let area: ExPolygon[];
  if (type === 'all' && solid) area = piece ? piece.slice() : [island.outline];
  else {
    area = piece && island.topSurface.length ? intersection(island.topSurface, piece) : island.topSurface;
    if (type === 'all') {
      const skin =
        fill.topSkin.length && fill.bottomSkin.length
          ? union(fill.topSkin, fill.bottomSkin)
          : fill.topSkin.length
            ? fill.topSkin
            : fill.bottomSkin;
      if (skin.length) area = area.length ? union(area, skin) : skin;
    }
  }
  if (area.length === 0) return [];
  area = intersection(area, offset([island.outline], -insetUm));
  if (area.length && fill.bridge.length) area = difference(area, fill.bridge);
  return area;
}
