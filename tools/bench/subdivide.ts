/**
 * The benchmark's big mesh: one round of midpoint subdivision of a binary STL. Each triangle (a, b, c) becomes
 * four, at its edge midpoints ab, bc, ca:
 *
 *       c
 *      / \
 *    ca---bc        (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)
 *    / \ / \
 *   a---ab--b
 *
 * The shape, the bounds, the volume and the G-code stay the same; only the triangle count grows four-fold, so
 * comparing the two isolates what the triangle count costs. Midpoints are rounded to float32 from the exact
 * mean of the two float32 ends: (p + q) / 2 is symmetric in p and q, so the two triangles that share an edge
 * compute the very same midpoint and a watertight mesh stays watertight. Orientation is kept (all four children
 * wind like their parent) and each child takes its parent's facet normal.
 */

const HEADER_BYTES = 80;
const FACET_BYTES = 50;

/** Triangle count of a binary STL, or null when the bytes are not one (size must be exactly 84 + 50·n). */
export function binaryStlTriangles(bytes: Uint8Array): number | null {
  if (bytes.length < HEADER_BYTES + 4) return null;
  const n = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(HEADER_BYTES, true);
  return HEADER_BYTES + 4 + FACET_BYTES * n === bytes.length ? n : null;
}

/** Subdivides a binary STL once; throws when the input is not a binary STL. */
export function subdivideBinaryStl(bytes: Uint8Array, header = 'midpoint subdivision x4'): Uint8Array {
  const n = binaryStlTriangles(bytes);
  if (n === null) throw new Error('midpoint subdivision needs a binary STL (84 + 50 bytes per triangle)');
  const src = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = new Uint8Array(HEADER_BYTES + 4 + FACET_BYTES * 4 * n);
  const dst = new DataView(out.buffer);
  out.set(new TextEncoder().encode(header.slice(0, HEADER_BYTES)));
  dst.setUint32(HEADER_BYTES, 4 * n, true);

  const v = new Float32Array(18); // a, b, c, ab, bc, ca (x, y, z each)
  const normal = new Float32Array(3);
  const A = 0,
    B = 3,
    C = 6,
    AB = 9,
    BC = 12,
    CA = 15;
  const mid = (p: number, q: number, into: number) => {
    for (let k = 0; k < 3; k++) v[into + k] = (v[p + k]! + v[q + k]!) / 2; // float64 mean, stored as float32
  };
  let o = HEADER_BYTES + 4;
  const put = (p: number, q: number, r: number) => {
    for (let k = 0; k < 3; k++) dst.setFloat32(o + 4 * k, normal[k]!, true);
    let w = o + 12;
    for (const corner of [p, q, r]) {
      for (let k = 0; k < 3; k++, w += 4) dst.setFloat32(w, v[corner + k]!, true);
    }
    // attribute byte count (bytes 48–49) stays 0
    o += FACET_BYTES;
  };
  for (let t = 0, i = HEADER_BYTES + 4; t < n; t++, i += FACET_BYTES) {
    for (let k = 0; k < 3; k++) normal[k] = src.getFloat32(i + 4 * k, true);
    for (let k = 0; k < 9; k++) v[k] = src.getFloat32(i + 12 + 4 * k, true);
    mid(A, B, AB);
    mid(B, C, BC);
    mid(C, A, CA);
    put(A, AB, CA);
    put(AB, B, BC);
    put(CA, BC, C);
    put(AB, BC, CA);
  }
  return out;
}
