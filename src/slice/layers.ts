/**
 * The Z plan: which layers are printed, at what nozzle height, and where each one is cut.
 *
 * Everything is computed in integer micrometres (slice planes in half-micrometres, since a layer's
 * mid-height can fall on a half µm), so 0.1 + 0.2 style float drift never adds or loses a layer.
 *
 * Rule for the last layer: layer i is planned iff its slice plane is at or below the model top, both
 * compared on the half-µm grid. The slicer (`sliceMesh`) classifies vertices on the same grid with
 * "z ≥ plane counts as above", so a plane that lies exactly on (or within ±0.25 µm of) the top still
 * cuts the top outline: a thin top feature that reaches a slice plane gets exactly one layer there —
 * never lost to float noise, never doubled. A feature ending below the last plane (less than half a
 * layer above the previous top) rounds away, as mid-height slicing always does.
 *
 * `planVaryingLayers` plans layers of varying height (adaptive layers, a layer range's own height) on the same
 * grid with the same rule: each layer's Z is the sum of whole-µm heights, so an uneven plan is as exact.
 */
import { StrataError } from '../errors.js';
import type { LayerZ } from './types.js';

/** Half-micrometres per millimetre: the grid slice planes and vertex heights are compared on. */
export const HALF_UM_PER_MM = 2000;

/** Above this many layers the plan is refused (a 1 m tall model at 0.02 mm is 50,000). */
export const MAX_LAYERS = 1_000_000;

/** A height in mm snapped to the half-µm grid (an integer). */
export function toHalfUm(mm: number): number {
  return Math.round(mm * HALF_UM_PER_MM);
}

/**
 * Plan the layers of a model whose bottom is at z = 0 and top at `modelHeight` (mm).
 * Layer 0 is printed at z = firstLayerHeight with that height; each next one `layerHeight` above.
 * `sliceZ` is the mid-height of each layer. Returns [] for a model with no height.
 */
export function planLayers(modelHeight: number, firstLayerHeight: number, layerHeight: number): LayerZ[] {
  if (!Number.isFinite(firstLayerHeight) || !Number.isFinite(layerHeight)) {
    throw new StrataError('BAD_SETTING', 'Layer heights must be finite numbers.');
  }
  const firstUm = Math.round(firstLayerHeight * 1000);
  const stepUm = Math.round(layerHeight * 1000);
  if (firstUm < 1 || stepUm < 1) {
    throw new StrataError(
      'BAD_SETTING',
      `Layer heights must be at least 0.001 mm (got ${firstLayerHeight} and ${layerHeight}).`,
    );
  }
  if (!Number.isFinite(modelHeight)) throw new StrataError('BAD_MESH', 'Model height is not a finite number.');
  const topHalf = toHalfUm(modelHeight);
  // Slice plane of layer i in half-µm: 2·z − h, with z and h in µm.
  const firstPlane = firstUm; // 2·first − first
  if (topHalf < firstPlane) return [];
  // Layers i ≥ 1: plane = 2·(first + i·step) − step = 2·first + (2i − 1)·step ≤ top.
  const more = Math.floor((topHalf - 2 * firstUm + stepUm) / (2 * stepUm));
  const count = 1 + Math.max(0, more);
  if (count > MAX_LAYERS) {
    throw new StrataError('LIMIT_EXCEEDED', `The model needs ${count} layers; at most ${MAX_LAYERS} are allowed.`);
  }
  const layers: LayerZ[] = new Array(count);
  layers[0] = { index: 0, z: firstUm / 1000, height: firstUm / 1000, sliceZ: firstUm / 2000 };
  for (let i = 1; i < count; i++) {
    const zUm = firstUm + i * stepUm;
    layers[i] = { index: i, z: zUm / 1000, height: stepUm / 1000, sliceZ: (2 * zUm - stepUm) / 2000 };
  }
  // A cut exactly at the top face finds nothing (vertices on a plane count as above it): cut the
  // last layer half a micrometre lower so it prints the top section instead of an empty layer.
  const last = layers[count - 1];
  if (toHalfUm(last.sliceZ) >= topHalf) last.sliceZ = (topHalf - 1) / HALF_UM_PER_MM;
  return layers;
}

/**
 * Plan layers of varying height, on the same grid and with the same last-layer rule as `planLayers`:
 * layer 0 is `firstLayerHeight` thick; each next one is `nextUm(bottomUm, prevUm, index)` µm thick (a whole
 * number ≥ 1), asked with the Z of its bottom (the top of the layer before) and that layer's height, both µm.
 * Z is summed in whole µm, so no drift: layer i's z is exactly the sum of the heights up to it.
 */
export function planVaryingLayers(
  modelHeight: number,
  firstLayerHeight: number,
  nextUm: (bottomUm: number, prevUm: number, index: number) => number,
): LayerZ[] {
  if (!Number.isFinite(firstLayerHeight)) throw new StrataError('BAD_SETTING', 'Layer heights must be finite numbers.');
  const firstUm = Math.round(firstLayerHeight * 1000);
  if (firstUm < 1)
    throw new StrataError('BAD_SETTING', `Layer heights must be at least 0.001 mm (got ${firstLayerHeight}).`);
  if (!Number.isFinite(modelHeight)) throw new StrataError('BAD_MESH', 'Model height is not a finite number.');
  const topHalf = toHalfUm(modelHeight);
  if (topHalf < firstUm) return [];
  const layers: LayerZ[] = [{ index: 0, z: firstUm / 1000, height: firstUm / 1000, sliceZ: firstUm / 2000 }];
  let zUm = firstUm,
    prevUm = firstUm;
  for (;;) {
    const i = layers.length;
    const hUm = nextUm(zUm, prevUm, i);
    if (!Number.isInteger(hUm) || hUm < 1) throw new Error(`layer ${i} was planned ${hUm} µm thick`);
    // its slice plane 2·(z + h) − h in half-µm must not lie above the top
    if (2 * zUm + hUm > topHalf) break;
    if (i >= MAX_LAYERS) throw new StrataError('LIMIT_EXCEEDED', `The model needs more than ${MAX_LAYERS} layers.`);
    zUm += hUm;
    layers.push({ index: i, z: zUm / 1000, height: hUm / 1000, sliceZ: (2 * zUm - hUm) / 2000 });
    prevUm = hUm;
  }
  const last = layers[layers.length - 1];
  if (toHalfUm(last.sliceZ) >= topHalf) last.sliceZ = (topHalf - 1) / HALF_UM_PER_MM;
  return layers;
}

/**
 * Whether every layer after the first is `layerHeight` thick (in whole µm, as planned): an even plan, whose
 * skin and support gap counts are the config's.
 */
export function evenLayers(layers: readonly LayerZ[], layerHeight: number): boolean {
  const um = Math.round(layerHeight * 1000);
  for (let i = 1; i < layers.length; i++) if (Math.round(layers[i].height * 1000) !== um) return false;
  return true;
}
