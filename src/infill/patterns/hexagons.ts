/**
 * Hexagons: a true honeycomb of regular hexagons (side a, flat sides along the infill angle), printed as
 * continuous zig-zag chains. A honeycomb has three edges at every vertex, so no set of continuous paths can
 * cover it without ends at every vertex or doubled edges; instead, each chain takes the slanted edges and
 * the flat edges on both of its sides, and the flat edge two neighbouring chains share is printed by each of
 * them half a line width to its side: the two lines lie side by side (touching, never overlapping or
 * crossing), the wall between the cells is two lines thick, and every chain runs unbroken across the region.
 *
 * In the chain frame (u along the chain, v across) chain k is the periodic polyline
 *   (0, +A'), (a, +A'), (1.5a, −A'), (2.5a, −A'), (3a, +A') …,  A = a·√3/4, A' = A − w/2,
 * shifted by (1.5a·k, 2A·k), so its lower flats sit beside the upper flats of chain k − 1.
 */
import type { InfillPattern } from '../types.js';
import { hypot, type Pt } from '../../geometry/types.js';
import { solveDecreasing } from '../density.js';
import { frameBounds } from '../geom-util.js';

/** Line length per area of the chains for side a and width w (the footprint has no crossings). */
function coverage(a: number, w: number): number {
  const A = (a * Math.sqrt(3)) / 4;
  const Ap = Math.max(0, A - w / 2);
  const len = 2 * a + 2 * hypot(a / 2, 2 * Ap);
  return (w * len) / (3 * a * 2 * A);
}

/** Hexagon side (µm) for a density. */
export function hexSide(density: number, w: number): number {
  const aMin = (2 * w) / Math.sqrt(3);
  if (density >= 1) return aMin;
  return solveDecreasing((a) => coverage(a, w), density, aMin, aMin * 1e5);
}

export const hexagons: InfillPattern = {
  id: 'hexagons',
  description: 'Honeycomb of regular hexagons as continuous zig-zag chains, shared walls side by side.',
  generate(layer, params) {
    const w = params.lineWidthUm;
    const a = hexSide(params.density, w);
    const A = (a * Math.sqrt(3)) / 4;
    const Ap = Math.max(0, A - w / 2);
    const th = (params.angle * Math.PI) / 180,
      c = Math.cos(th),
      s = Math.sin(th);
    const o = params.origin;
    const { uMin, uMax, vMin, vMax } = frameBounds(layer.region, o, th);
    const lines: Pt[][] = [];
    if (!(uMin <= uMax)) return { lines, loops: [] };
    // put a cell centre on the origin: cells sit at (2a, A) in chain-0 coordinates
    const u0 = -2 * a,
      v0 = -A;
    const kLo = Math.floor((vMin - v0 - 2 * A) / (2 * A)),
      kHi = Math.ceil((vMax - v0 + 2 * A) / (2 * A));
    const P = 3 * a;
    const du = [0, a, 1.5 * a, 2.5 * a];
    const dv = [Ap, Ap, -Ap, -Ap];
    for (let k = kLo; k <= kHi; k++) {
      const vk = v0 + 2 * A * k;
      const uk = u0 + 1.5 * a * k;
      const jLo = Math.floor((uMin - uk) / P) - 1,
        jHi = Math.ceil((uMax - uk) / P) + 1;
      const pts: Pt[] = [];
      for (let j = jLo; j <= jHi; j++) {
        for (let q = 0; q < 4; q++) {
          const u = uk + j * P + du[q],
            v = vk + dv[q];
          pts.push({ x: o.x + u * c - v * s, y: o.y + u * s + v * c });
        }
      }
      lines.push(pts);
    }
    return { lines, loops: [], linkSpacingUm: 2 * A };
  },
};
