/**
 * Exposure detection for top and bottom skin, done exactly with polygon booleans.
 * A part of a layer's inner area is top skin when any of the `topLayers` layers above lacks material
 * there, and bottom skin when any of the `bottomLayers` layers below does. Areas with material on
 * every layer within the skin thickness above and below (covered areas, cavity interiors) get none.
 */
import { difference, intersection, opening, union } from '../geometry/clip.js';
import type { ExPolygon } from '../geometry/types.js';

export interface SkinAreas {
  top: ExPolygon[];
  bottom: ExPolygon[];
}

/**
 * The region covered by material on every one of the given layers (their sections intersected).
 * An empty or missing layer covers nothing.
 */
export function coveredByAll(sections: readonly (readonly ExPolygon[])[], count: number): ExPolygon[] {
  if (sections.length < count) return [];
  let covered: ExPolygon[] | null = null;
  for (let k = 0; k < count; k++) {
    const s = sections[k];
    if (s.length === 0) return [];
    covered = covered === null ? s.slice() : intersection(covered, s);
    if (covered.length === 0) return [];
  }
  return covered ?? [];
}

/**
 * Skin areas of one island.
 * @param inner the island's area inside its walls, µm
 * @param coveredAbove area with material on each of the `topLayers` layers above (coveredByAll), µm
 * @param coveredBelow the same for the `bottomLayers` layers below
 * @param minWidthUm features of skin narrower than this are dropped (they are slivers along the walls)
 */
export function skinAreas(
  inner: readonly ExPolygon[],
  coveredAbove: readonly ExPolygon[],
  coveredBelow: readonly ExPolygon[],
  topLayers: number,
  bottomLayers: number,
  minWidthUm: number,
): SkinAreas {
  if (inner.length === 0) return { top: [], bottom: [] };
  const top = topLayers > 0 ? difference(inner, coveredAbove) : [];
  // A region that is both top and bottom is printed once, as bottom (it rests on nothing).
  const bottom = bottomLayers > 0 ? difference(inner, coveredBelow) : [];
  const topOnly = bottom.length && top.length ? difference(top, bottom) : top;
  const clean = (a: ExPolygon[]) => (a.length && minWidthUm > 0 ? opening(a, minWidthUm / 2) : a);
  return { top: clean(topOnly), bottom: clean(bottom) };
}

/** All skin of a layer as one area. */
export function allSkin(s: SkinAreas): ExPolygon[] {
  if (s.top.length === 0) return s.bottom;
  if (s.bottom.length === 0) return s.top;
  return union(s.top, s.bottom);
}
