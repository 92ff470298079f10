/**
 * Gap fill for skin: the parts of an island's exposed surface that no bead of the layer reaches. Solid lines
 * leave wedges where they meet the skin's edge at a shallow angle (up to most of a line width between the last
 * line and the edge when they run nearly parallel); skin narrower than a line width (a sliver inside the walls
 * on a slope) gets no lines at all. Each such strip gets a thin loop, as the walls' gap fill does: a quarter of the strip's
 * width in from its edge, half its width wide, so that going round the strip its two passes cover it side by side
 * (and nested loops where a wedge is wider than that).
 */
import { difference, offset, opening, ringArea, strokeArea } from '../geometry/clip.js';
import { islandArea, stripWidth } from './strip-width.js';
import type { ExPolygon, Polygon, Polyline } from '../geometry/types.js';

export interface SkinGapLoop {
  loop: Polygon;
  widthUm: number;
}

/** Strips whose width (stripWidth) is below this fraction of a line width are left (nothing prints that thin). */
const MIN_GAP_FRACTION = 0.3;
/** Strips wider than this many line widths are not gaps (a loop of half their width would not cover them). */
const MAX_GAP_WIDTHS = 2;
/** At most this many nested loops per gap. */
const MAX_NESTED_LOOPS = 4;
/** Loops enclosing less than this (µm²) are specks the nozzle cannot draw. */
const MIN_LOOP_AREA_UM2 = 25 * 25;

/**
 * Loops filling what the layer's beads miss of an exposed surface.
 * @param exposed the exposed surface inside the walls, slivers included (SkinAreas.exposed), µm
 * @param skinWalls closed skin-wall centrelines, µm
 * @param skinLines skin line centrelines, µm
 * @param lineWidthUm the width of their beads, µm
 */
export function skinGapFill(
  exposed: readonly ExPolygon[], skinWalls: readonly Polygon[], skinLines: readonly Polyline[], lineWidthUm: number,
): SkinGapLoop[] {
  if (exposed.length === 0) return [];
  const w = lineWidthUm;
  const gaps = difference(exposed, strokeArea(skinLines, skinWalls, w, 'miter'));
  const out: SkinGapLoop[] = [];
  // parts thinner than a printable bead go first: they would also join real gaps into long pieces of small mean width
  const minArea = (MIN_GAP_FRACTION * w) ** 2;
  const pieces = gaps.filter((g) => islandArea(g) >= minArea);
  for (const g of pieces.length ? opening(pieces, (MIN_GAP_FRACTION * w) / 2) : []) {
    const d = stripWidth(g);
    if (d < MIN_GAP_FRACTION * w || d > MAX_GAP_WIDTHS * w) continue;
    // loops of half the strip's width, a bead apart: one covers a strip; a wedge wider at one end than the
    // strip's width gets more, nested towards its wide end
    const bead = d / 2;
    for (let k = 0, inset = bead / 2; k < MAX_NESTED_LOOPS; k++, inset += bead) {
      const rings = offset([g], -inset).filter((p) => Math.abs(ringArea(p.outer)) >= MIN_LOOP_AREA_UM2);
      if (rings.length === 0) break;
      for (const piece of rings) out.push({ loop: piece.outer, widthUm: Math.round(bead) });
    }
  }
  return out;
}
