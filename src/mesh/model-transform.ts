/**
 * The linear transform a model gets before it is placed: Y-up input turned Z-up, then rotations about
 * X, Y and Z, then scaling along the bed axes. Placement adds the translation afterwards, so the
 * centre the transform turns and scales about does not matter.
 */
import type { Affine } from './transform.js';
import { compose, identity } from './transform.js';

export interface ModelTransform {
  /** Which input axis points up; 'y' is turned so that +Y becomes +Z. */
  upAxis: 'y' | 'z';
  /** Degrees about X, then Y, then Z (right-handed: counter-clockwise looking down the axis). */
  rotate: readonly [number, number, number];
  /** Factors along the bed's X, Y and Z, applied after rotating. */
  scale: readonly [number, number, number];
}

export const NO_TRANSFORM: ModelTransform = Object.freeze({ upAxis: 'z', rotate: [0, 0, 0], scale: [1, 1, 1] } as const);

export function isIdentity(t: ModelTransform): boolean {
  return t.upAxis === 'z' && t.rotate.every((a) => a % 360 === 0) && t.scale.every((s) => s === 1);
}

/** Exact sine and cosine for multiples of 90°, so quarter turns keep coordinates exact. */
function sinCos(degrees: number): [number, number] {
  const d = ((degrees % 360) + 360) % 360;
  if (d === 0) return [0, 1];
  if (d === 90) return [1, 0];
  if (d === 180) return [0, -1];
  if (d === 270) return [-1, 0];
  const r = (d * Math.PI) / 180;
  return [Math.sin(r), Math.cos(r)];
}

function rotation(axis: 0 | 1 | 2, degrees: number): Affine {
  const [s, c] = sinCos(degrees);
  const m = identity();
  const a = (axis + 1) % 3;
  const b = (axis + 2) % 3;
  // rows a and b of the 3×4 matrix: a' = c·a − s·b, b' = s·a + c·b
  m[a * 4 + a] = c;
  m[a * 4 + b] = -s;
  m[b * 4 + a] = s;
  m[b * 4 + b] = c;
  return m;
}

/** The whole linear part as an affine transform (no translation). */
export function modelMatrix(t: ModelTransform): Affine {
  let m = t.upAxis === 'y' ? rotation(0, 90) : identity();
  m = compose(m, rotation(0, t.rotate[0]));
  m = compose(m, rotation(1, t.rotate[1]));
  m = compose(m, rotation(2, t.rotate[2]));
  const s = identity();
  s[0] = t.scale[0];
  s[5] = t.scale[1];
  s[10] = t.scale[2];
  return compose(m, s);
}
