/**
 * Bridge direction: skin printed over air should run from support to support, so that each line is held at
 * both ends, rather than along the gap. When most of an island's bottom skin rests on nothing, the direction is
 * taken between the two largest places where the skin's surroundings rest on the layer below (the anchors),
 * as other slicers do for bridges.
 */
import { area, difference, intersection, offset } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';

/** The skin counts as a bridge when at least this share of it lies over nothing. */
const BRIDGE_SHARE = 0.5;
/** Anchors are sought this many line widths around the unsupported skin (walls and skin wall lie between). */
const ANCHOR_REACH_WIDTHS = 3;

/** Centroid and area of an island (outer ring counter-clockwise, holes clockwise, as the clipper gives them). */
function centroid(a: ExPolygon): { x: number; y: number; area: number } {
  let cx = 0, cy = 0, A = 0;
  for (const ring of [a.outer, ...a.holes]) {
    for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
      const cross = ring[j].x * ring[i].y - ring[i].x * ring[j].y;
      A += cross / 2;
      cx += ((ring[j].x + ring[i].x) * cross) / 6;
      cy += ((ring[j].y + ring[i].y) * cross) / 6;
    }
  }
  return A !== 0 ? { x: cx / A, y: cy / A, area: Math.abs(A) } : { x: a.outer[0].x, y: a.outer[0].y, area: 0 };
}

/**
 * The direction (degrees) skin lines should take when the bottom skin bridges, or null when it does not (or
 * has fewer than two anchors, as over a cantilever).
 * @param bottom the island's bottom skin, µm
 * @param below the section of the layer below, µm
 */
export function bridgeAngle(bottom: readonly ExPolygon[], below: readonly ExPolygon[], lineWidthUm: number): number | null {
  if (bottom.length === 0) return null;
  const unsupported = difference(bottom, below);
  if (unsupported.length === 0 || area(unsupported) < BRIDGE_SHARE * area(bottom)) return null;
  const anchors = intersection(offset(unsupported, ANCHOR_REACH_WIDTHS * lineWidthUm), below).map(centroid);
  if (anchors.length < 2) return null;
  anchors.sort((p, q) => q.area - p.area);
  const [a, b] = anchors;
  return (Math.atan2(b.y - a.y, b.x - a.x) * 180) / Math.PI;
}
