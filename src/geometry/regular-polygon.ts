/** Regular polygons (drawn circles), µm: vertex k at angle 2πk/sides, counter-clockwise. */
import type { Polygon } from './types.js';

/** A regular polygon: its centre and circumradius, µm, and its side count. */
export interface RegularPolygon {
  x: number;
  y: number;
  r: number;
  sides: number;
}

/**
 * cos and sin of each vertex's angle, per side count: a constant table, each row made on first use and never
 * changed (the same numbers for every slice).
 */
const units = new Map<number, Float64Array>();

function unitsOf(sides: number): Float64Array {
  let u = units.get(sides);
  if (!u) {
    u = new Float64Array(2 * sides);
    for (let k = 0; k < sides; k++) {
      const a = (2 * Math.PI * k) / sides;
      u[2 * k] = Math.cos(a);
      u[2 * k + 1] = Math.sin(a);
    }
    units.set(sides, u);
  }
  return u;
}

/** How far a vertex rounded to whole µm may lie beyond the polygon's circle, µm (√2 / 2, rounded up). */
export const VERTEX_ROUNDING_UM = 1;

/** The polygon's vertices, rounded to whole µm (so they may lie up to VERTEX_ROUNDING_UM outside its circle). */
export function regularPolygon(x: number, y: number, r: number, sides: number): Polygon {
  const u = unitsOf(sides);
  const out: Polygon = new Array(sides);
  for (let k = 0; k < sides; k++) out[k] = { x: Math.round(x + r * u[2 * k]), y: Math.round(y + r * u[2 * k + 1]) };
  return out;
}

/** What an offset leaves of a shrunk polygon at least (µm from its edges to its centre), below which it is gone. */
export const MIN_LEFT_UM = 1;

/**
 * The polygon shrunk by d µm, as the mitred offset makes it (every vertex d / cos(π/sides) nearer the
 * centre), or null when nothing is left of it.
 */
export function shrunkRegularPolygon(c: RegularPolygon, d: number): Polygon | null {
  const cos = Math.cos(Math.PI / c.sides);
  if (c.r * cos - d < MIN_LEFT_UM) return null;
  return regularPolygon(c.x, c.y, c.r - d / cos, c.sides);
}
