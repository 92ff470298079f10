/**
 * Cubic: the horizontal sections of a stack of cubes standing on a corner (body diagonal vertical). Each
 * cube face is a plane whose normal makes acos(1/√3) with the vertical; its trace in the plane at height z
 * moves along the face's horizontal normal by z·cot(54.74°) = z/√2. The three face directions project 120°
 * apart, so the layer holds three line families at angle, angle + 120°, angle + 240° (as directed lines),
 * each shifted by z/√2 along its own normal. Their crossings move with Z and the cells turn from triangles
 * into hexagons and back: every face overhangs at 35.3° from the vertical, self-supporting at any density.
 *
 * Density: the three families meet at common points only at some heights (where 3·z/√2 is a multiple of
 * the spacing); in between, each near-triple point is a small triangle and the crossing overlaps shrink
 * from 3·w² to 2.25·w² per cell (see density.ts) and back. Averaged over one Z period (s·√2/3) the overlap
 * is (3 − w/s)·w² per s² (the triple overlap integrates to w³ over a period of the defect), so the spacing
 * solves 3x − (3 − x)·x² = density, x = w/s; single layers vary by ±0.4·x² (±2.3 % at 40 %): 'volume'.
 */
import type { InfillParams, InfillPattern } from '../types.js';
import { solveDecreasing } from '../density.js';
import { UM_PER_MM } from '../../geometry/types.js';

/** Mean coverage of the three families at w/s = x over one Z period. */
function coverage(x: number): number {
  return 3 * x - (3 - x) * x * x;
}

/** Line spacing of each family, µm. */
export function cubicSpacing(params: InfillParams): number {
  const w = params.lineWidth;
  const d = Math.min(1, Math.max(1e-6, params.density));
  // coverage(x) rises up to x = 1 (coverage 1)
  return solveDecreasing((s) => coverage(Math.min(1, w / s)), d, w, w * 1e6);
}

export const cubic: InfillPattern = {
  id: 'cubic',
  description: 'Three line families 120° apart whose offsets move with Z: cubes standing on a corner.',
  densityModel: 'volume',
  zPeriod: (params) => (cubicSpacing(params) * Math.SQRT2) / 3 / UM_PER_MM,
  generate(layer, params) {
    const s = cubicSpacing(params);
    const zMid = layer.z - layer.layerHeight / 2;
    const shift = (zMid * UM_PER_MM) / Math.SQRT2;
    return {
      lines: [],
      loops: [],
      sweeps: [0, 120, 240].map((d) => ({ angle: params.angle + d, spacing: s, offset: shift })),
      linkSpacing: s,
    };
  },
};
