/**
 * One 3MF model part (XML): its unit, its objects (meshes and components) and its build items, and the
 * metadata a slicer may keep there (the model's `<metadata>`, an object's or item's `<metadatagroup>`,
 * Cura's older `<settings>`). Coordinates and transform translations are converted to millimetres here.
 */
import { StrataError } from '../errors.js';
import { GrowableF64, GrowableU32 } from './growable.js';
import { from3mf, type Affine } from './transform.js';
import { printable } from './printable.js';
import { partKey } from './threemf-package.js';
import { XML_END, XML_EOF, XmlScanner } from './xml-scanner.js';

const CORE_NS = 'http://schemas.microsoft.com/3dmanufacturing/core/2015/02';

/** Millimetres per model unit (3MF core spec, `unit` attribute of <model>). */
const UNIT_MM: Readonly<Record<string, number>> = Object.freeze({
  micron: 0.001,
  millimeter: 1,
  centimeter: 10,
  inch: 25.4,
  foot: 304.8,
  meter: 1000,
});

/** A reference to an object, from a <component> or a build <item>. */
export interface ObjectRef {
  objectId: number;
  /** Normalised part name when the reference points into another part (production extension p:path). */
  path: string | null;
  /** Object space → parent (or build) space, translation in mm. */
  transform: Affine | null;
  /** A build item's `<metadatagroup>` entries by name, when it has any. */
  metadata?: Map<string, string>;
}

export interface ModelObject {
  id: number;
  name: string;
  /** xyz per vertex in mm, or null when the object has no <mesh>. */
  vertices: Float64Array | null;
  triangles: Uint32Array | null;
  components: ObjectRef[];
  /** `<metadatagroup>` (and Cura's older `<settings>`) entries by name, or null when there are none. */
  metadata: Map<string, string> | null;
}

export interface ModelPart {
  unitScale: number;
  objects: Map<number, ModelObject>;
  items: ObjectRef[];
  /** The model's own `<metadata name="…">` entries (Application, Title, a slicer's version). */
  metadata: Map<string, string>;
  /** Namespace prefixes declared on `<model>`, prefix → URI. */
  namespaces: Map<string, string>;
}

// Element contexts: what the parent of the element being read is.
const C_OTHER = 0;
const C_DOC = 1;
const C_MODEL = 2;
const C_RESOURCES = 3;
const C_OBJECT = 4;
const C_MESH = 5;
const C_VERTICES = 6;
const C_TRIANGLES = 7;
const C_COMPONENTS = 8;
const C_BUILD = 9;
const C_ITEM = 10;
/** A `<metadatagroup>` or `<settings>` of an object or item: its children are named values. */
const C_GROUP = 11;
/** A `<metadata>` or `<setting>` whose text is its value. */
const C_VALUE = 12;

const MAX_DEPTH = 64;
export function parseModelPart(bytes: Uint8Array, partName: string): ModelPart {
  const x = new XmlScanner(bytes, `3MF model part ${partName}`, MAX_DEPTH);
  const ctx = new Uint8Array(MAX_DEPTH + 1);
  ctx[0] = C_DOC;
  const corePrefixes: string[] = [];
  let unitScale = 1;
  let sawModel = false;
  const objects = new Map<number, ModelObject>();
  const items: ObjectRef[] = [];
  const metadata = new Map<string, string>();
  const namespaces = new Map<string, string>();
  // the named value being read: where its text starts and which map it goes to
  const value: { name: string; start: number; target: Map<string, string> | null } = {
    name: '',
    start: 0,
    target: null,
  };
  let groupTarget: Map<string, string> | null = null;

  let obj: ModelObject | null = null;
  let verts: GrowableF64 | null = null;
  let tris: GrowableU32 | null = null;
  let maxIndex = -1;

  const isCore = (): boolean => x.localStart === x.nameStart || corePrefixes.includes(x.prefix());

  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev === XML_END) {
      const closed = ctx[x.depth + 1];
      if (closed === C_MESH && obj !== null && verts !== null && tris !== null) {
        finishMesh(x, obj, verts, tris, maxIndex);
        verts = null;
        tris = null;
      } else if (closed === C_OBJECT) {
        obj = null;
      } else if (closed === C_VALUE && value.target !== null) {
        value.target.set(value.name, x.textContent(value.start));
        value.target = null;
      }
      continue;
    }
    const parentDepth = x.selfClosing ? x.depth : x.depth - 1;
    const parent = ctx[parentDepth];
    let here = C_OTHER;
    switch (parent) {
      case C_VERTICES:
        if (x.is('vertex') && isCore() && verts !== null) {
          let vx = NaN,
            vy = NaN,
            vz = NaN;
          while (x.nextAttr()) {
            if (x.attrNameEnd - x.attrNameStart !== 1) continue;
            const c = bytes[x.attrNameStart];
            if (c === 120) vx = x.number();
            else if (c === 121) vy = x.number();
            else if (c === 122) vz = x.number();
          }
          if (!Number.isFinite(vx) || !Number.isFinite(vy) || !Number.isFinite(vz)) {
            x.fail('a <vertex> needs finite numbers in x, y and z', x.nameStart);
          }
          verts.push3(vx * unitScale, vy * unitScale, vz * unitScale);
        }
        break;
      case C_TRIANGLES:
        if (x.is('triangle') && isCore() && tris !== null) {
          let v1 = -1,
            v2 = -1,
            v3 = -1;
          while (x.nextAttr()) {
            if (x.attrNameEnd - x.attrNameStart !== 2 || bytes[x.attrNameStart] !== 118) continue;
            const c = bytes[x.attrNameStart + 1];
            if (c === 49) v1 = x.uint();
            else if (c === 50) v2 = x.uint();
            else if (c === 51) v3 = x.uint();
          }
          if (v1 < 0 || v2 < 0 || v3 < 0) x.fail('a <triangle> needs vertex indices v1, v2 and v3', x.nameStart);
          if (v1 > maxIndex) maxIndex = v1;
          if (v2 > maxIndex) maxIndex = v2;
          if (v3 > maxIndex) maxIndex = v3;
          tris.push3(v1, v2, v3);
        }
        break;
      case C_DOC:
        if (!x.is('model')) x.fail(`the root element is <${x.text(x.nameStart, x.nameEnd)}>, not <model>`, x.nameStart);
        sawModel = true;
        here = C_MODEL;
        while (x.nextAttr()) {
          if (x.attrIs('unit')) {
            const u = x.value();
            const s = UNIT_MM[u];
            if (s === undefined)
              x.fail(
                `unknown unit "${printable(u)}" (expected micron, millimeter, centimeter, inch, foot or meter)`,
                x.nameStart,
              );
            unitScale = s;
          } else if (x.attrNameEnd - x.attrNameStart > 6 && x.attrName().startsWith('xmlns:')) {
            const uri = x.value();
            namespaces.set(x.attrName().slice(6), uri);
            if (uri === CORE_NS) corePrefixes.push(x.attrName().slice(6));
          }
        }
        break;
      case C_MODEL:
        if (isCore()) {
          if (x.is('resources')) here = C_RESOURCES;
          else if (x.is('build')) here = C_BUILD;
          else if (x.is('metadata')) here = startValue(x, 'name', metadata);
        }
        break;
      case C_RESOURCES:
        if (x.is('object') && isCore()) {
          here = C_OBJECT;
          let id = -1;
          let name = '';
          while (x.nextAttr()) {
            if (x.attrIs('id')) id = x.uint();
            else if (x.attrIs('name')) name = printable(x.value(), 200);
          }
          if (id < 0) x.fail('an <object> needs a numeric id', x.nameStart);
          if (objects.has(id)) x.fail(`two objects have the id ${id}`, x.nameStart);
          obj = { id, name, vertices: null, triangles: null, components: [], metadata: null };
          objects.set(id, obj);
        }
        break;
      case C_OBJECT:
        if (isCore()) {
          if (x.is('mesh')) {
            here = C_MESH;
            verts = new GrowableF64(3 * 1024);
            tris = new GrowableU32(3 * 2048);
            maxIndex = -1;
          } else if (x.is('components')) {
            here = C_COMPONENTS;
          } else if ((x.is('metadatagroup') || x.is('settings')) && obj !== null) {
            here = C_GROUP;
            groupTarget = obj.metadata ??= new Map();
          }
        }
        break;
      case C_ITEM:
        if (isCore() && x.is('metadatagroup') && items.length > 0) {
          here = C_GROUP;
          groupTarget = items[items.length - 1].metadata ??= new Map();
        }
        break;
      case C_GROUP:
        if (isCore() && groupTarget !== null) {
          if (x.is('metadata')) here = startValue(x, 'name', groupTarget);
          else if (x.is('setting')) here = startValue(x, 'key', groupTarget);
        }
        break;
      case C_MESH:
        if (isCore()) {
          if (x.is('vertices')) here = C_VERTICES;
          else if (x.is('triangles')) here = C_TRIANGLES;
        }
        break;
      case C_COMPONENTS:
        if (x.is('component') && isCore() && obj !== null) obj.components.push(readRef(x, unitScale, 'component'));
        break;
      case C_BUILD:
        if (x.is('item') && isCore()) {
          items.push(readRef(x, unitScale, 'build item'));
          here = C_ITEM;
        }
        break;
    }
    if (!x.selfClosing) ctx[x.depth] = here;
  }
  if (!sawModel) throw new StrataError('BAD_FILE', `3MF model part ${partName} has no <model> element`);
  return { unitScale, objects, items, metadata, namespaces };

  /** At a named value's start tag: remember where its text goes (C_VALUE), or store an empty one. */
  function startValue(x: XmlScanner, nameAttr: string, target: Map<string, string>): number {
    let key = '';
    while (x.nextAttr()) if (x.attrIs(nameAttr)) key = x.value();
    if (key === '') return C_OTHER;
    if (x.selfClosing) {
      target.set(key, '');
      return C_OTHER;
    }
    value.name = key;
    value.start = x.contentStart();
    value.target = target;
    return C_VALUE;
  }
}

function finishMesh(x: XmlScanner, obj: ModelObject, verts: GrowableF64, tris: GrowableU32, maxIndex: number): void {
  const nv = verts.length / 3;
  if (maxIndex >= nv) {
    x.fail(`object ${obj.id}: a triangle uses vertex ${maxIndex} but the mesh has ${nv} vertices`, x.nameStart);
  }
  obj.vertices = verts.toArray();
  obj.triangles = tris.toArray();
}

function readRef(x: XmlScanner, unitScale: number, what: string): ObjectRef {
  let objectId = -1;
  let path: string | null = null;
  let transform: Affine | null = null;
  while (x.nextAttr()) {
    if (x.attrIs('objectid')) objectId = x.uint();
    else if (x.attrIs('transform')) transform = parseTransform(x, x.value(), unitScale);
    else if (x.attrIsPrefixed('path')) path = partKey(x.value());
  }
  if (objectId < 0) x.fail(`a ${what} needs a numeric objectid`, x.nameStart);
  return { objectId, path, transform };
}

function parseTransform(x: XmlScanner, text: string, unitScale: number): Affine {
  const parts = text.trim().split(/\s+/);
  const nums = parts.map(Number);
  if (parts.length !== 12 || nums.some((n) => !Number.isFinite(n))) {
    x.fail(`transform "${printable(text)}" is not 12 numbers`, x.nameStart);
  }
  const m = from3mf(nums);
  m[3] *= unitScale;
  m[7] *= unitScale;
  m[11] *= unitScale;
  return m;
}
