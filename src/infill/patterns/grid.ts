/**
 * Grid: two families of straight lines crossing at right angles, at the infill angle and 90° from it
 * (45° and 135° by default), both passing through the pattern origin so the crossings stack layer on layer.
 * Each family extrudes half the density (see density.ts).
 */
import type { InfillPattern } from '../types.js';
import { familySpacing } from '../density.js';

export const GRID_FAMILIES = 2;

export const grid: InfillPattern = {
  id: 'grid',
  description: 'Two line families at ±45° (angle and angle + 90°) crossing in squares.',
  generate(_layer, params) {
    const s = familySpacing(params.density, params.lineWidthUm, GRID_FAMILIES);
    return {
      lines: [],
      loops: [],
      sweeps: [
        { angle: params.angle, spacingUm: s, offsetUm: 0 },
        { angle: params.angle + 90, spacingUm: s, offsetUm: 0 },
      ],
      linkSpacingUm: s,
    };
  },
};
