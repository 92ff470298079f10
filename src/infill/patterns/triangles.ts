/**
 * Triangles: three families 60° apart (angle, angle + 60°, angle + 120°: 45°, 105°, 165° by default), all
 * with the same spacing and all passing through the origin. With unit normals n0, n60, n120 one has
 * n60 − n0 = n120, so wherever lines of the first two families cross, a line of the third passes too: the
 * cells are true equilateral triangles of height s. Each family extrudes a third of the density.
 */
import type { InfillPattern } from '../types.js';
import { familySpacing } from '../density.js';

export const triangles: InfillPattern = {
  id: 'triangles',
  description: 'Three line families 60° apart meeting at common points: equilateral triangles.',
  generate(_layer, params) {
    const s = familySpacing(params.density, params.lineWidthUm, 3);
    return {
      lines: [],
      loops: [],
      sweeps: [0, 60, 120].map((d) => ({ angle: params.angle + d, spacingUm: s, offsetUm: 0 })),
      linkSpacingUm: s,
    };
  },
};
