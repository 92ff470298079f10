/** Shapes for tests, in µm. */
import type { ExPolygon } from '#strata/geometry/types.js';

/** The axis-aligned square [x0, x0+s] × [y0, y0+s], counter-clockwise, without holes. */
export const square = (x0: number, y0: number, s: number): ExPolygon => ({
  outer: [
    { x: x0, y: y0 },
    { x: x0 + s, y: y0 },
    { x: x0 + s, y: y0 + s },
    { x: x0, y: y0 + s },
  ],
  holes: [],
});

/** The axis-aligned rectangle [x0, x1] × [y0, y1], counter-clockwise, without holes. */
export const rect = (x0: number, y0: number, x1: number, y1: number): ExPolygon => ({
  outer: [
    { x: x0, y: y0 },
    { x: x1, y: y0 },
    { x: x1, y: y1 },
    { x: x0, y: y1 },
  ],
  holes: [],
});

/** A regular polygon of `n` sides approximating the disc of radius `r` round (cx, cy), counter-clockwise. */
export const disc = (cx: number, cy: number, r: number, n = 64): ExPolygon => ({
  outer: Array.from({ length: n }, (_, k) => ({
    x: Math.round(cx + r * Math.cos((2 * Math.PI * k) / n)),
    y: Math.round(cy + r * Math.sin((2 * Math.PI * k) / n)),
  })),
  holes: [],
});
