/** Shapes for tests, in µm. */
import type { ExPolygon } from './types.js';

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
