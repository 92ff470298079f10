/**
 * The lines and loops of a region's skin by its skin patterns (topSkinPattern, bottomSkinPattern; the
 * patterns are infill/skin-patterns.ts). The top skin is the skin exposed upward (RegionFill.topSkin) and,
 * where skin is exposed both ways, that part of the bottom skin too (RegionFill.topAndBottom) unless it lies
 * over air; the bottom skin is the rest. Skin over air keeps straight lines: a region whose skin bridges
 * (it has a bridge angle) lays concentric bottom skin as lines across the gap.
 *
 * With one pattern for both (the default, lines, among them) the skin is filled as one area, as it always
 * was. With two, the area is cut where top meets bottom, each side half a line width short of the other's
 * skin, so the beads of the two sides meet at the cut and do not pile up on it.
 */
import { difference, offset, union } from '../geometry/clip.js';
import type { ExPolygon, Pt } from '../geometry/types.js';
import { SKIN_PATTERNS, type SkinFill } from '../infill/skin-patterns.js';
import type { SkinPatternId } from '../infill/types.js';
import type { RegionFill } from '../regions/types.js';
import type { Config } from '../settings/resolve.js';

/**
 * The skin fills of one region: one per pattern in use (bottom first).
 * @param fillArea the centreline area of the skin's beads, µm
 * @param angle direction of the skin lines on this layer, degrees
 * @param w line width (and spacing), µm
 */
export function skinFills(
  fill: RegionFill,
  cfg: Config,
  fillArea: ExPolygon[],
  angle: number,
  w: number,
  origin: Pt,
): SkinFill[] {
  const topId: SkinPatternId = cfg.topSkinPattern;
  let bottomId: SkinPatternId = cfg.bottomSkinPattern;
  if (bottomId === 'concentric' && fill.bridgeAngle !== null) bottomId = 'lines';
  const lay = (id: SkinPatternId, area: ExPolygon[]) => SKIN_PATTERNS[id].fill(area, angle, w, origin);
  if (topId === bottomId) return [lay(topId, fillArea)];
  let both = fill.topAndBottom ?? [];
  if (both.length && fill.bridge.length) both = difference(both, fill.bridge);
  const top = both.length ? (fill.topSkin.length ? union(fill.topSkin, both) : both) : fill.topSkin;
  const bottom = both.length ? difference(fill.bottomSkin, both) : fill.bottomSkin;
  if (top.length === 0) return [lay(bottomId, fillArea)];
  if (bottom.length === 0) return [lay(topId, fillArea)];
  const bottomPart = difference(fillArea, offset(top, w / 2));
  const topPart = difference(fillArea, offset(bottom, w / 2));
  const out: SkinFill[] = [];
  if (bottomPart.length) out.push(lay(bottomId, bottomPart));
  if (topPart.length) out.push(lay(topId, topPart));
  return out;
}
