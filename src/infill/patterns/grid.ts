/**
 * Grid: two families of straight lines crossing at right angles, at the infill angle and 90° from it
 * (45° and 135° by default), both passing through the pattern origin so the crossings stack layer on layer.
 */
import type { InfillPattern } from '../types.js';
import { familyOverlap, familySpacing } from '../density.js';

/** Two families: each pair of crossing families loses w² per s² of area to the overlap (see density.ts). */
export const GRID_FAMILIES = 2;
export const GRID_OVERLAP = 1;

export const grid: InfillPattern = {
  id: 'grid',
  description: 'Two line families at ±45° (angle and angle + 90°) crossing in squares.',
  generate(_layer, params) {
    const s = familySpacing(params.density, params.lineWidth, GRID_FAMILIES, GRID_OVERLAP);
    return {
      lines: [],
      loops: [],
      sweeps: [
        { angle: params.angle, spacing: s, offset: 0 },
        { angle: params.angle + 90, spacing: s, offset: 0 },
      ],
      linkSpacing: s,
      overlap: familyOverlap(s, params.lineWidth, GRID_FAMILIES, GRID_OVERLAP),
    };
  },
};
