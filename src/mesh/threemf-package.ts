/**
 * The 3MF container: a zip (OPC package) whose `_rels/.rels` points at the root model part. Parts are
 * inflated only when read, so only `_rels/.rels`, the model parts the build refers to and the slicer
 * configs a project reader asks for are ever unpacked (thumbnails, textures and unreferenced models stay
 * packed), within the unpack budget of zip.ts.
 */
import { StrataError } from '../errors.js';
import { printable } from './printable.js';
import { XML_EOF, XML_START, XmlScanner } from './xml-scanner.js';
import { ZipArchive, type ZipBudget } from './zip.js';

/** Default unpack budget of a 3MF (the inflateBudget setting's default), bytes. */
export const DEFAULT_INFLATE_BYTES = 512 * 1024 * 1024;

const MODEL_REL = 'http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel';

export interface ThreeMfPackage {
  /** Normalised name of the root model part. */
  root: string;
  /** A model part's bytes by normalised name (inflated on first use), or undefined when absent. */
  read(key: string): Uint8Array | undefined;
  /** Normalised names of every part in the archive. */
  keys(): string[];
  /**
   * Any other part's bytes (a slicer's config under Metadata/), read through the same unpack budget;
   * undefined when absent. A part that declares more than `maxBytes` is refused (LIMIT_EXCEEDED).
   */
  readFile(key: string, maxBytes: number): Uint8Array | undefined;
}

/** Normalise an OPC part name for lookup: drop the leading "/", undo %-escapes, lower-case. */
export function partKey(name: string): string {
  let n = name.replace(/\\/g, '/').replace(/^\/+/, '');
  try {
    n = decodeURIComponent(n);
  } catch {
    // keep it as written
  }
  return n.toLowerCase();
}

export function openPackage(
  bytes: Uint8Array,
  budget: ZipBudget = { maxBytes: DEFAULT_INFLATE_BYTES, setting: 'inflateBudget' },
): ThreeMfPackage {
  if (bytes.length < 22 || bytes[0] !== 0x50 || bytes[1] !== 0x4b) {
    throw new StrataError('BAD_FILE', 'not a 3MF file: a 3MF is a zip archive and this does not start like one');
  }
  const zip = new ZipArchive(bytes, budget, partKey);
  const models = [...zip.entries.keys()].filter((k) => k.endsWith('.model'));
  if (models.length === 0)
    throw new StrataError('BAD_FILE', 'not a valid 3MF file: the archive holds no 3D model part');
  const cache = new Map<string, Uint8Array>();
  const read = (key: string): Uint8Array | undefined => {
    const known = cache.get(key);
    if (known !== undefined) return known;
    const entry = zip.entries.get(key);
    if (entry === undefined) return undefined;
    const data = zip.read(entry);
    cache.set(key, data);
    return data;
  };
  const rels = read('_rels/.rels');
  const target = rels ? rootModelTarget(rels) : undefined;
  let root = target !== undefined ? partKey(target) : '';
  if (!zip.entries.has(root)) root = '3d/3dmodel.model';
  if (!zip.entries.has(root)) {
    if (models.length !== 1) {
      throw new StrataError(
        'BAD_FILE',
        'not a valid 3MF file: cannot tell which part is the 3D model (no usable _rels/.rels)',
      );
    }
    root = models[0];
  }
  const readFile = (key: string, maxBytes: number): Uint8Array | undefined => {
    const entry = zip.entries.get(key);
    if (entry === undefined) return undefined;
    if (entry.size > maxBytes) {
      const mib = (n: number) => `${Math.ceil((n / 1048576) * 10) / 10} MiB`;
      throw new StrataError(
        'LIMIT_EXCEEDED',
        `3MF part ${printable(entry.name)} unpacks to ${mib(entry.size)}, more than the ${mib(maxBytes)} a slicer config may take`,
      );
    }
    return read(key);
  };
  // only model parts are read as models
  return {
    root,
    read: (key) => (key.endsWith('.model') || key === root ? read(key) : undefined),
    keys: () => [...zip.entries.keys()],
    readFile,
  };
}

/** The Target of the first 3D-model relationship in `_rels/.rels`. */
function rootModelTarget(rels: Uint8Array): string | undefined {
  const x = new XmlScanner(rels, '3MF _rels/.rels', 16);
  for (let ev = x.next(); ev !== XML_EOF; ev = x.next()) {
    if (ev !== XML_START || !x.is('Relationship')) continue;
    let type = '';
    let target: string | undefined;
    while (x.nextAttr()) {
      if (x.attrIs('Type')) type = x.value();
      else if (x.attrIs('Target')) target = x.value();
    }
    if (type === MODEL_REL && target !== undefined) return target;
  }
  return undefined;
}
