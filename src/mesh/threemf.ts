/**
 * 3MF reader: every <build><item> becomes one MeshObject in millimetres, with the item transform
 * and any (nested) component transforms applied. Objects in other model parts (production
 * extension p:path) are followed; only the parts the build reaches are unpacked, within
 * `maxInflatedBytes` (threemf-package.ts, zip.ts). Colours, materials and other extensions are ignored.
 * A slicer's project data (volumes, per-object settings) is read by threemf-project.ts over the same build.
 */
import { StrataError } from '../errors.js';
import { compose, determinant, identity, transformPoints, type Affine } from './transform.js';
import { parseModelPart, type ModelObject, type ModelPart, type ObjectRef } from './threemf-model.js';
import { MAX_MODEL_TRIANGLES } from './limits.js';
import { printable } from './printable.js';
import { DEFAULT_INFLATE_BYTES, openPackage, type ThreeMfPackage } from './threemf-package.js';
import type { MeshObject } from './types.js';
import { weld } from './weld.js';

/** Most triangles a 3MF may expand to (components can instance an object many times). */
export const MAX_3MF_TRIANGLES = MAX_MODEL_TRIANGLES;
/** Deepest component nesting followed. */
const MAX_COMPONENT_DEPTH = 32;

interface Size {
  vertices: number;
  triangles: number;
}

export interface ThreeMfOptions {
  /** Most bytes the referenced parts may unpack to together (default 512 MiB). */
  maxInflatedBytes?: number;
}

/** A 3MF's build: its root part, its items and how to look objects up, sizes checked against the limits. */
export interface Build {
  pkg: ThreeMfPackage;
  root: ModelPart;
  /** Normalised name of the root part. */
  rootKey: string;
  items: BuildItem[];
  lookup(key: string, id: number): ModelObject;
}

export interface BuildItem {
  ref: ObjectRef;
  /** Normalised name of the part that defines the item's object. */
  key: string;
  /** Unique display name: the object's name, else the file's (numbered when there are several items). */
  label: string;
  vertices: number;
  triangles: number;
}

/** The triangles one mesh-bearing object contributed to an expanded item. */
export interface Segment {
  /** The objects from the item's object down to the one holding these triangles (components in between). */
  path: ModelObject[];
  /** First triangle in the item's arrays, and how many. */
  start: number;
  count: number;
}

/** One build item with every transform applied: triangle soup over shared vertices, not yet welded. */
export interface ExpandedItem {
  positions: Float32Array;
  /** Three vertex ids per triangle, winding fixed for mirroring transforms. */
  indices: Uint32Array;
  /** In triangle order, covering every triangle once. */
  segments: Segment[];
}

export function parse3mf(bytes: Uint8Array, name = 'model', opts: ThreeMfOptions = {}): MeshObject[] {
  const build = openBuild(bytes, name, opts);
  const out: MeshObject[] = [];
  for (const item of build.items) {
    if (item.triangles === 0) continue;
    const e = expandItem(build, item);
    out.push({ name: item.label, mesh: weld(e.positions, e.indices, '3MF') });
  }
  return out;
}

/** Open the package, parse the root part and size every build item (nothing is expanded yet). */
export function openBuild(bytes: Uint8Array, name: string, opts: ThreeMfOptions = {}): Build {
  const pkg = openPackage(bytes, {
    maxBytes: opts.maxInflatedBytes ?? DEFAULT_INFLATE_BYTES,
    setting: 'inflateBudget',
  });
  const parsed = new Map<string, ModelPart>();
  const part = (key: string): ModelPart => {
    let p = parsed.get(key);
    if (p === undefined) {
      const data = pkg.read(key);
      if (data === undefined)
        throw new StrataError(
          'BAD_FILE',
          `3MF: a component refers to part /${printable(key)}, which is not in the archive`,
        );
      p = parseModelPart(data, key);
      parsed.set(key, p);
    }
    return p;
  };
  const lookup = (key: string, id: number): ModelObject => {
    const o = part(key).objects.get(id);
    if (o === undefined)
      throw new StrataError('BAD_FILE', `3MF: object ${id} is referenced but not defined in /${printable(key)}`);
    return o;
  };

  // Sizes first (memoised, with cycle detection), so a hostile file cannot make us allocate unbounded memory.
  const sizes = new Map<string, Size>();
  const inProgress = new Set<string>();
  const sizeOf = (key: string, id: number, depth: number): Size => {
    const k = `${key}#${id}`;
    const known = sizes.get(k);
    if (known !== undefined) return known;
    if (inProgress.has(k))
      throw new StrataError('BAD_FILE', `3MF: object ${id} contains itself through its components`);
    if (depth > MAX_COMPONENT_DEPTH) {
      throw new StrataError('LIMIT_EXCEEDED', `3MF: components nested deeper than ${MAX_COMPONENT_DEPTH} levels`);
    }
    inProgress.add(k);
    const o = lookup(key, id);
    let vertices = o.vertices ? o.vertices.length / 3 : 0;
    let triangles = o.triangles ? o.triangles.length / 3 : 0;
    for (const c of o.components) {
      const s = sizeOf(c.path ?? key, c.objectId, depth + 1);
      vertices += s.vertices;
      triangles += s.triangles;
      if (triangles > MAX_3MF_TRIANGLES || vertices > 3 * MAX_3MF_TRIANGLES) tooMany();
    }
    inProgress.delete(k);
    const size = { vertices, triangles };
    sizes.set(k, size);
    return size;
  };

  const root = part(pkg.root);
  if (root.items.length === 0) throw new StrataError('EMPTY_MODEL', '3MF: the build has no items');
  let total = 0;
  let totalVertices = 0;
  const used = new Set<string>();
  const items = root.items.map((ref, i): BuildItem => {
    const key = ref.path ?? pkg.root;
    const s = sizeOf(key, ref.objectId, 0);
    total += s.triangles;
    totalVertices += s.vertices;
    if (total > MAX_3MF_TRIANGLES || totalVertices > 3 * MAX_3MF_TRIANGLES) tooMany();
    const objName = lookup(key, ref.objectId).name;
    let label = objName !== '' ? objName : root.items.length === 1 ? name : `${name} ${i + 1}`;
    if (used.has(label)) label = `${label} (${i + 1})`;
    used.add(label);
    return { ref, key, label, vertices: s.vertices, triangles: s.triangles };
  });
  if (total === 0) throw new StrataError('EMPTY_MODEL', '3MF: the build items hold no triangles');
  return { pkg, root, rootKey: pkg.root, items, lookup };
}

/** Every triangle of one build item in build coordinates (mm), with where each object's triangles went. */
export function expandItem(build: Build, item: BuildItem): ExpandedItem {
  const positions = new Float32Array(item.vertices * 3);
  const indices = new Uint32Array(item.triangles * 3);
  const segments: Segment[] = [];
  let vOff = 0;
  let tOff = 0;
  const emit = (key: string, ref: ObjectRef, parent: Affine, path: ModelObject[]): void => {
    const o = build.lookup(key, ref.objectId);
    const m = ref.transform ? compose(ref.transform, parent) : parent;
    const here = [...path, o];
    if (o.vertices !== null && o.triangles !== null && o.triangles.length > 0) {
      const nv = o.vertices.length / 3;
      transformPoints(m, o.vertices, nv, positions, vOff * 3);
      const tr = o.triangles;
      const flip = determinant(m) < 0;
      for (let t = 0; t < tr.length; t += 3) {
        indices[tOff + t] = tr[t] + vOff;
        indices[tOff + t + 1] = tr[flip ? t + 2 : t + 1] + vOff;
        indices[tOff + t + 2] = tr[flip ? t + 1 : t + 2] + vOff;
      }
      segments.push({ path: here, start: tOff / 3, count: tr.length / 3 });
      vOff += nv;
      tOff += tr.length;
    }
    for (const c of o.components) emit(c.path ?? key, c, m, here);
  };
  emit(item.key, item.ref, identity(), []);
  return { positions, indices, segments };
}

function tooMany(): never {
  throw new StrataError('LIMIT_EXCEEDED', `3MF: the build expands to more than ${MAX_3MF_TRIANGLES} triangles`);
}
