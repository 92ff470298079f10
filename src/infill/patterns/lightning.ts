/**
 * Lightning: trees that hold up top skins and nothing else. `prepare` walks the layers from the top down
 * (see lightning-forest.ts): where a top skin sits directly above a layer (`supportNeeded`), new branches
 * are grown from the walls so every point of it is within the support radius of a branch; going down,
 * tips retract by h·tan(40°) per layer (each branch stays within a 40° overhang of the one above), crooked
 * branches straighten by up to h·tan(40°) per layer, and branches leaving the region are cut and grounded
 * on the walls again. Layers with no top surface above them anywhere print nothing.
 *
 * The support radius is half the seed's lightning spacing (2·w/density), i.e. w/density: right under a
 * skin the branches are about as far apart as the lines of `lines` infill at that density, and they thin
 * out quickly below; the density actually printed is reported by the tests and is far below the setting.
 * Without `prepared` (a single layer on its own), the whole region is treated as lying under a skin.
 */
import type { InfillModelInput, InfillParams, InfillPattern } from '../types.js';
import type { Polyline } from '../../geometry/types.js';
import { UM_PER_MM } from '../../geometry/types.js';
import { indexRegion, regionGeom } from '../region-index.js';
import { type Forest, type ForestParams, emptyForest, forestPolylines, grow, propagate } from '../lightning-forest.js';
import { MIN_DENSITY } from '../../geometry/tolerances.js';

/** Largest angle from the vertical a branch may lean by (tips retract at this rate going down), degrees. */
export const LIGHTNING_OVERHANG_DEG = 40;
/** How fast crooked branches are straightened going down, as an angle from the vertical, degrees. */
export const LIGHTNING_STRAIGHTEN_DEG = 40;

export function lightningRadius(params: InfillParams): number {
  const d = Math.min(1, Math.max(MIN_DENSITY, params.density));
  return params.lineWidthUm / d;
}

function prepareTrees(model: InfillModelInput, params: InfillParams): Polyline[][] {
  const n = model.layers.length;
  const out: Polyline[][] = new Array(n);
  const tan = (deg: number) => Math.tan((deg * Math.PI) / 180);
  let forest: Forest = emptyForest();
  for (let i = n - 1; i >= 0; i--) {
    const layer = model.layers[i];
    const h = layer.layerHeightMm * UM_PER_MM;
    const fp: ForestParams = {
      radius: lightningRadius(params),
      pruneDist: h * tan(LIGHTNING_OVERHANG_DEG),
      straightenDist: h * tan(LIGHTNING_STRAIGHTEN_DEG),
      origin: { x: 0, y: 0 },
    };
    if (layer.region.length === 0) {
      forest = emptyForest();
      out[i] = [];
      continue;
    }
    const need = model.supportNeeded[i] ?? [];
    if (forest.par.length === 0 && need.length === 0) {
      out[i] = [];
      continue;
    }
    const ix = indexRegion(regionGeom(layer.region));
    forest = propagate(forest, ix, fp);
    grow(forest, need, ix, fp);
    out[i] = forestPolylines(forest);
  }
  return out;
}

export const lightning: InfillPattern = {
  id: 'lightning',
  description: 'Trees grown down from the top skins they support, pruned and straightened layer by layer.',
  densityModel: 'support',
  followsRegion: true,
  prepare: prepareTrees,
  generate(layer, params, prepared) {
    const lines = prepared ?? prepareTrees({ layers: [layer], supportNeeded: [layer.region] }, params)[0];
    return { lines, loops: [], link: false };
  },
};
