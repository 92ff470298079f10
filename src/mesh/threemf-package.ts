/**
 * The 3MF container: a zip (OPC package) whose `_rels/.rels` points at the root model part.
 * Only `.rels` and `*.model` entries are inflated, each after checking its declared size
 * (fflate inflates into a buffer of exactly that size, so the check bounds memory).
 */
import { unzipSync } from 'fflate';
import { StrataError } from '../errors.js';
import { printable } from './printable.js';
import { XML_EOF, XML_START, XmlScanner } from './xml-scanner.js';

/** Largest single part we inflate. */
export const MAX_PART_BYTES = 1024 * 1024 * 1024;
/** Largest total of inflated parts. */
export const MAX_TOTAL_BYTES = 1536 * 1024 * 1024;

const MODEL_REL = 'http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel';

export interface ThreeMfPackage {
  /** Normalised part name (no leading "/", lower case) → bytes, for every *.model part. */
  parts: Map<string, Uint8Array>;
  /** Normalised name of the root model part. */
  root: string;
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

export function openPackage(bytes: Uint8Array): ThreeMfPackage {
  if (bytes.length < 22 || bytes[0] !== 0x50 || bytes[1] !== 0x4b) {
    throw new StrataError('BAD_FILE', 'not a 3MF file: a 3MF is a zip archive and this does not start like one');
  }
  let total = 0;
  let files: Record<string, Uint8Array>;
  try {
    files = unzipSync(bytes, {
      filter: (f) => {
        const key = partKey(f.name);
        if (key !== '_rels/.rels' && !key.endsWith('.model')) return false;
        if (f.originalSize > MAX_PART_BYTES) {
          throw new StrataError(
            'LIMIT_EXCEEDED',
            `3MF part ${printable(f.name)} would inflate to ${f.originalSize} bytes; the limit is ${MAX_PART_BYTES} bytes`,
          );
        }
        total += f.originalSize;
        if (total > MAX_TOTAL_BYTES) {
          throw new StrataError('LIMIT_EXCEEDED', `3MF model parts would inflate to more than ${MAX_TOTAL_BYTES} bytes`);
        }
        return true;
      },
    });
  } catch (err) {
    if (err instanceof StrataError) throw err;
    const why = err instanceof Error ? err.message : String(err);
    throw new StrataError('BAD_FILE', `not a valid 3MF file: the zip archive is damaged (${printable(why)})`);
  }

  const parts = new Map<string, Uint8Array>();
  let rels: Uint8Array | undefined;
  for (const [name, data] of Object.entries(files)) {
    const key = partKey(name);
    if (key === '_rels/.rels') rels = data;
    else parts.set(key, data);
  }
  if (parts.size === 0) throw new StrataError('BAD_FILE', 'not a valid 3MF file: the archive holds no 3D model part');

  const target = rels ? rootModelTarget(rels) : undefined;
  let root = target !== undefined ? partKey(target) : '';
  if (!parts.has(root)) root = '3d/3dmodel.model';
  if (!parts.has(root)) {
    const models = [...parts.keys()];
    if (models.length !== 1) {
      throw new StrataError('BAD_FILE', 'not a valid 3MF file: cannot tell which part is the 3D model (no usable _rels/.rels)');
    }
    root = models[0];
  }
  return { parts, root };
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
