/**
 * Putting objects on the build plate: merge them into one mesh, drop it to z = 0, optionally centre
 * it, and refuse it when it does not fit the build volume.
 */
import { StrataError } from '../errors.js';
import type { Mesh, MeshObject } from './types.js';

/** Concatenate the objects' meshes (no welding across objects). */
export function mergeObjects(objects: MeshObject[]): Mesh {
  let nPos = 0;
  let nIdx = 0;
  for (const o of objects) {
    nPos += o.mesh.positions.length;
    nIdx += o.mesh.indices.length;
  }
  const positions = new Float32Array(nPos);
  const indices = new Uint32Array(nIdx);
  let p = 0;
  let k = 0;
  for (const o of objects) {
    const base = p / 3;
    positions.set(o.mesh.positions, p);
    const src = o.mesh.indices;
    for (let i = 0; i < src.length; i++) indices[k + i] = src[i] + base;
    p += o.mesh.positions.length;
    k += src.length;
  }
  return { positions, indices };
}

export interface PlaceOptions {
  /** Move the XY bounding-box centre to the bed centre. */
  center: boolean;
  bedWidth: number;
  bedLength: number;
  bedHeight: number;
  /** The bed origin (0, 0) is its centre (delta printers) rather than its front-left corner. */
  originAtCenter: boolean;
}

/** Tolerance for "fits" comparisons, in mm (float32 rounding of coordinates near 200 mm is ~1e-5). */
const FIT_EPS = 1e-3;

export function placeOnBed(mesh: Mesh, opts: PlaceOptions): { mesh: Mesh; offset: [number, number, number] } {
  for (const key of ['bedWidth', 'bedLength', 'bedHeight'] as const) {
    const v = opts[key];
    if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) {
      throw new StrataError('BAD_SETTING', `${key} must be a positive number of mm, got ${String(v)}`);
    }
  }
  const { positions, indices } = mesh;
  if (indices.length === 0) throw new StrataError('EMPTY_MODEL', 'the model has no triangles: there is nothing to print');
  let x0 = Infinity, y0 = Infinity, z0 = Infinity;
  let x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
  const nVerts = positions.length / 3;
  for (let i = 0; i < indices.length; i++) {
    const v = indices[i];
    if (v >= nVerts) throw new StrataError('BAD_MESH', `triangle ${Math.floor(i / 3)} uses vertex ${v} but there are only ${nVerts} vertices`);
    const x = positions[v * 3], y = positions[v * 3 + 1], z = positions[v * 3 + 2];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  if (![x0, y0, z0, x1, y1, z1].every(Number.isFinite)) {
    throw new StrataError('BAD_MESH', 'the model has coordinates that are not finite numbers');
  }
  const { bedWidth: w, bedLength: l, bedHeight: h } = opts;
  let dx = 0;
  let dy = 0;
  if (opts.center) {
    const cx = opts.originAtCenter ? 0 : w / 2;
    const cy = opts.originAtCenter ? 0 : l / 2;
    dx = cx - (x0 + x1) / 2;
    dy = cy - (y0 + y1) / 2;
  }
  const dz = -z0;
  const out = new Float32Array(positions.length);
  for (let i = 0; i < positions.length; i += 3) {
    out[i] = positions[i] + dx;
    out[i + 1] = positions[i + 1] + dy;
    out[i + 2] = positions[i + 2] + dz;
  }

  const sx = x1 - x0, sy = y1 - y0, sz = z1 - z0;
  const bedX0 = opts.originAtCenter ? -w / 2 : 0;
  const bedY0 = opts.originAtCenter ? -l / 2 : 0;
  const problems: string[] = [];
  if (sx > w + FIT_EPS) problems.push(`${mm(sx)} mm wide in X, the bed ${fmt(w)} mm`);
  else if (x0 + dx < bedX0 - FIT_EPS || x1 + dx > bedX0 + w + FIT_EPS) {
    problems.push(`X spans ${mm(x0 + dx)} to ${mm(x1 + dx)} mm, outside the bed's ${fmt(bedX0)} to ${fmt(bedX0 + w)} mm`);
  }
  if (sy > l + FIT_EPS) problems.push(`${mm(sy)} mm deep in Y, the bed ${fmt(l)} mm`);
  else if (y0 + dy < bedY0 - FIT_EPS || y1 + dy > bedY0 + l + FIT_EPS) {
    problems.push(`Y spans ${mm(y0 + dy)} to ${mm(y1 + dy)} mm, outside the bed's ${fmt(bedY0)} to ${fmt(bedY0 + l)} mm`);
  }
  if (sz > h + FIT_EPS) problems.push(`${mm(sz)} mm tall in Z, the volume ${fmt(h)} mm`);
  if (problems.length > 0) {
    throw new StrataError(
      'DOES_NOT_FIT',
      `the model is ${mm(sx)} × ${mm(sy)} × ${mm(sz)} mm and does not fit the ${fmt(w)} × ${fmt(l)} × ${fmt(h)} mm build volume (${problems.join('; ')})`,
    );
  }
  return { mesh: { positions: out, indices }, offset: [dx, dy, dz] };
}

/** One decimal, as model sizes are shown. */
function mm(v: number): string {
  const s = v.toFixed(1);
  return s === '-0.0' ? '0.0' : s;
}

/** A setting as the user wrote it: 220 → "220", 220.5 → "220.5". */
function fmt(v: number): string {
  return String(Math.round(v * 1000) / 1000);
}
