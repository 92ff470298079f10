/**
 * Cubic: the horizontal sections of a stack of cubes standing on a corner (body diagonal vertical). Each
 * cube face is a plane whose normal makes acos(1/√3) with the vertical; its trace in the plane at height z
 * moves along the face's horizontal normal by z·cot(54.74°) = z/√2. The three face directions project 120°
 * apart, so the layer holds three line families at angle, angle + 120°, angle + 240° (as directed lines),
 * each shifted by z/√2 along its own normal. Their crossings move with Z and the cells turn from triangles
 * into hexagons and back: every face overhangs at 35.3° from the vertical, self-supporting at any density.
 *
 * Density: three families, each extruding a third of the setting (see density.ts), at every height: the
 * crossings move with Z but the line length per area does not.
 */
import type { InfillParams, InfillPattern } from '../types.js';
import { familySpacing } from '../density.js';
import { UM_PER_MM } from '../../geometry/types.js';

/** Line spacing of each family, µm. */
export function cubicSpacing(params: InfillParams): number {
  return familySpacing(params.density, params.lineWidthUm, 3);
}

export const cubic: InfillPattern = {
  id: 'cubic',
  description: 'Three line families 120° apart whose offsets move with Z: cubes standing on a corner.',
  densityModel: 'volume',
  zPeriodMm: (params) => (cubicSpacing(params) * Math.SQRT2) / 3 / UM_PER_MM,
  generate(layer, params) {
    const s = cubicSpacing(params);
    const zMid = layer.zMm - layer.layerHeightMm / 2;
    const shift = (zMid * UM_PER_MM) / Math.SQRT2;
    return {
      lines: [],
      loops: [],
      sweeps: [0, 120, 240].map((d) => ({ angle: params.angle + d, spacingUm: s, offsetUm: shift })),
      linkSpacingUm: s,
    };
  },
};
