/**
 * Node adapter: read custom infillers from disk — a single shader or image file, or a folder in
 * IceSL's layout (`NAME/shader.glsl`, `NAME/cells.png`) — and list them with their parameters.
 */
import { readdir, readFile, stat } from 'node:fs/promises';
import { basename, dirname, extname, join } from 'node:path';
import { StrataError } from '../errors.js';
import type { Infiller, InfillerFiles, InfillerInfo } from './infiller.js';
import { describeInfiller, infillerFromImage, infillerFromShader, loadInfiller } from './infiller.js';
import { MAX_SOURCE_LENGTH } from './shader.js';
import { iceslInfillersDirs, shippedInfillersDir } from './infiller-dirs.js';

export { iceslInfillersDirs, shippedInfillersDir };

/** Largest cells.png read, bytes. */
const MAX_IMAGE_BYTES = 64 * 1024 * 1024;
/** Most infiller folders read from one directory. */
const MAX_ENTRIES = 1000;

async function readLimited(path: string, limit: number): Promise<Buffer> {
  const s = await stat(path);
  if (!s.isFile()) throw new StrataError('BAD_FILE', `${path} is not a file`);
  if (s.size > limit) throw new StrataError('LIMIT_EXCEEDED', `${path} is larger than ${limit} bytes`);
  return readFile(path);
}

async function exists(path: string): Promise<boolean> {
  try {
    return (await stat(path)).isFile();
  } catch {
    return false;
  }
}

/** The file contents of every infiller in a folder (missing folder → empty list). */
export async function readInfillersFolder(dir: string): Promise<InfillerFiles[]> {
  let names: string[];
  try {
    const entries = await readdir(dir, { withFileTypes: true });
    names = entries.filter((e) => e.isDirectory() && !e.name.startsWith('.')).map((e) => e.name);
  } catch (e) {
    if ((e as NodeJS.ErrnoException).code === 'ENOENT') return [];
    throw new StrataError('BAD_FILE', `cannot read infillers folder ${dir}: ${(e as Error).message}`);
  }
  names.sort();
  if (names.length > MAX_ENTRIES) names = names.slice(0, MAX_ENTRIES);
  const out: InfillerFiles[] = [];
  for (const name of names) {
    const shaderPath = join(dir, name, 'shader.glsl');
    const imagePath = join(dir, name, 'cells.png');
    if (await exists(shaderPath)) {
      out.push({ name, shader: (await readLimited(shaderPath, MAX_SOURCE_LENGTH * 4)).toString('utf8') });
    } else if (await exists(imagePath)) {
      out.push({ name, image: new Uint8Array(await readLimited(imagePath, MAX_IMAGE_BYTES)) });
    }
  }
  return out;
}

export interface ListedInfiller extends Partial<InfillerInfo> {
  name: string;
  /** Folder the infiller was found in. */
  dir: string;
  /** Why it could not be loaded. */
  error?: string;
}

/** List a folder's infillers with kind, passes and ui_ parameters (`strata infillers`). */
export async function listInfillers(dir: string = shippedInfillersDir()): Promise<ListedInfiller[]> {
  const files = await readInfillersFolder(dir);
  return files.map((f) => {
    try {
      return { ...describeInfiller(loadInfiller(f)), dir };
    } catch (e) {
      if (e instanceof StrataError)
        return { name: f.name, kind: f.shader !== undefined ? 'shader' : 'image', dir, error: e.message };
      throw e;
    }
  });
}

/** Load infiller NAME from the first folder that has it. */
export async function findInfiller(
  name: string,
  dirs: readonly string[] = [shippedInfillersDir(), ...iceslInfillersDirs()],
): Promise<Infiller> {
  for (const dir of dirs) {
    const files = await readInfillersFolder(dir);
    const f = files.find((x) => x.name === name);
    if (f !== undefined) return loadInfiller(f);
  }
  throw new StrataError('BAD_SETTING', `unknown infiller '${name.slice(0, 60)}' (looked in ${dirs.join(', ')})`);
}

/** Load a shader (`--infill-shader FILE`) or image (`--infill-image FILE`) file. */
export async function loadInfillerFile(path: string, kind?: 'shader' | 'image'): Promise<Infiller> {
  const k = kind ?? (extname(path).toLowerCase() === '.png' ? 'image' : 'shader');
  const name =
    basename(path) === 'shader.glsl' || basename(path) === 'cells.png'
      ? basename(dirname(path))
      : basename(path, extname(path));
  if (k === 'image')
    return infillerFromImage(new Uint8Array(await readLimited(path, MAX_IMAGE_BYTES)), name, {
      fileName: basename(path),
    });
  return infillerFromShader((await readLimited(path, MAX_SOURCE_LENGTH * 4)).toString('utf8'), name, {
    fileName: basename(path),
  });
}
