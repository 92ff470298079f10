/**
 * From a layer's oriented, simplified rings to islands: drop tiny rings, merge with the non-zero
 * fill rule (overlapping shells union; holes are rings wound against their container), then drop
 * sliver islands and holes.
 */
import { ringArea, unionRings } from '../geometry/clip.js';
import type { ExPolygon, Polygon } from '../geometry/types.js';

/** Rings (outer CCW, holes CW, µm) to islands; rings, holes and islands under minAreaUm2 are dropped. */
export function ringsToIslands(rings: readonly Polygon[], minAreaUm2: number): ExPolygon[] {
  const kept: Polygon[] = [];
  for (const r of rings) if (r.length >= 3 && Math.abs(ringArea(r)) >= minAreaUm2) kept.push(r);
  if (kept.length === 0) return [];
  const merged = unionRings(kept);
  const out: ExPolygon[] = [];
  for (const island of merged) {
    const holes: Polygon[] = [];
    let net = Math.abs(ringArea(island.outer));
    for (const h of island.holes) {
      const a = Math.abs(ringArea(h));
      if (a >= minAreaUm2) {
        holes.push(h);
        net -= a;
      }
    }
    if (net >= minAreaUm2) out.push({ outer: island.outer, holes });
  }
  return out;
}
