/**
 * Ironing: after a region's skin, the nozzle passes over the area it irons (RegionFill.ironing, found by the
 * regions stage) again at the layer's height, in monotonic lines ironingSpacing apart (each laid beside the
 * last, so the melted ridges are pushed one way), across the layer's skin lines unless ironingAngle says
 * otherwise. The lines are as wide as their spacing and extrude ironingFlow % of such a line at the layer
 * height (the role's flow, roles.ts): PrusaSlicer's measure, a trickle that fills the grooves between the
 * skin's beads.
 */
import { UM_PER_MM } from '../geometry/types.js';
import { monotonicFill } from '../infill/monotonic.js';
import type { RegionFill } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';
import type { Pt } from '../geometry/types.js';
import { makeEntry } from './entry.js';
import type { PathEntry } from './types.js';

/**
 * The ironing entry of one region, or null where it irons nothing.
 * @param skinAngle direction of the region's skin lines on this layer, degrees
 */
export function ironingEntry(fill: RegionFill, cfg: Config, skinAngle: number, origin: Pt): PathEntry | null {
  if (!fill.ironing?.length) return null;
  const spacing = Math.round(cfg.ironingSpacing * UM_PER_MM);
  const lines = monotonicFill(fill.ironing, cfg.ironingAngle ?? skinAngle + 90, spacing, origin);
  if (lines.length === 0) return null;
  const e = makeEntry(cfg, 'ironing', false, lines, spacing / UM_PER_MM);
  e.ordered = true;
  return e;
}
