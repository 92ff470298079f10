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

/** What has been read of one model part, and where the reader is in it. */
class PartReader {
  /** The context of each open element (what it is, for its children), by depth. */
  readonly ctx = new Uint8Array(MAX_DEPTH + 1);
  /** Prefixes bound to the 3MF core namespace. */
  readonly corePrefixes: string[] = [];
  unitScale = 1;
  sawModel = false;
  readonly objects = new Map<number, ModelObject>();
  readonly items: ObjectRef[] = [];
  readonly metadata = new Map<string, string>();
  readonly namespaces = new Map<string, string>();
  /** The named value being read: where its text starts and which map it goes to. */
  readonly value: { name: string; start: number; target: Map<string, string> | null } = {
    name: '',
    start: 0,
    target: null,
  };
  /** The map the open `<metadatagroup>` or `<settings>` fills. */
  groupTarget: Map<string, string> | null = null;
  /** The open object, and its mesh's vertices and triangles while its `<mesh>` is open. */
  obj: ModelObject | null = null;
  verts: GrowableF64 | null = null;
  tris: GrowableU32 | null = null;
  maxIndex = -1;

  constructor(
    readonly x: XmlScanner,
    readonly bytes: Uint8Array,
  ) {
    this.ctx[0] = C_DOC;
  }

  /** Whether the current element is in the core namespace. */
  isCore(): boolean {
    const x = this.x;
    return x.localStart === x.nameStart || this.corePrefixes.includes(x.prefix());
  }

  /** An end tag: finish the mesh, object or named value it closes. */
  endElement(): void {
    const x = this.x;
    const closed = this.ctx[x.depth + 1];
    if (closed === C_MESH && this.obj !== null && this.verts !== null && this.tris !== null) {
      finishMesh(x, this.obj, this.verts, this.tris, this.maxIndex);
      this.verts = null;
      this.tris = null;
    } else if (closed === C_OBJECT) {
      this.obj = null;
    } else if (closed === C_VALUE && this.value.target !== null) {
      this.value.target.set(this.value.name, x.textContent(this.value.start));
      this.value.target = null;
    }
  }

  /** A start tag: read it as a child of its parent's context, and record its own context. */
  startElement(): void {
    const x = this.x;
    const parentDepth = x.selfClosing ? x.depth : x.depth - 1;
    let here = C_OTHER;
    switch (this.ctx[parentDepth]) {
      case C_VERTICES:
        this.readVertex();
        break;
      case C_TRIANGLES:
        this.readTriangle();
        break;
      case C_DOC:
        here = this.readModel();
        break;
      case C_MODEL:
        here = this.modelChild();
        break;
      case C_RESOURCES:
        here = this.readObject();
        break;
      case C_OBJECT:
        here = this.objectChild();
        break;
      case C_ITEM:
        here = this.itemChild();
        break;
      case C_GROUP:
        here = this.groupChild();
        break;
      case C_MESH:
        here = this.meshChild();
        break;
      case C_COMPONENTS:
        this.readComponent();
        break;
      case C_BUILD:
        here = this.readItem();
        break;
    }
    if (!x.selfClosing) this.ctx[x.depth] = here;
  }

  /** The root `<model>`: its unit and namespace prefixes. */
  readModel(): number {
    const x = this.x;
    if (!x.is('model')) x.fail(`the root element is <${x.text(x.nameStart, x.nameEnd)}>, not <model>`, x.nameStart);
    this.sawModel = true;
    while (x.nextAttr()) {
      if (x.attrIs('unit')) {
        const u = x.value();
        const s = UNIT_MM[u];
        if (s === undefined)
          x.fail(
            `unknown unit "${printable(u)}" (expected micron, millimeter, centimeter, inch, foot or meter)`,
            x.nameStart,
          );
        this.unitScale = s;
      } else if (x.attrNameEnd - x.attrNameStart > 6 && x.attrName().startsWith('xmlns:')) {
        const uri = x.value();
        this.namespaces.set(x.attrName().slice(6), uri);
        if (uri === CORE_NS) this.corePrefixes.push(x.attrName().slice(6));
      }
    }
    return C_MODEL;
  }

  /** A child of `<model>`: `<resources>`, `<build>` or the model's `<metadata>`. */
  modelChild(): number {
    const x = this.x;
    if (this.isCore()) {
      if (x.is('resources')) return C_RESOURCES;
      if (x.is('build')) return C_BUILD;
      if (x.is('metadata')) return this.startValue('name', this.metadata);
    }
    return C_OTHER;
  }

  /** An `<object>` of `<resources>`: its id and name. */
  readObject(): number {
    const x = this.x;
    if (!(x.is('object') && this.isCore())) return C_OTHER;
    let id = -1;
    let name = '';
    while (x.nextAttr()) {
      if (x.attrIs('id')) id = x.uint();
      else if (x.attrIs('name')) name = printable(x.value(), 200);
    }
    if (id < 0) x.fail('an <object> needs a numeric id', x.nameStart);
    if (this.objects.has(id)) x.fail(`two objects have the id ${id}`, x.nameStart);
    this.obj = { id, name, vertices: null, triangles: null, components: [], metadata: null };
    this.objects.set(id, this.obj);
    return C_OBJECT;
  }

  /** A child of an object: its `<mesh>`, `<components>`, or `<metadatagroup>` (or Cura's `<settings>`). */
  objectChild(): number {
    const x = this.x;
    if (!this.isCore()) return C_OTHER;
    if (x.is('mesh')) {
      this.verts = new GrowableF64(3 * 1024);
      this.tris = new GrowableU32(3 * 2048);
      this.maxIndex = -1;
      return C_MESH;
    }
    if (x.is('components')) return C_COMPONENTS;
    if ((x.is('metadatagroup') || x.is('settings')) && this.obj !== null) {
      this.groupTarget = this.obj.metadata ??= new Map();
      return C_GROUP;
    }
    return C_OTHER;
  }

  /** A child of a mesh: `<vertices>` or `<triangles>`. */
  meshChild(): number {
    const x = this.x;
    if (this.isCore()) {
      if (x.is('vertices')) return C_VERTICES;
      if (x.is('triangles')) return C_TRIANGLES;
    }
    return C_OTHER;
  }

  /** A `<vertex>`: x, y and z in mm. */
  readVertex(): void {
    const x = this.x;
    const verts = this.verts;
    if (!(x.is('vertex') && this.isCore() && verts !== null)) return;
    const bytes = this.bytes;
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
    const unitScale = this.unitScale;
    verts.push3(vx * unitScale, vy * unitScale, vz * unitScale);
  }

  /** A `<triangle>`: its vertex indices v1, v2, v3 (checked against the vertices when the mesh ends). */
  readTriangle(): void {
    const x = this.x;
    const tris = this.tris;
    if (!(x.is('triangle') && this.isCore() && tris !== null)) return;
    const bytes = this.bytes;
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
    if (v1 > this.maxIndex) this.maxIndex = v1;
    if (v2 > this.maxIndex) this.maxIndex = v2;
    if (v3 > this.maxIndex) this.maxIndex = v3;
    tris.push3(v1, v2, v3);
  }

  /** A `<component>` of the open object. */
  readComponent(): void {
    const x = this.x;
    if (x.is('component') && this.isCore() && this.obj !== null)
      this.obj.components.push(readRef(x, this.unitScale, 'component'));
  }

  /** A build `<item>`. */
  readItem(): number {
    const x = this.x;
    if (!(x.is('item') && this.isCore())) return C_OTHER;
    this.items.push(readRef(x, this.unitScale, 'build item'));
    return C_ITEM;
  }

  /** A child of a build item: its `<metadatagroup>`. */
  itemChild(): number {
    const x = this.x;
    if (!(this.isCore() && x.is('metadatagroup') && this.items.length > 0)) return C_OTHER;
    this.groupTarget = this.items[this.items.length - 1].metadata ??= new Map();
    return C_GROUP;
  }

  /** A child of a metadata group: a `<metadata name>` or a `<setting key>`. */
  groupChild(): number {
    const x = this.x;
    if (this.isCore() && this.groupTarget !== null) {
      if (x.is('metadata')) return this.startValue('name', this.groupTarget);
      if (x.is('setting')) return this.startValue('key', this.groupTarget);
    }
    return C_OTHER;
  }

  /** At a named value's start tag: remember where its text goes (C_VALUE), or store an empty one. */
  startValue(nameAttr: string, target: Map<string, string>): number {
    const x = this.x;
    let key = '';
    while (x.nextAttr()) if (x.attrIs(nameAttr)) key = x.value();
    if (key === '') return C_OTHER;
    if (x.selfClosing) {
      target.set(key, '');
      return C_OTHER;
    }
    this.value.name = key;
    this.value.start = x.contentStart();
    this.value.target = target;
    return C_VALUE;
  }
}

/** Read one model part: its unit, objects, build items, metadata and namespaces. */
export function parseModelPart(bytes: Uint8Array, partName: string): ModelPart {
  const x = new XmlScanner(bytes, `3MF model part ${partName}`, MAX_DEPTH);
  const r = new PartReader(x, bytes);
  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev === XML_END) r.endElement();
    else r.startElement();
  }
  if (!r.sawModel) throw new StrataError('BAD_FILE', `3MF model part ${partName} has no <model> element`);
  return { unitScale: r.unitScale, objects: r.objects, items: r.items, metadata: r.metadata, namespaces: r.namespaces };
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
