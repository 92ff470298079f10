/**
 * Classic walls of one layer: concentric loops of the line width inset from each island's outline.
 * The outer wall's centreline lies half a line width inside the outline, so its outer edge is the
 * model's surface. Each inner wall k is printed only where its full width fits between wall k-1 and
 * the inside (an opening of the region), so walls never overlap or cross in thin parts.
 */
import { offset, area, difference } from '../geometry/clip.js';
import type { ExPolygon, Polygon } from '../geometry/types.js';
import type { WallSet } from './types.js';
import { gapLoops, gapLoopWidthsMm, type GapLoop } from './gap-loops.js';

export type { GapLoop } from './gap-loops.js';

export interface IslandWalls {
  /** The island's outline (the layer section), µm. */
  outline: ExPolygon;
  /** The wall paths by index (classic: closed loops of the line width, and the gap loops). */
  walls: WallSet[];
  /** The area inside the innermost wall's inner edge (where skin and infill go), µm. */
  inner: ExPolygon[];
  /** Area too thin to print, mm². */
  lostMm2: number;
}

/**
 * Smallest area a wall's centreline may enclose (holes taken off), µm²: a 50 µm square. A smaller one is a
 * speck the nozzle cannot draw. (Gap loops have their own, smaller: MIN_GAP_LOOP_AREA_UM2 in gap-loops.ts.)
 */
const MIN_WALL_LOOP_AREA_UM2 = 0.05 * 1000 * 0.05 * 1000;

/** The rings of the areas big enough to print as loops (wall centrelines). */
export function rings(areas: readonly ExPolygon[]): Polygon[] {
  const out: Polygon[] = [];
  for (const a of areas) {
    if (Math.abs(area([a])) < MIN_WALL_LOOP_AREA_UM2) continue;
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
export function classicWalls(islands: readonly ExPolygon[], wallCount: number, lineWidthUm: number): IslandWalls[] {
  const w = lineWidthUm;
  const out: IslandWalls[] = [];
  for (const island of islands) {
    const wallLoops: Polygon[][] = [];
    const gapFill: GapLoop[] = [];
    if (wallCount === 0) {
      out.push({ outline: island, walls: [], inner: [island], lostMm2: 0 });
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
      if (area(inside) - area(covered) > w * w) gapFill.push(...gapLoops(difference(inside, covered), w));
      if (fit.length === 0) {
        inside = [];
        break;
      }
      const centre = offset(fit, w / 2);
      wallLoops.push(rings(centre));
      inside = fit;
    }
    const walls: WallSet[] = wallLoops.map((paths, wall) => ({
      role: 'wall',
      wall,
      closed: true,
      paths,
      widths: null,
    }));
    if (gapFill.length) {
      walls.push({
        role: 'wall-gap',
        wall: 1,
        closed: true,
        paths: gapFill.map((g) => g.loop),
        widths: gapLoopWidthsMm(gapFill),
      });
    }
    out.push({ outline: island, walls, inner: inside, lostMm2: 0 });
  }
  return out;
}
