/**
 * Triangles: three families 60° apart (angle, angle + 60°, angle + 120°: 45°, 105°, 165° by default), all
 * with the same spacing and all passing through the origin. With unit normals n0, n60, n120 one has
 * n60 − n0 = n120, so wherever lines of the first two families cross, a line of the third passes too: the
 * cells are true equilateral triangles of height s.
 */
import type { InfillPattern } from '../types.js';
import { familyOverlap, familySpacing } from '../density.js';

/** Area lost per s² at the triple crossings, in units of w² (see density.ts). */
export const TRIANGLE_OVERLAP = 2.25;

export const triangles: InfillPattern = {
  id: 'triangles',
  description: 'Three line families 60° apart meeting at common points: equilateral triangles.',
  generate(_layer, params) {
    const s = familySpacing(params.density, params.lineWidth, 3, TRIANGLE_OVERLAP);
    return {
      lines: [],
      loops: [],
      sweeps: [0, 60, 120].map((d) => ({ angle: params.angle + d, spacing: s, offset: 0 })),
      linkSpacing: s,
      overlap: familyOverlap(s, params.lineWidth, 3, TRIANGLE_OVERLAP),
    };
  },
};
