/**
 * three.js input without depending on three.js: duck-typed BufferGeometry, Mesh, Group, Scene.
 * Every visible mesh in the tree becomes one MeshObject (instanced meshes: one per instance), with
 * its world transform applied. Lines, points and other non-mesh objects are skipped, and so are
 * objects with `visible === false` and everything under them (as three.js does not draw them).
 * Coordinates are taken as they are (Z up); `upAxis: 'y'` turns a Y-up scene when it is placed.
 */
import { StrataError } from '../errors.js';
import { MAX_MODEL_TRIANGLES } from './limits.js';
import { printable } from './printable.js';
import { compose, determinant, fromColumnMajor4x4, identity, transformPoints, type Affine } from './transform.js';
import type { MeshObject } from './types.js';
import { weld } from './weld.js';

type Dict = Record<string, unknown>;

/** Most triangles accepted from one scene. */
export const MAX_THREE_TRIANGLES = MAX_MODEL_TRIANGLES;
const MAX_TREE_DEPTH = 256;

function isDict(v: unknown): v is Dict {
  return typeof v === 'object' && v !== null;
}

function isNumberArray(v: unknown): v is ArrayLike<number> {
  if (Array.isArray(v)) return true;
  return (
    ArrayBuffer.isView(v) && !(v instanceof DataView) && !(v instanceof BigInt64Array) && !(v instanceof BigUint64Array)
  );
}

/** Looks like a three.js BufferGeometry (and not an Object3D). */
export function isThreeGeometry(v: unknown): boolean {
  if (!isDict(v) || v.isObject3D === true) return false;
  return v.isBufferGeometry === true || (isDict(v.attributes) && isDict(v.attributes.position));
}

/** Looks like a three.js Object3D (Mesh, Group, Scene, ...) or a BufferGeometry. */
export function isThreeLike(v: unknown): boolean {
  if (!isDict(v)) return false;
  return v.isObject3D === true || v.isMesh === true || v.isScene === true || v.isGroup === true || isThreeGeometry(v);
}

/**
 * Whether the object says it is Y-up: its `up` vector is +Y, three.js's default (`Object3D.DEFAULT_UP`),
 * which a Z-up application changes to (0, 0, 1).
 */
export function threeLooksYUp(object: unknown): boolean {
  if (!isDict(object) || !isDict(object.up)) return false;
  const { x, y, z } = object.up;
  return x === 0 && y === 1 && z === 0;
}

export function fromThree(object: unknown): MeshObject[] {
  if (!isDict(object))
    throw new StrataError('UNSUPPORTED_FORMAT', 'fromThree expects a three.js Object3D or BufferGeometry');
  if (isThreeGeometry(object)) {
    const name = typeof object.name === 'string' && object.name !== '' ? object.name : 'mesh';
    return [{ name, mesh: geometryToMesh(object, identity(), name) }];
  }
  if (!isThreeLike(object) && !Array.isArray(object.children)) {
    throw new StrataError(
      'UNSUPPORTED_FORMAT',
      'fromThree expects a three.js Object3D (Mesh, Group, Scene) or BufferGeometry',
    );
  }
  const useWorld = typeof object.updateMatrixWorld === 'function';
  if (useWorld) (object.updateMatrixWorld as (force?: boolean) => void).call(object, true);

  const out: MeshObject[] = [];
  const seen = new Set<unknown>();
  let triangles = 0;
  let hidden = 0;
  const add = (name: string, geometry: Dict, m: Affine): void => {
    const mesh = geometryToMesh(geometry, m, name);
    triangles += mesh.indices.length / 3;
    if (triangles > MAX_THREE_TRIANGLES) {
      throw new StrataError('LIMIT_EXCEEDED', `the scene has more than ${MAX_THREE_TRIANGLES} triangles`);
    }
    if (mesh.indices.length > 0) out.push({ name, mesh });
  };

  const visit = (node: Dict, parentWorld: Affine, depth: number): void => {
    if (seen.has(node)) return;
    if (depth > MAX_TREE_DEPTH)
      throw new StrataError('LIMIT_EXCEEDED', `the scene is nested deeper than ${MAX_TREE_DEPTH} levels`);
    seen.add(node);
    if (node.visible === false) {
      hidden++;
      return;
    }
    const composed = compose(localMatrix(node), parentWorld);
    const world = useWorld ? (matrixOf(node.matrixWorld) ?? composed) : composed;
    if (node.isMesh && isDict(node.geometry)) {
      const name = typeof node.name === 'string' && node.name !== '' ? node.name : `mesh ${out.length + 1}`;
      const inst = node.isInstancedMesh && isDict(node.instanceMatrix) ? node.instanceMatrix.array : undefined;
      if (isNumberArray(inst)) {
        const n =
          typeof node.count === 'number'
            ? Math.min(node.count, Math.floor(inst.length / 16))
            : Math.floor(inst.length / 16);
        for (let i = 0; i < n; i++) {
          const e = Array.prototype.slice.call(inst, i * 16, i * 16 + 16) as number[];
          add(`${name} #${i + 1}`, node.geometry, compose(fromColumnMajor4x4(e), world));
        }
      } else {
        add(name, node.geometry, world);
      }
    }
    if (Array.isArray(node.children)) {
      for (const child of node.children) if (isDict(child)) visit(child, composed, depth + 1);
    }
  };
  visit(object, identity(), 0);
  if (out.length === 0) {
    throw new StrataError(
      'EMPTY_MODEL',
      `the three.js object holds no ${hidden ? 'visible ' : ''}meshes with triangles${hidden ? ` (${hidden} hidden object${hidden === 1 ? ' is' : 's are'} skipped)` : ''}`,
    );
  }
  return out;
}

function matrixOf(m: unknown): Affine | undefined {
  if (!isDict(m)) return undefined;
  const e = m.elements;
  return isNumberArray(e) && e.length === 16 ? fromColumnMajor4x4(e) : undefined;
}

/** The node's local matrix: `matrix.elements`, else position/quaternion/scale, else identity. */
function localMatrix(node: Dict): Affine {
  const m = matrixOf(node.matrix);
  if (m !== undefined) return m;
  const p = isDict(node.position) ? node.position : {};
  const q = isDict(node.quaternion) ? node.quaternion : {};
  const s = isDict(node.scale) ? node.scale : {};
  const num = (o: Dict, k: string, d: number): number => (typeof o[k] === 'number' ? (o[k] as number) : d);
  const x = num(q, 'x', 0),
    y = num(q, 'y', 0),
    z = num(q, 'z', 0),
    w = num(q, 'w', 1);
  const sx = num(s, 'x', 1),
    sy = num(s, 'y', 1),
    sz = num(s, 'z', 1);
  // Rotation matrix of a unit quaternion, columns scaled.
  return Float64Array.of(
    (1 - 2 * (y * y + z * z)) * sx,
    2 * (x * y - w * z) * sy,
    2 * (x * z + w * y) * sz,
    num(p, 'x', 0),
    2 * (x * y + w * z) * sx,
    (1 - 2 * (x * x + z * z)) * sy,
    2 * (y * z - w * x) * sz,
    num(p, 'y', 0),
    2 * (x * z - w * y) * sx,
    2 * (y * z + w * x) * sy,
    (1 - 2 * (x * x + y * y)) * sz,
    num(p, 'z', 0),
  );
}

/** Divisor that maps a normalised integer attribute to [-1, 1] / [0, 1], or 0 when not normalised. */
function normaliser(arr: ArrayLike<number>): number {
  if (arr instanceof Int8Array) return 127;
  if (arr instanceof Uint8Array || arr instanceof Uint8ClampedArray) return 255;
  if (arr instanceof Int16Array) return 32767;
  if (arr instanceof Uint16Array) return 65535;
  if (arr instanceof Int32Array) return 2147483647;
  if (arr instanceof Uint32Array) return 4294967295;
  return 0;
}

/** Read a duck-typed BufferGeometry into a welded mesh, positions transformed by `m`. */
function geometryToMesh(geometry: Dict, m: Affine, name: string): { positions: Float32Array; indices: Uint32Array } {
  const label = printable(name);
  const attrs = geometry.attributes;
  const pos = isDict(attrs) ? attrs.position : undefined;
  if (!isDict(pos)) throw new StrataError('BAD_MESH', `${label}: the geometry has no position attribute`);
  const itemSize = typeof pos.itemSize === 'number' ? pos.itemSize : 3;
  if (!Number.isInteger(itemSize) || itemSize < 3) {
    throw new StrataError(
      'BAD_MESH',
      `${label}: position itemSize is ${printable(String(itemSize))}; 3D positions need at least 3`,
    );
  }
  let arr: unknown = pos.array;
  let stride = itemSize;
  let offset = 0;
  if (isDict(pos.data) && isNumberArray(pos.data.array)) {
    // InterleavedBufferAttribute: data.array, data.stride, offset.
    arr = pos.data.array;
    stride = typeof pos.data.stride === 'number' ? pos.data.stride : itemSize;
    offset = typeof pos.offset === 'number' ? pos.offset : 0;
  }
  if (!isNumberArray(arr)) throw new StrataError('BAD_MESH', `${label}: the position attribute has no array`);
  if (!Number.isInteger(stride) || stride < 3 || !Number.isInteger(offset) || offset < 0 || offset + 3 > stride) {
    throw new StrataError(
      'BAD_MESH',
      `${label}: bad interleaved layout (stride ${printable(String(stride))}, offset ${printable(String(offset))})`,
    );
  }
  const fit = arr.length >= offset + 3 ? Math.floor((arr.length - offset - 3) / stride) + 1 : 0;
  let count = fit;
  if (typeof pos.count === 'number') {
    if (!Number.isInteger(pos.count) || pos.count < 0 || pos.count > fit) {
      throw new StrataError(
        'BAD_MESH',
        `${label}: position count ${printable(String(pos.count))} does not fit its array of ${arr.length} numbers`,
      );
    }
    count = pos.count;
  }
  const norm = pos.normalized === true ? normaliser(arr) : 0;
  const src = new Float64Array(count * 3);
  for (let i = 0, o = offset; i < count; i++, o += stride) {
    let x = arr[o],
      y = arr[o + 1],
      z = arr[o + 2];
    if (norm !== 0) {
      x = Math.max(x / norm, -1);
      y = Math.max(y / norm, -1);
      z = Math.max(z / norm, -1);
    }
    src[i * 3] = x;
    src[i * 3 + 1] = y;
    src[i * 3 + 2] = z;
  }
  const positions = new Float32Array(count * 3);
  transformPoints(m, src, count, positions, 0);

  let indices: Uint32Array;
  const index = geometry.index;
  if (isDict(index) && isNumberArray(index.array)) {
    const ia = index.array;
    let n = ia.length;
    if (typeof index.count === 'number' && Number.isInteger(index.count) && index.count >= 0 && index.count <= n)
      n = index.count;
    if (n % 3 !== 0) throw new StrataError('BAD_MESH', `${label}: ${n} indices is not a multiple of 3`);
    indices = new Uint32Array(n);
    for (let i = 0; i < n; i++) {
      const v = ia[i];
      if (!Number.isInteger(v) || v < 0 || v >= count) {
        throw new StrataError(
          'BAD_MESH',
          `${label}: index ${i} is ${printable(String(v))}, outside the ${count} vertices`,
        );
      }
      indices[i] = v;
    }
  } else {
    if (count % 3 !== 0)
      throw new StrataError('BAD_MESH', `${label}: ${count} unindexed vertices is not a multiple of 3`);
    indices = new Uint32Array(count);
    for (let i = 0; i < count; i++) indices[i] = i;
  }
  if (determinant(m) < 0) {
    for (let t = 0; t < indices.length; t += 3) {
      const b = indices[t + 1];
      indices[t + 1] = indices[t + 2];
      indices[t + 2] = b;
    }
  }
  return weld(positions, indices, label);
}
