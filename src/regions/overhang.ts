/**
 * Overhang detection: the part of a layer's section that the layer below does not hold up. A layer may reach
 * out past the one below by layerHeight · tan(threshold) and still print on it (the overhang angle, measured
 * from vertical); what lies further out needs support. Specks below supportMinArea are ignored.
 */
import { area, difference, offset, opening } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';

/** Parts of an overhang thinner than twice this (µm) are slicing noise along a wall, not something to hold up. */
const NOISE_RADIUS_UM = 10;

export interface OverhangSettings {
  /** Overhang angle from vertical beyond which support is needed, degrees. */
  supportThreshold: number;
  /** Smallest overhang worth supporting, mm². */
  supportMinArea: number;
}

/**
 * The area of `section` that needs support.
 * @param section the layer's section, µm
 * @param below the section of the layer below, µm ([] for the first layer, which rests on the bed)
 * @param layerHeightMm the layer's thickness
 * @param isFirst whether this is the first layer (it rests on the bed: no overhang)
 * @param beyond what the caller already knows: whether any of the section lies beyond the layer below grown
 *   by `grownUm`; when none does and the overhang reach is at least that, nothing overhangs (no clipping)
 */
export function overhangOf(
  section: readonly ExPolygon[],
  below: readonly ExPolygon[],
  layerHeightMm: number,
  s: OverhangSettings,
  isFirst = false,
  beyond?: { any: boolean; grownUm: number },
): ExPolygon[] {
  if (isFirst || section.length === 0) return [];
  const reachUm = layerHeightMm * 1000 * Math.tan((s.supportThreshold * Math.PI) / 180);
  // the section less the layer below grown by the reach lies within the section less it grown by less;
  // an empty difference of the smaller growth can leave only clipping-rounding slivers, which the opening
  // below removes anyway
  if (beyond && !beyond.any && reachUm >= beyond.grownUm && below.length) return [];
  const held = below.length && reachUm >= 1 ? offset(below, reachUm) : below;
  const raw = difference(section, held);
  if (raw.length === 0) return [];
  const cleaned = opening(raw, NOISE_RADIUS_UM);
  const minUm2 = s.supportMinArea * 1e6;
  return minUm2 > 0 ? cleaned.filter((a) => area([a]) >= minUm2) : cleaned;
}
