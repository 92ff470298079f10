/**
 * Lines: one family of parallel lines per layer, turning 90° every layer (angle on even layers,
 * angle + 90° on odd ones), anchored at the pattern origin.
 */
import type { InfillPattern } from '../types.js';
import { familySpacing } from '../density.js';

export const lines: InfillPattern = {
  id: 'lines',
  description: 'One line family per layer, turning 90° each layer.',
  generate(layer, params) {
    const s = familySpacing(params.density, params.lineWidthUm, 1);
    const odd = ((layer.layerIndex % 2) + 2) % 2 === 1;
    return {
      lines: [],
      loops: [],
      sweeps: [{ angle: params.angle + (odd ? 90 : 0), spacingUm: s, offsetUm: 0 }],
      linkSpacingUm: s,
    };
  },
};
