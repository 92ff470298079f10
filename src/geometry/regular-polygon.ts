/** Regular polygons (drawn circles), µm: vertex k at angle 2πk/sides, counter-clockwise. */
import type { Polygon } from './types.js';

/** A regular polygon: its centre and circumradius, µm, and its side count. */
export interface RegularPolygon {
  x: number;
  y: number;
  r: number;
  sides: number;
}

/** The polygon's vertices, rounded to whole µm. */
export function regularPolygon(x: number, y: number, r: number, sides: number): Polygon {
  const out: Polygon = [];
  for (let k = 0; k < sides; k++) {
    const a = (2 * Math.PI * k) / sides;
    out.push({ x: Math.round(x + r * Math.cos(a)), y: Math.round(y + r * Math.sin(a)) });
  }
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
