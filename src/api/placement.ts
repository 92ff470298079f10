/**
 * Placing objects on the bed as the slicer does, for a plate editor (the web page's): an object's placement
 * (a rotation and scale, and the bed point under the middle of its bounds, standing on the bed) as the
 * affine transform it is drawn and sliced with, the 3×3 turns that build one, and arranging footprints
 * without overlap as the slicer arranges several models. Objects placed with `placeObjects` and sliced with
 * `center: false` print where the editor shows them.
 */
import { determinant, transformPoints, type Affine } from '../mesh/transform.js';
import type { Mesh } from '../mesh/types.js';

export type { Affine } from '../mesh/transform.js';
export {
  IDENTITY_LINEAR,
  axisRotation,
  linearBounds,
  mul3 as multiplyLinear,
  placeObjects,
  placementAffine,
  rotationBetween,
  type Box,
  type Placement,
} from '../mesh/placement.js';
export {
  ARRANGE_GAP_MM,
  arrange,
  findSpot,
  footprintsOverlap,
  type Bed,
  type Footprint,
  type PlacedFootprint,
} from '../mesh/arrange.js';

/**
 * A mesh under an affine transform (e.g. `placementAffine`'s: a volume moved with its object), as new arrays;
 * where the transform mirrors, two corners of every triangle are swapped so that it still faces outwards.
 */
export function transformMesh(mesh: Readonly<Mesh>, affine: Affine): Mesh {
  const n = mesh.positions.length / 3;
  const positions = new Float32Array(n * 3);
  transformPoints(affine, mesh.positions, n, positions, 0);
  if (determinant(affine) >= 0) return { positions, indices: mesh.indices.slice() };
  const indices = mesh.indices.slice();
  for (let t = 0; t < indices.length; t += 3) [indices[t + 1], indices[t + 2]] = [indices[t + 2], indices[t + 1]];
  return { positions, indices };
}
