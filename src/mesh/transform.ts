/**
 * Affine transforms as 12 numbers: the top three rows of a 4×4 matrix acting on column vectors,
 * row-major: [m00 m01 m02 tx, m10 m11 m12 ty, m20 m21 m22 tz]. x' = m00·x + m01·y + m02·z + tx.
 */

export type Affine = Float64Array;

export function identity(): Affine {
  return Float64Array.of(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0);
}

/** The transform that applies `first`, then `second`. */
export function compose(first: Affine, second: Affine): Affine {
  const a = second;
  const b = first;
  const r = new Float64Array(12);
  for (let row = 0; row < 3; row++) {
    const a0 = a[row * 4],
      a1 = a[row * 4 + 1],
      a2 = a[row * 4 + 2],
      a3 = a[row * 4 + 3];
    for (let col = 0; col < 4; col++) {
      r[row * 4 + col] = a0 * b[col] + a1 * b[4 + col] + a2 * b[8 + col] + (col === 3 ? a3 : 0);
    }
  }
  return r;
}

/** Determinant of the linear part: negative when the transform mirrors (and so flips winding). */
export function determinant(m: Affine): number {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
}

/** From a column-major 4×4 (three.js `Matrix4.elements`). The projective row is ignored. */
export function fromColumnMajor4x4(e: ArrayLike<number>): Affine {
  return Float64Array.of(e[0], e[4], e[8], e[12], e[1], e[5], e[9], e[13], e[2], e[6], e[10], e[14]);
}

/**
 * From a 3MF transform "m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32": 3MF multiplies row
 * vectors (p' = p·M), so m10 is the y coefficient of x' and m30 the x translation.
 */
export function from3mf(m: ArrayLike<number>): Affine {
  return Float64Array.of(m[0], m[3], m[6], m[9], m[1], m[4], m[7], m[10], m[2], m[5], m[8], m[11]);
}

/** Transform xyz triples from `src` (float64 or float32) into `dst` at `dstOffset` (in numbers). */
export function transformPoints(
  m: Affine,
  src: ArrayLike<number>,
  count: number,
  dst: Float32Array,
  dstOffset: number,
): void {
  const m0 = m[0],
    m1 = m[1],
    m2 = m[2],
    m3 = m[3];
  const m4 = m[4],
    m5 = m[5],
    m6 = m[6],
    m7 = m[7];
  const m8 = m[8],
    m9 = m[9],
    m10 = m[10],
    m11 = m[11];
  for (let i = 0, o = dstOffset; i < count * 3; i += 3, o += 3) {
    const x = src[i],
      y = src[i + 1],
      z = src[i + 2];
    dst[o] = m0 * x + m1 * y + m2 * z + m3;
    dst[o + 1] = m4 * x + m5 * y + m6 * z + m7;
    dst[o + 2] = m8 * x + m9 * y + m10 * z + m11;
  }
}
