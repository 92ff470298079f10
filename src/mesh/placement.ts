/**
 * Where an object stands on the bed, as an editor (the web page) keeps it: a linear part (rotation
 * and scale) applied to the model's own coordinates, and the bed point under the centre of the
 * result's bounding box; its bottom rests on z = 0. Turned into an affine transform from the
 * model's vertices, so the page draws and slices the same placement.
 */
import { transformPoints, type Affine } from './transform.js';
import type { MeshObject } from './types.js';
import { OPPOSITE_COS_EPS } from '../geometry/tolerances.js';

/** Where an object stands: its turn and scale, and where on the bed. */
export interface Placement {
  /** Row-major 3×3 matrix: rotation and scale, applied first. */
  linear: readonly number[];
  /** Bed XY under the centre of the placed bounding box, mm. */
  center: readonly [number, number];
}

/** The row-major 3×3 identity: no turn, no scale. */
export const IDENTITY_LINEAR: readonly number[] = Object.freeze([1, 0, 0, 0, 1, 0, 0, 0, 1]);

export function isIdentityLinear(m: readonly number[]): boolean {
  return m.every((v, i) => v === IDENTITY_LINEAR[i]);
}

/** Bounds in X, Y and Z, mm. */
export interface Box {
  min: [number, number, number];
  max: [number, number, number];
}

/**
 * Bounds after the linear part `m` (row-major 3×3) of the objects' vertices that triangles use
 * (as placeOnBed counts them), or of every vertex in a flat xyz array.
 */
export function linearBounds(
  objects: readonly MeshObject[] | Float32Array,
  m: readonly number[] = IDENTITY_LINEAR,
): Box {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  const add = (p: ArrayLike<number>, i: number) => {
    const x = p[i],
      y = p[i + 1],
      z = p[i + 2];
    for (let r = 0; r < 3; r++) {
      const v = m[r * 3] * x + m[r * 3 + 1] * y + m[r * 3 + 2] * z;
      if (v < min[r]) min[r] = v;
      if (v > max[r]) max[r] = v;
    }
  };
  if (objects instanceof Float32Array) {
    for (let i = 0; i + 2 < objects.length; i += 3) add(objects, i);
  } else {
    for (const o of objects) {
      const { positions, indices } = o.mesh;
      for (let k = 0; k < indices.length; k++) add(positions, indices[k] * 3);
    }
  }
  return { min, max };
}

/** The affine transform (model → bed) of a placement, given the bounds after its linear part. */
export function placementAffine(p: Placement, box: Box): Affine {
  const m = p.linear;
  const tx = p.center[0] - (box.min[0] + box.max[0]) / 2;
  const ty = p.center[1] - (box.min[1] + box.max[1]) / 2;
  const tz = -box.min[2];
  return Float64Array.of(m[0], m[1], m[2], tx, m[3], m[4], m[5], ty, m[6], m[7], m[8], tz);
}

/** The objects moved to their placement (new arrays; the inputs are not changed). */
export function placeObjects(objects: readonly MeshObject[], p: Placement): MeshObject[] {
  const affine = placementAffine(p, linearBounds(objects, p.linear));
  const mirrored = determinant3(p.linear) < 0;
  return objects.map((o) => {
    const n = o.mesh.positions.length / 3;
    const positions = new Float32Array(n * 3);
    transformPoints(affine, o.mesh.positions, n, positions, 0);
    let indices = o.mesh.indices;
    if (mirrored) {
      // a mirror turns the triangles inside out: swap two corners to keep them facing outwards
      indices = indices.slice();
      for (let t = 0; t < indices.length; t += 3) [indices[t + 1], indices[t + 2]] = [indices[t + 2], indices[t + 1]];
    }
    return { name: o.name, mesh: { positions, indices } };
  });
}

function determinant3(m: readonly number[]): number {
  return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
}

/** Product of two row-major 3×3 matrices (a·b: b applies first). */
export function mul3(a: readonly number[], b: readonly number[]): number[] {
  const r = new Array<number>(9);
  for (let i = 0; i < 3; i++)
    for (let j = 0; j < 3; j++) r[i * 3 + j] = a[i * 3] * b[j] + a[i * 3 + 1] * b[3 + j] + a[i * 3 + 2] * b[6 + j];
  return r;
}

/** Rotation by `deg` about a coordinate axis, exact for multiples of 90°. */
export function axisRotation(axis: 'x' | 'y' | 'z', deg: number): number[] {
  const quarter = deg / 90;
  const c = Number.isInteger(quarter) ? [1, 0, -1, 0][((quarter % 4) + 4) % 4] : Math.cos((deg * Math.PI) / 180);
  const s = Number.isInteger(quarter) ? [0, 1, 0, -1][((quarter % 4) + 4) % 4] : Math.sin((deg * Math.PI) / 180);
  if (axis === 'x') return [1, 0, 0, 0, c, -s, 0, s, c];
  if (axis === 'y') return [c, 0, s, 0, 1, 0, -s, 0, c];
  return [c, -s, 0, s, c, 0, 0, 0, 1];
}

/** The rotation taking unit vector `from` to unit vector `to` (Rodrigues). */
export function rotationBetween(from: readonly number[], to: readonly number[]): number[] {
  const [ax, ay, az] = from,
    [bx, by, bz] = to;
  const cx = ay * bz - az * by,
    cy = az * bx - ax * bz,
    cz = ax * by - ay * bx;
  const c = ax * bx + ay * by + az * bz;
  if (c < -1 + OPPOSITE_COS_EPS) {
    // opposite: half a turn about any axis perpendicular to `from`
    const p = Math.abs(ax) < 0.9 ? [1, 0, 0] : [0, 1, 0];
    let ux = ay * p[2] - az * p[1],
      uy = az * p[0] - ax * p[2],
      uz = ax * p[1] - ay * p[0];
    const l = Math.hypot(ux, uy, uz);
    ux /= l;
    uy /= l;
    uz /= l;
    return [
      2 * ux * ux - 1,
      2 * ux * uy,
      2 * ux * uz,
      2 * uy * ux,
      2 * uy * uy - 1,
      2 * uy * uz,
      2 * uz * ux,
      2 * uz * uy,
      2 * uz * uz - 1,
    ];
  }
  const k = 1 / (1 + c);
  return [
    c + cx * cx * k,
    cx * cy * k - cz,
    cx * cz * k + cy,
    cy * cx * k + cz,
    c + cy * cy * k,
    cy * cz * k - cx,
    cz * cx * k - cy,
    cz * cy * k + cx,
    c + cz * cz * k,
  ];
}
