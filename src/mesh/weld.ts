/**
 * Vertex welding: vertices with bit-identical float32 coordinates become one vertex (-0 equals +0).
 * A hash table keyed on the float bits keeps it linear; only vertices that triangles use are kept.
 */
import { StrataError } from '../errors.js';
import type { Mesh } from './types.js';

const NON_FINITE = 0x7f800000;

/**
 * The meshes `weld` made (welding one again changes nothing: its vertices are distinct and numbered in
 * the order triangles first use them), so later stages take them as they are instead of welding a
 * 225 k-triangle mesh two more times.
 */
const WELDED = new WeakSet<Mesh>();

/** Whether `mesh` came out of `weld` (its arrays as weld left them: Float32Array and Uint32Array). */
export function isWelded(mesh: unknown): boolean {
  return typeof mesh === 'object' && mesh !== null && WELDED.has(mesh as Mesh);
}

function hash(bx: number, by: number, bz: number): number {
  let h = Math.imul(bx, 0x9e3779b1) ^ Math.imul(by, 0x85ebca77) ^ Math.imul(bz, 0xc2b2ae3d);
  h ^= h >>> 15;
  h = Math.imul(h, 0x2c1b3c6d);
  return h ^ (h >>> 13);
}

/** A table of `cap` slots (a power of two) holding vertices 0..count-1 of `bits` (linear probing). */
function rehash(bits: Uint32Array, count: number, cap: number): Int32Array {
  const table = new Int32Array(cap).fill(-1);
  const mask = cap - 1;
  for (let id = 0; id < count; id++) {
    let h = hash(bits[id * 3], bits[id * 3 + 1], bits[id * 3 + 2]) & mask;
    while (table[h] >= 0) h = (h + 1) & mask;
    table[h] = id;
  }
  return table;
}

/**
 * Weld `positions` (xyz per vertex). With `indices`, they index `positions`; with `null`, every
 * three consecutive vertices form a triangle (a "triangle soup", as STL stores it).
 * `what` names the source in error messages.
 */
export function weld(positions: Float32Array, indices: Uint32Array | null, what = 'mesh'): Mesh {
  if (positions.length % 3 !== 0) {
    throw new StrataError('BAD_MESH', `${what}: ${positions.length} coordinates is not a multiple of 3`);
  }
  const nVerts = positions.length / 3;
  const nCorners = indices ? indices.length : nVerts;
  if (nCorners % 3 !== 0) {
    throw new StrataError('BAD_MESH', `${what}: ${nCorners} triangle corners is not a multiple of 3`);
  }
  const maxUnique = Math.min(nVerts, nCorners);
  // closed meshes have about one vertex per six corners: the table starts at twice that and doubles
  // whenever it is half full, so it stays small enough to sit in the cache
  let cap = 16;
  while (cap < Math.min(maxUnique * 2, nCorners / 3)) cap *= 2;
  let mask = cap - 1;
  let table: Int32Array = new Int32Array(cap).fill(-1);
  const bits = new Uint32Array(positions.buffer, positions.byteOffset, positions.length);
  const outBits = new Uint32Array(maxUnique * 3);
  const outIdx = new Uint32Array(nCorners);
  const cache = indices ? new Int32Array(nVerts).fill(-1) : null;
  let count = 0;

  for (let c = 0; c < nCorners; c++) {
    let v = c;
    if (indices !== null && cache !== null) {
      v = indices[c];
      if (v >= nVerts) {
        throw new StrataError(
          'BAD_MESH',
          `${what}: triangle ${Math.floor(c / 3)} uses vertex ${v} but there are only ${nVerts} vertices`,
        );
      }
      const known = cache[v];
      if (known >= 0) {
        outIdx[c] = known;
        continue;
      }
    }
    let bx = bits[v * 3];
    let by = bits[v * 3 + 1];
    let bz = bits[v * 3 + 2];
    if ((bx & NON_FINITE) === NON_FINITE || (by & NON_FINITE) === NON_FINITE || (bz & NON_FINITE) === NON_FINITE) {
      const where = indices ? `vertex ${v}` : `triangle ${Math.floor(c / 3)}`;
      throw new StrataError('BAD_MESH', `${what}: ${where} has a coordinate that is not a finite number`);
    }
    if (bx === 0x80000000) bx = 0;
    if (by === 0x80000000) by = 0;
    if (bz === 0x80000000) bz = 0;
    let h = hash(bx, by, bz) & mask;
    let id: number;
    for (;;) {
      id = table[h];
      if (id < 0) {
        id = count++;
        table[h] = id;
        outBits[id * 3] = bx;
        outBits[id * 3 + 1] = by;
        outBits[id * 3 + 2] = bz;
        if (2 * count > cap) {
          cap *= 2;
          mask = cap - 1;
          table = rehash(outBits, count, cap);
        }
        break;
      }
      if (outBits[id * 3] === bx && outBits[id * 3 + 1] === by && outBits[id * 3 + 2] === bz) break;
      h = (h + 1) & mask;
    }
    outIdx[c] = id;
    if (cache !== null) cache[v] = id;
  }
  const mesh: Mesh = { positions: new Float32Array(outBits.buffer.slice(0, count * 12)), indices: outIdx };
  WELDED.add(mesh);
  return mesh;
}
