/**
 * Bridges: bottom skin over nothing on the layer below. Its lines should run from support to support, so that
 * each line is held at both ends, rather than along the gap: the direction is taken between the two largest
 * places where the bridge's surroundings rest on the layer below (the anchors), as other slicers do.
 */
import { area, difference, intersection, offset, opening } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';

/** An island's skin takes the bridge direction as a whole when at least this share of it lies over nothing. */
const BRIDGE_SHARE = 0.5;
/** Parts of the skin over nothing narrower than this share of a line width are not bridges (they rest on the walls). */
const MIN_BRIDGE_WIDTHS = 0.5;
/** Anchors are sought this many line widths around the unsupported skin (walls and skin wall lie between). */
const ANCHOR_REACH_WIDTHS = 3;

/** Centroid and area of an island (outer ring counter-clockwise, holes clockwise, as the clipper gives them). */
function centroid(a: ExPolygon): { x: number; y: number; area: number } {
  let cx = 0,
    cy = 0,
    A = 0;
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

export interface Bridge {
  /** The bottom skin over nothing (slivers dropped), µm. */
  area: ExPolygon[];
  /** Direction of the lines across it, degrees, or null without two anchors (a cantilever). */
  angle: number | null;
  /** Whether most of the skin is bridge (then all of the island's skin may take the bridge direction). */
  mostly: boolean;
  /** The direction of the bridge's lines whether or not it is most of the skin (null: no two anchors). */
  lines?: number | null;
}

/**
 * The bridge of an island's bottom skin over the layer below.
 * @param bottom the island's bottom skin, µm
 * @param below the section of the layer below, µm
 */
export function bridgeOf(bottom: readonly ExPolygon[], below: readonly ExPolygon[], lineWidthUm: number): Bridge {
  if (bottom.length === 0) return { area: [], angle: null, mostly: false };
  const raw = difference(bottom, below);
  if (raw.length === 0) return { area: [], angle: null, mostly: false };
  const over = opening(raw, (MIN_BRIDGE_WIDTHS * lineWidthUm) / 2);
  const mostly = area(raw) >= BRIDGE_SHARE * area(bottom);
  const lines = over.length ? anchorAngle(raw, below, lineWidthUm) : null;
  return { area: over, angle: mostly ? lines : null, mostly, lines };
}

/**
 * The area a bridge's lines cover: the bridge grown by `anchorUm` into the region's area inside its walls (onto
 * what the layer below holds up, and over any air next to it), so that every line starts and ends that far onto
 * support, as PrusaSlicer's bridge anchors and Cura's bridge skin support do. The growth stops at the walls: a
 * bridge between walls resting on thin pillars ends at the innermost wall, which lies on them.
 * @param inner the region's area inside its walls, µm
 */
export function anchoredBridge(
  bridge: readonly ExPolygon[],
  inner: readonly ExPolygon[],
  anchorUm: number,
): ExPolygon[] {
  if (bridge.length === 0 || inner.length === 0) return [];
  if (anchorUm <= 0) return intersection(bridge, inner);
  return intersection(offset(bridge, anchorUm), inner);
}

function anchorAngle(
  unsupported: readonly ExPolygon[],
  below: readonly ExPolygon[],
  lineWidthUm: number,
): number | null {
  const anchors = intersection(offset(unsupported, ANCHOR_REACH_WIDTHS * lineWidthUm), below).map(centroid);
  if (anchors.length < 2) return null;
  anchors.sort((p, q) => q.area - p.area);
  const [a, b] = anchors;
  return (Math.atan2(b.y - a.y, b.x - a.x) * 180) / Math.PI;
}

/**
 * The direction (degrees) skin lines should take when the bottom skin bridges, or null when it does not (or
 * has fewer than two anchors, as over a cantilever).
 * @param bottom the island's bottom skin, µm
 * @param below the section of the layer below, µm
 */
export function bridgeAngle(
  bottom: readonly ExPolygon[],
  below: readonly ExPolygon[],
  lineWidthUm: number,
): number | null {
  if (bottom.length === 0) return null;
  const unsupported = difference(bottom, below);
  if (unsupported.length === 0 || area(unsupported) < BRIDGE_SHARE * area(bottom)) return null;
  return anchorAngle(unsupported, below, lineWidthUm);
}
