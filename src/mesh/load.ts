/**
 * Entry points that take "a model" in whatever form: file bytes (format detected), text, three.js
 * objects, raw arrays, meshes, or arrays of these.
 */
import { StrataError } from '../errors.js';
import { fromArrays } from './arrays.js';
import { isObjectInput, objectFromInput } from './object-input.js';
import { parseObj } from './obj.js';
import { parseStl } from './stl.js';
import type { ModelInput } from './place.js';
import { isThreeLike, fromThree, threeLooksYUp } from './three.js';
import { parse3mfProject } from './threemf-project.js';
import type { MeshObject, RawMeshArrays, SettingsSource } from './types.js';

export interface LoadOptions {
  /** Most bytes a 3MF's referenced parts may unpack to together (default 512 MiB). */
  maxInflatedBytes?: number;
  /** The input's up axis; with 'z' (default) a three.js scene that is Y-up gets a warning. */
  upAxis?: 'y' | 'z';
}

/** Models and the notes made while reading them. */
export interface LoadedModels {
  models: ModelInput[];
  warnings: string[];
  /** The print settings of the first project file (3MF) among the inputs that holds any. */
  projectSettings?: SettingsSource;
}

/** One model file read: its objects, a project's print settings, and the notes made while reading it. */
export interface LoadedFile {
  objects: MeshObject[];
  projectSettings?: SettingsSource;
  warnings: string[];
}

export type ModelFormat = 'stl' | 'obj' | '3mf';

/** Deepest nesting of arrays accepted by toMeshObjects. */
const MAX_INPUT_DEPTH = 16;

/**
 * Detect the format of file bytes: zip magic → 3mf; exact binary-STL size → stl; then the file
 * extension; then the text ("solid" → stl; v/f/o/g statements → obj).
 */
export function detectFormat(bytes: Uint8Array, fileName?: string): ModelFormat {
  if (bytes.length >= 4 && bytes[0] === 0x50 && bytes[1] === 0x4b && bytes[2] === 3 && bytes[3] === 4) return '3mf';
  if (bytes.length >= 84) {
    const n = (bytes[80] | (bytes[81] << 8) | (bytes[82] << 16) | (bytes[83] << 24)) >>> 0;
    if (84 + 50 * n === bytes.length) return 'stl';
  }
  const ext = fileName ? extension(fileName) : '';
  if (ext === 'stl' || ext === 'obj' || ext === '3mf') return ext;
  const head = new TextDecoder('utf-8').decode(bytes.subarray(0, 4096));
  if (/^\s*solid(\s|$)/i.test(head)) return 'stl';
  if (/^\s*(v|vn|vt|f|o|g|mtllib|usemtl)\s/m.test(head) && !/[\x00-\x08\x0e-\x1f]/.test(head)) return 'obj';
  throw new StrataError(
    'UNSUPPORTED_FORMAT',
    `cannot tell the format of ${fileName ? `"${fileName}"` : 'the file'}: expected STL, OBJ or 3MF`,
  );
}

/** Parse model file bytes; `fileName` helps detection and names the objects. */
export function loadModelBytes(bytes: Uint8Array, fileName?: string, opts: LoadOptions = {}): MeshObject[] {
  return loadModelFile(bytes, fileName, opts).objects;
}

/**
 * Parse model file bytes, keeping what a project file says besides its objects (their volumes and
 * settings are on the objects): the print's settings and the reader's warnings.
 */
export function loadModelFile(bytes: Uint8Array, fileName?: string, opts: LoadOptions = {}): LoadedFile {
  const name = fileName ? baseName(fileName) : 'model';
  switch (detectFormat(bytes, fileName)) {
    case '3mf':
      return parse3mfProject(bytes, name, { maxInflatedBytes: opts.maxInflatedBytes });
    case 'obj':
      return { objects: parseObj(bytes, name), warnings: [] };
    case 'stl':
      return { objects: parseStl(bytes, name), warnings: [] };
  }
}

/**
 * Whatever a library caller passes: Uint8Array / ArrayBuffer (file bytes), a string (ASCII STL or
 * OBJ text), a three.js Object3D or BufferGeometry, `{ positions, indices? }`, a Mesh, a MeshObject,
 * or an array of these.
 */
export function toMeshObjects(input: unknown, opts: LoadOptions = {}): MeshObject[] {
  return convert(input, 0, opts, { warnings: [] });
}

/** What converting inputs collects besides objects. */
interface Notes {
  warnings: string[];
  projectSettings?: SettingsSource;
}

/**
 * Whatever a library caller passes, as models to place on the bed: a list gives one model per
 * element (a file's bytes, a three.js scene, a mesh, a nested list of objects kept together, or a
 * named model `{ name, objects }`); anything else is one model. A model's objects keep their places
 * relative to each other; models are arranged on the bed.
 */
export function toModels(input: unknown, opts: LoadOptions = {}): LoadedModels {
  const notes: Notes = { warnings: [] };
  const list = Array.isArray(input) && !input.every((v) => typeof v === 'number') ? input : [input];
  const models = list.map((item, i): ModelInput => {
    if (isNamedModel(item)) {
      const named = item as ModelInput;
      if (named.warnings) notes.warnings.push(...named.warnings);
      if (notes.projectSettings === undefined && named.projectSettings !== undefined)
        notes.projectSettings = named.projectSettings;
      return { name: item.name, objects: convert(item.objects, 1, opts, notes) };
    }
    const objects = convert(item, 1, opts, notes);
    const name = list.length === 1 ? 'the model' : objects.length === 1 ? objects[0].name : `model ${i + 1}`;
    return { name, objects };
  });
  const out: LoadedModels = { models, warnings: notes.warnings };
  if (notes.projectSettings !== undefined) out.projectSettings = notes.projectSettings;
  return out;
}

function isNamedModel(v: unknown): v is { name: string; objects: unknown[] } {
  return (
    typeof v === 'object' &&
    v !== null &&
    typeof (v as { name?: unknown }).name === 'string' &&
    Array.isArray((v as { objects?: unknown }).objects)
  );
}

/** File bytes: their objects, with the file's warnings and (the first) project settings noted. */
function fromBytes(bytes: Uint8Array, opts: LoadOptions, notes: Notes): MeshObject[] {
  const file = loadModelFile(bytes, undefined, opts);
  notes.warnings.push(...file.warnings);
  if (notes.projectSettings === undefined && file.projectSettings !== undefined)
    notes.projectSettings = file.projectSettings;
  return file.objects;
}

function convert(input: unknown, depth: number, opts: LoadOptions, notes: Notes): MeshObject[] {
  if (depth > MAX_INPUT_DEPTH) throw new StrataError('UNSUPPORTED_FORMAT', 'the input is nested too deeply');
  if (input instanceof Uint8Array) return fromBytes(input, opts, notes);
  if (input instanceof ArrayBuffer) return fromBytes(new Uint8Array(input), opts, notes);
  if (input instanceof DataView)
    return fromBytes(new Uint8Array(input.buffer, input.byteOffset, input.byteLength), opts, notes);
  if (typeof input === 'string') {
    if (/^\s*solid(\s|$)/i.test(input.slice(0, 256))) return parseStl(new TextEncoder().encode(input));
    if (/^\s*(v|vn|vt|f|o|g|mtllib|usemtl|#)/m.test(input.slice(0, 4096))) return parseObj(input);
    throw new StrataError('UNSUPPORTED_FORMAT', 'the string is neither ASCII STL nor OBJ text');
  }
  if (Array.isArray(input)) {
    if (input.length > 0 && input.every((v) => typeof v === 'number')) {
      throw new StrataError(
        'UNSUPPORTED_FORMAT',
        'got an array of numbers: pass { positions, indices } for raw arrays',
      );
    }
    return input.flatMap((item) => convert(item, depth + 1, opts, notes));
  }
  if (typeof input === 'object' && input !== null) {
    const o = input as Record<string, unknown>;
    if (isThreeLike(o)) {
      const objects = fromThree(o);
      if (opts.upAxis !== 'y' && threeLooksYUp(o)) {
        notes.warnings.push(
          "the three.js scene's up axis is +Y (three.js's default), but it is sliced with Z up, so a Y-up scene lies on its side: " +
            "pass upAxis: 'y' to stand it up, or set the scene's up to (0, 0, 1) if it is modelled Z-up",
        );
      }
      return objects;
    }
    if (isObjectInput(o))
      return [objectFromInput(o as Record<string, unknown>, (mesh) => convert(mesh, depth + 1, opts, notes), 0)];
    if ('positions' in o)
      return [fromArrays(o as unknown as RawMeshArrays, typeof o.name === 'string' ? o.name : 'mesh')];
    if (typeof o.mesh === 'object' && o.mesh !== null && 'positions' in o.mesh) {
      const name = typeof o.name === 'string' && o.name !== '' ? o.name : 'mesh';
      return [fromArrays(o.mesh as RawMeshArrays, name)];
    }
  }
  const what =
    input === null
      ? 'null'
      : Array.isArray(input)
        ? 'array'
        : typeof input === 'object'
          ? (input.constructor?.name ?? 'object')
          : typeof input;
  throw new StrataError(
    'UNSUPPORTED_FORMAT',
    `cannot make a mesh from ${what}: pass file bytes, STL/OBJ text, a three.js object, { positions, indices } or a Mesh`,
  );
}

function extension(fileName: string): string {
  const base = fileName.split(/[\\/]/).pop() ?? '';
  const dot = base.lastIndexOf('.');
  return dot > 0 ? base.slice(dot + 1).toLowerCase() : '';
}

function baseName(fileName: string): string {
  const base = fileName.split(/[\\/]/).pop() ?? fileName;
  const dot = base.lastIndexOf('.');
  return dot > 0 ? base.slice(0, dot) : base || 'model';
}
