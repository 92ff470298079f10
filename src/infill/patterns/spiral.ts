/**
 * Spiral: one Archimedean spiral r = s·θ/2π per island, from the island's area centroid out to its
 * farthest vertex, starting in the infill angle's direction. The spiral follows the region (its centre is
 * the island's), so centering has no effect. Only clipping breaks it: in a disc it stays one line; where the
 * outline cuts the outer turns (corners of a square), the broken arcs are joined along the boundary by the
 * shared linker. Points are placed so the chord error stays under CHORD_TOLERANCE_UM.
 */
import type { InfillPattern } from '../types.js';
import { hypot, type Pt } from '../../geometry/types.js';
import { ringArea } from '../../geometry/clip.js';
import { familySpacing } from '../density.js';

const CHORD_TOLERANCE_UM = 5;

/** Area centroid of an island (outer minus holes). */
export function islandCentroid(outer: readonly Pt[], holes: readonly (readonly Pt[])[]): Pt {
  let A = 0,
    cx = 0,
    cy = 0;
  for (const ring of [outer, ...holes]) {
    const sign = ring === outer ? 1 : -1;
    const a = Math.abs(ringArea(ring));
    if (a === 0) continue;
    let rx = 0,
      ry = 0,
      ra = 0;
    for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
      const cr = ring[j].x * ring[i].y - ring[i].x * ring[j].y;
      ra += cr;
      rx += (ring[j].x + ring[i].x) * cr;
      ry += (ring[j].y + ring[i].y) * cr;
    }
    cx += sign * (rx / (3 * ra)) * a;
    cy += sign * (ry / (3 * ra)) * a;
    A += sign * a;
  }
  if (A <= 0) return outer[0];
  return { x: cx / A, y: cy / A };
}

export const spiral: InfillPattern = {
  id: 'spiral',
  description: 'One Archimedean spiral per island from its centre, clipped, broken arcs linked.',
  followsRegion: true,
  generate(_layer, params) {
    const sp = familySpacing(params.density, params.lineWidthUm, 1);
    const lines: Pt[][] = [];
    const a0 = (params.angle * Math.PI) / 180;
    for (const isl of _layer.region) {
      const c = islandCentroid(isl.outer, isl.holes);
      let rMax = 0;
      for (const p of isl.outer) rMax = Math.max(rMax, hypot(p.x - c.x, p.y - c.y));
      const thetaMax = (2 * Math.PI * (rMax + sp)) / sp;
      const pts: Pt[] = [{ x: c.x, y: c.y }];
      let th = 0;
      while (th < thetaMax) {
        const r = (sp * th) / (2 * Math.PI);
        // sagitta of a chord over dθ at radius r is r(1 − cos(dθ/2)) ≈ r·dθ²/8
        const dth =
          r > CHORD_TOLERANCE_UM ? Math.min(Math.PI / 8, Math.sqrt((8 * CHORD_TOLERANCE_UM) / r)) : Math.PI / 8;
        th = Math.min(thetaMax, th + dth);
        const rr = (sp * th) / (2 * Math.PI);
        pts.push({ x: c.x + rr * Math.cos(th + a0), y: c.y + rr * Math.sin(th + a0) });
      }
      lines.push(pts);
    }
    return { lines, loops: [], linkSpacingUm: sp };
  },
};
