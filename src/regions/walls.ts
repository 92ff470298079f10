/**
 * Walls of one layer: concentric loops inset from each island's outline.
 * The outer wall's centreline lies half a line width inside the outline, so its outer edge is the
 * model's surface. Each inner wall k is printed only where its full width fits between wall k-1 and
 * the inside (an opening of the region), so walls never overlap or cross in thin parts.
 */
import { offset, area, difference, ringArea } from '../geometry/clip.js';
import type { ExPolygon, Polygon } from '../geometry/types.js';

export interface IslandWalls {
  /** The island's outline (the layer section), µm. */
  outline: ExPolygon;
  /** wallLoops[k] are the closed centrelines of wall k (0 = outer), each ring as printed. */
  wallLoops: Polygon[][];
  /** The area inside the innermost wall's inner edge (where skin and infill go), µm. */
  inner: ExPolygon[];
  /** Gap fill: thin loops (with their bead width, µm) for strips between walls too narrow for another wall. */
  gapFill: GapLoop[];
}

export interface GapLoop {
  loop: Polygon;
  widthUm: number;
}

/** Strips narrower than this fraction of a line width are left empty (they would print nothing). */
const MIN_GAP_FRACTION = 0.3;

/** Perimeter of an island's rings, µm. */
function perimeter(a: ExPolygon): number {
  let p = 0;
  for (const r of [a.outer, ...a.holes]) {
    for (let i = 0, j = r.length - 1; i < r.length; j = i++) p += Math.hypot(r[i].x - r[j].x, r[i].y - r[j].y);
  }
  return p;
}

/**
 * Fill thin strips (narrower than two line widths) with one loop each, whose bead is half the
 * strip's mean width: going round the strip, its two passes cover it side by side.
 * Mean width of a strip = 2·area / perimeter.
 */
function gapLoops(gaps: readonly ExPolygon[], w: number, out: GapLoop[]): void {
  for (const g of gaps) {
    const a = Math.abs(ringArea(g.outer)) - g.holes.reduce((s, h) => s + Math.abs(ringArea(h)), 0);
    const d = (2 * a) / Math.max(perimeter(g), 1);
    if (d < MIN_GAP_FRACTION * w || d > 2 * w) continue;
    for (const piece of offset([g], -d / 4)) {
      if (Math.abs(ringArea(piece.outer)) < MIN_LOOP_AREA_UM2 / 4) continue;
      out.push({ loop: piece.outer, widthUm: Math.round(d / 2) });
    }
  }
}

/** Smallest loop worth printing, µm²: anything smaller is a speck the nozzle cannot draw. */
const MIN_LOOP_AREA_UM2 = 0.05 * 1000 * 0.05 * 1000;

function rings(areas: readonly ExPolygon[]): Polygon[] {
  const out: Polygon[] = [];
  for (const a of areas) {
    if (Math.abs(area([a])) < MIN_LOOP_AREA_UM2) continue;
    out.push(a.outer);
    for (const h of a.holes) out.push(h);
  }
  return out;
}

/**
 * Compute the walls of each island.
 * @param islands the layer's islands, µm
 * @param wallCount number of walls
 * @param lineWidthUm extrusion width, µm
 */
export function computeWalls(islands: readonly ExPolygon[], wallCount: number, lineWidthUm: number): IslandWalls[] {
  const w = lineWidthUm;
  const out: IslandWalls[] = [];
  for (const island of islands) {
    const wallLoops: Polygon[][] = [];
    const gapFill: GapLoop[] = [];
    if (wallCount === 0) {
      out.push({ outline: island, wallLoops, inner: [island], gapFill });
      continue;
    }
    const outer = offset([island], -w / 2);
    wallLoops.push(rings(outer));
    // Inner edge of wall 0.
    let inside = offset(outer, -w / 2);
    for (let k = 1; k < wallCount && inside.length > 0; k++) {
      // Wall k fits where the area inside wall k-1, shrunk by a full width, is not empty.
      const fit = offset(inside, -w);
      // what wall k's bead covers: from its inner edge (fit) out by one width
      const covered = fit.length ? offset(fit, w) : [];
      if (area(inside) - area(covered) > w * w) gapLoops(difference(inside, covered), w, gapFill);
      if (fit.length === 0) {
        inside = [];
        break;
      }
      const centre = offset(fit, w / 2);
      wallLoops.push(rings(centre));
      inside = fit;
    }
    out.push({ outline: island, wallLoops, inner: inside, gapFill });
  }
  return out;
}
