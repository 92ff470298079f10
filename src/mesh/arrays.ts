/**
 * Raw arrays from a library caller (or the Doodle3D worker protocol): validated, then welded.
 */
import { StrataError } from '../errors.js';
import { printable } from './printable.js';
import type { Mesh, MeshObject, RawMeshArrays } from './types.js';
import { isWelded, weld } from './weld.js';

function isNumberArray(v: unknown): v is ArrayLike<number> {
  return Array.isArray(v) || (ArrayBuffer.isView(v) && !(v instanceof DataView));
}

export function fromArrays(raw: RawMeshArrays, name = 'mesh'): MeshObject {
  const what = printable(name);
  if (typeof raw !== 'object' || raw === null) {
    throw new StrataError('BAD_MESH', `${what}: expected { positions, indices? }`);
  }
  const p: unknown = raw.positions;
  if (!isNumberArray(p))
    throw new StrataError('BAD_MESH', `${what}: positions must be an array or typed array of numbers`);
  if (p.length % 3 !== 0) {
    throw new StrataError(
      'BAD_MESH',
      `${what}: positions holds ${p.length} numbers, not a multiple of 3 (x, y, z per vertex)`,
    );
  }
  const nVerts = p.length / 3;
  if (isWelded(raw)) {
    // a mesh Strata's loaders made: valid and welded; only its coordinates are checked again, in case
    // the caller changed them
    const q = (raw as unknown as Mesh).positions;
    for (let i = 0; i < q.length; i++) {
      if (!Number.isFinite(q[i]))
        throw new StrataError(
          'BAD_MESH',
          `${what}: positions[${i}] is ${q[i]}; every coordinate must be a finite number`,
        );
    }
    return { name, mesh: raw as unknown as Mesh };
  }
  const positions = new Float32Array(p.length);
  for (let i = 0; i < p.length; i++) {
    const v = p[i];
    if (typeof v !== 'number' || !Number.isFinite(v)) {
      throw new StrataError(
        'BAD_MESH',
        `${what}: positions[${i}] is ${printable(String(v))}; every coordinate must be a finite number`,
      );
    }
    positions[i] = v;
    if (!Number.isFinite(positions[i])) {
      throw new StrataError('BAD_MESH', `${what}: positions[${i}] = ${v} is too large for float32`);
    }
  }

  const ix: unknown = raw.indices;
  if (ix === undefined || ix === null) {
    if (nVerts % 3 !== 0) {
      throw new StrataError(
        'BAD_MESH',
        `${what}: without indices, positions must hold whole triangles (9 numbers each); it has ${p.length}`,
      );
    }
    return { name, mesh: weld(positions, null, what) };
  }
  if (!isNumberArray(ix))
    throw new StrataError('BAD_MESH', `${what}: indices must be an array or typed array of integers`);
  if (ix.length % 3 !== 0) {
    throw new StrataError('BAD_MESH', `${what}: indices holds ${ix.length} numbers, not a multiple of 3`);
  }
  const indices = new Uint32Array(ix.length);
  for (let i = 0; i < ix.length; i++) {
    const v = ix[i];
    if (typeof v !== 'number' || !Number.isInteger(v) || v < 0) {
      throw new StrataError(
        'BAD_MESH',
        `${what}: indices[${i}] is ${printable(String(v))}; indices must be non-negative integers`,
      );
    }
    if (v >= nVerts) {
      throw new StrataError(
        'BAD_MESH',
        `${what}: indices[${i}] = ${v} is out of range; the mesh has ${nVerts} vertices`,
      );
    }
    indices[i] = v;
  }
  return { name, mesh: weld(positions, indices, what) };
}
