/**
 * Where a region's skin beads go: the skin-wall loops round its skin (skinWall), the centreline area its
 * lines or loops fill, split by pattern where the top and bottom skin patterns differ, the anchored bridge's
 * bead centres where it prints as bridge lines, and the exposed surface that skin gap fill must still reach.
 *
 * It is the regions stage's, computed from the region's areas (RegionFill), but once the support is known:
 * skin resting on support right below it (no Z gap) is no bridge, and an anchored bridge that support holds
 * up in part prints as skin. So the paths stage calls it once per region with the support under the layer,
 * and lays its lines and loops in the areas it returns.
 *
 * Top and bottom patterns: the top skin is the skin exposed upward (RegionFill.topSkin) and, where skin is
 * exposed both ways, that part of the bottom skin too (RegionFill.topAndBottom) unless it lies over air; the
 * bottom skin is the rest. Skin over air keeps straight lines: a region whose skin bridges (it has a bridge
 * angle) lays concentric bottom skin as lines across the gap. With one pattern for both (the default, lines,
 * among them) the skin is filled as one area. With two, the area is cut where top meets bottom, each side half
 * a line width short of the other's skin, so the beads of the two sides meet at the cut and do not pile up on it.
 */
import { area, difference, flatten, offset, opening, union } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon, type Polygon } from '../geometry/types.js';
import type { SkinPatternId } from '../infill/types.js';
import type { Config } from '../settings/resolve.js';
import type { RegionFill } from './types.js';

/** A part of a region's skin laid in one pattern: the centreline area of its lines or loops, µm. */
export interface SkinPart {
  pattern: SkinPatternId;
  area: ExPolygon[];
}

/** The anchored bridge as it prints in lines of its own. */
export interface BridgeLayout {
  /** The area the beads' centres fill (half a bead in from the bridge's edge, as far into the walls as skin reaches), µm. */
  centres: ExPolygon[];
  /** Direction of the lines, degrees. */
  angle: number;
  /** Most the lines lie apart (bridgeSpacing, or the nozzle's diameter and 0.05 mm), µm. */
  spacingUm: number;
}

export interface SkinLayout {
  /** The skin over air, µm: the region's bridge less the support right below it (no Z gap). */
  overAir: ExPolygon[];
  /** The anchored bridge when it prints as bridge lines (no support holds part of it up), else null. */
  bridge: BridgeLayout | null;
  /** Closed skin-wall centrelines (skinWall), µm. */
  walls: Polygon[];
  /** The skin's lines or loops, by pattern (one part, or bottom then top), µm. */
  parts: SkinPart[];
  /** The exposed surface inside the walls, slivers included, less the bridge lines' own, µm. */
  exposed: ExPolygon[];
}

/**
 * The layout of one region's skin.
 * @param w line width, µm
 * @param supportBelow the support of the layer below that holds this layer with no Z gap, µm
 */
export function skinLayout(fill: RegionFill, cfg: Config, w: number, supportBelow: readonly ExPolygon[]): SkinLayout {
  const overAir = fill.bridge.length && supportBelow.length ? difference(fill.bridge, supportBelow) : fill.bridge;
  // the anchored bridge prints as bridge lines unless support holds part of it up
  const held = supportBelow.length > 0 && fill.bridgeFill !== undefined && area(overAir) < area(fill.bridge) - 1;
  const anchored = held ? null : (fill.bridgeFill ?? null);
  const overlapSkin = (cfg.skinOverlap / 100) * w;
  let skin = fill.skin;
  let exposed = fill.exposed;
  let bridge: BridgeLayout | null = null;
  if (anchored) {
    const spacingUm = Math.round((cfg.bridgeSpacing ?? cfg.nozzleDiameter + 0.05) * UM_PER_MM);
    const centres = offset(anchored.area, -(Math.max(spacingUm, w) / 2 - overlapSkin));
    bridge = { centres, angle: anchored.angle, spacingUm };
    // the rest of the skin, less the bridge; whatever of it is narrower than a line is the bridge's (merged into it)
    skin = opening(difference(skin, anchored.area), w / 2);
    exposed = difference(exposed, offset(anchored.area, w / 2));
  }
  if (skin.length === 0 && exposed.length === 0) return { overAir, bridge, walls: [], parts: [], exposed };
  let walls: Polygon[] = [];
  let fillArea: ExPolygon[];
  if (cfg.skinWall && skin.length) {
    const wallCentre = offset(skin, -w / 2);
    walls = flatten(wallCentre);
    fillArea = offset(wallCentre, -(w - overlapSkin));
    // pieces too narrow for a skin-wall loop still get their lines
    if (skin.length > 1 || wallCentre.length === 0) {
      for (const piece of skin) {
        if (offset([piece], -w / 2).length === 0) fillArea.push(...offset([piece], -(w / 2 - overlapSkin)));
      }
    }
  } else {
    fillArea = offset(skin, -(w / 2 - overlapSkin));
  }
  const parts = fillArea.length ? skinParts(fill, cfg, fillArea, w) : [];
  return { overAir, bridge, walls, parts, exposed };
}

/** The skin's fill area by pattern (see the file comment): one part per pattern in use, bottom first. */
function skinParts(fill: RegionFill, cfg: Config, fillArea: ExPolygon[], w: number): SkinPart[] {
  const topId: SkinPatternId = cfg.topSkinPattern;
  let bottomId: SkinPatternId = cfg.bottomSkinPattern;
  if (bottomId === 'concentric' && fill.bridgeAngle !== null) bottomId = 'lines';
  if (topId === bottomId) return [{ pattern: topId, area: fillArea }];
  let both = fill.topAndBottom ?? [];
  if (both.length && fill.bridge.length) both = difference(both, fill.bridge);
  const top = both.length ? (fill.topSkin.length ? union(fill.topSkin, both) : both) : fill.topSkin;
  const bottom = both.length ? difference(fill.bottomSkin, both) : fill.bottomSkin;
  if (top.length === 0) return [{ pattern: bottomId, area: fillArea }];
  if (bottom.length === 0) return [{ pattern: topId, area: fillArea }];
  const bottomPart = difference(fillArea, offset(top, w / 2));
  const topPart = difference(fillArea, offset(bottom, w / 2));
  const out: SkinPart[] = [];
  if (bottomPart.length) out.push({ pattern: bottomId, area: bottomPart });
  if (topPart.length) out.push({ pattern: topId, area: topPart });
  return out;
}
