/**
 * The linear transform a model gets before it is placed: Y-up input turned Z-up, then rotations about
 * X, Y and Z, then scaling along the bed axes. Placement adds the translation afterwards, so the
 * centre the transform turns and scales about does not matter.
 */
import { axisRotation, IDENTITY_LINEAR, mul3 } from './placement.js';
import type { Affine } from './transform.js';

export interface ModelTransform {
  /** Which input axis points up; 'y' is turned so that +Y becomes +Z. */
  upAxis: 'y' | 'z';
  /** Degrees about X, then Y, then Z (right-handed: counter-clockwise looking down the axis). */
  rotate: readonly [number, number, number];
  /** Factors along the bed's X, Y and Z, applied after rotating. */
  scale: readonly [number, number, number];
}

export const NO_TRANSFORM: ModelTransform = Object.freeze({
  upAxis: 'z',
  rotate: [0, 0, 0],
  scale: [1, 1, 1],
} as const);

export function isIdentity(t: ModelTransform): boolean {
  return t.upAxis === 'z' && t.rotate.every((a) => a % 360 === 0) && t.scale.every((s) => s === 1);
}

/** The whole linear part as an affine transform (no translation). */
export function modelMatrix(t: ModelTransform): Affine {
  // mul3(a, b): b applies first
  let m: number[] = t.upAxis === 'y' ? axisRotation('x', 90) : [...IDENTITY_LINEAR];
  m = mul3(axisRotation('x', t.rotate[0]), m);
  m = mul3(axisRotation('y', t.rotate[1]), m);
  m = mul3(axisRotation('z', t.rotate[2]), m);
  m = mul3([t.scale[0], 0, 0, 0, t.scale[1], 0, 0, 0, t.scale[2]], m);
  return Float64Array.of(m[0], m[1], m[2], 0, m[3], m[4], m[5], 0, m[6], m[7], m[8], 0);
}
