/**
 * Gap fill for skin: the parts of an island's exposed surface that no bead of the layer reaches. Solid lines
 * leave wedges where they meet the skin's edge at a shallow angle (up to most of a line width between the last
 * line and the edge when they run nearly parallel); skin narrower than a line width (a sliver inside the walls
 * on a slope) gets no lines at all. These get thin loops (gapLoops), as the gaps between walls do.
 *
 * The work is done turned so that the skin lines run along x: the beads' footprint is then a stack of flat
 * strips, which the scanline booleans sweep several times faster than diagonal ones. The loops are turned back
 * (within a micrometre of where the unturned computation puts them).
 */
import { difference, strokeArea } from '../geometry/clip.js';
import type { ExPolygon, Polygon, Polyline } from '../geometry/types.js';
import { flatteningTurn, inverse, turnAreas, turnPts } from '../geometry/turn.js';
import { gapLoops, type GapLoop } from './gap-loops.js';

/**
 * Loops filling what the skin's beads miss of an exposed surface.
 * @param exposed the exposed surface inside the walls, slivers included (SkinAreas.exposed), µm
 * @param skinWalls closed skin-wall centrelines, µm
 * @param skinLines skin line centrelines, µm
 * @param lineWidthUm the width of their beads, µm
 */
export function skinGapFill(
  exposed: readonly ExPolygon[],
  skinWalls: readonly Polygon[],
  skinLines: readonly Polyline[],
  lineWidthUm: number,
): GapLoop[] {
  if (exposed.length === 0) return [];
  const turn = flatteningTurn(skinLines);
  if (!turn) return gapLoops(difference(exposed, strokeArea(skinLines, skinWalls, lineWidthUm, 'miter')), lineWidthUm);
  const lines = skinLines.map((l) => turnPts(l, turn));
  const walls = skinWalls.map((r) => turnPts(r, turn));
  const bare = difference(turnAreas(exposed, turn), strokeArea(lines, walls, lineWidthUm, 'miter'));
  const back = inverse(turn);
  return gapLoops(bare, lineWidthUm).map((g) => ({ loop: turnPts(g.loop, back), widthUm: g.widthUm }));
}
