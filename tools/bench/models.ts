/**
 * The benchmark's models: listing the shared folder, unpacking gzipped STL once into a work folder, making the
 * big mesh (3DBenchy subdivided once, about 1 M triangles), and counting triangles (for the tables only; the
 * slicers parse the files themselves).
 */
import { existsSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gunzipSync } from 'node:zlib';
import { strFromU8, unzipSync } from 'fflate';
import { subdivideBinaryStl } from './subdivide.js';

export interface BenchModel {
  /** Display name: the file name, without .gz for unpacked files. */
  name: string;
  /** Path the slicers read (inside the work folder for unpacked files). */
  path: string;
  triangles: number | null;
  /** How the bench made it, for models that are not files in the folder (the big mesh); else absent. */
  madeFrom?: string;
}

/** The big mesh: 3DBenchy after one round of midpoint subdivision (4 × 225,154 = 900,616 triangles). */
export const BIG_MODEL = '3DBenchy-x4.stl';
/** Files the big mesh can be made from, in order of preference. */
export const BIG_MODEL_SOURCES = Object.freeze(['3DBenchy.stl', '3DBenchy.stl.gz']);

/** The file in `names` the big mesh is made from, or null when the folder has none. */
export function bigModelSource(names: readonly string[]): string | null {
  return BIG_MODEL_SOURCES.find((s) => names.includes(s)) ?? null;
}

const MODEL_EXTENSIONS = Object.freeze(['.stl', '.stl.gz', '.3mf', '.obj']);

/** ../shared/models beside the repository, from dist-dev/tools/bench/ (or tools/bench/). */
export function defaultModelsDir(): string {
  return fileURLToPath(new URL('../../../../shared/models/', import.meta.url));
}

/** Model file names in a folder (STL, gzipped STL, 3MF, OBJ), sorted by name. */
export function listModelFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true })
    .filter((e) => e.isFile() && MODEL_EXTENSIONS.some((ext) => e.name.toLowerCase().endsWith(ext)))
    .map((e) => e.name)
    .sort((a, b) => a.localeCompare(b, 'en'));
}

/**
 * Triangle count of a model file's bytes: binary STL from its header (when the size matches), ASCII STL by
 * counting facets, 3MF by counting <triangle> elements, OBJ by counting faces as triangle fans. Null if unknown.
 */
export function countTriangles(name: string, bytes: Uint8Array): number | null {
  const lower = name.toLowerCase().replace(/\.gz$/, '');
  if (lower.endsWith('.stl')) {
    if (bytes.length >= 84) {
      const n = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(80, true);
      if (84 + 50 * n === bytes.length) return n;
    }
    const text = Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength).toString('latin1');
    return text.match(/\bfacet\s+normal\b/g)?.length ?? 0;
  }
  if (lower.endsWith('.3mf')) {
    try {
      const files = unzipSync(bytes, { filter: (f) => f.name.toLowerCase().endsWith('.model') });
      let n = 0;
      for (const data of Object.values(files)) n += strFromU8(data).match(/<(?:\w+:)?triangle\b/g)?.length ?? 0;
      return n;
    } catch {
      return null;
    }
  }
  if (lower.endsWith('.obj')) {
    let n = 0;
    const text = Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength).toString('latin1');
    for (const line of text.split('\n')) {
      if (line.startsWith('f ')) n += Math.max(0, line.trim().split(/\s+/).length - 3);
    }
    return n;
  }
  return null;
}

/** The bytes of a model file, gunzipped when its name ends in .gz. */
function readModel(dir: string, file: string): Uint8Array {
  const bytes: Uint8Array = readFileSync(join(dir, file));
  return file.toLowerCase().endsWith('.gz') ? gunzipSync(bytes) : bytes;
}

/**
 * Reads the chosen files; gzipped ones are unpacked once into workDir, and BIG_MODEL, unless the folder has
 * that file, is made there from the folder's 3DBenchy STL.
 */
export function prepareModels(dir: string, names: readonly string[], workDir: string): BenchModel[] {
  return names.map((file) => {
    if (file === BIG_MODEL && !existsSync(join(dir, file))) {
      const source = bigModelSource(listModelFiles(dir));
      if (!source)
        throw new Error(`${BIG_MODEL} is made from ${BIG_MODEL_SOURCES.join(' or ')}, and ${dir} has neither`);
      const big = subdivideBinaryStl(
        readModel(dir, source),
        `${source.replace(/\.gz$/i, '')} after one round of midpoint subdivision`,
      );
      const path = join(workDir, BIG_MODEL);
      writeFileSync(path, big);
      return {
        name: BIG_MODEL,
        path,
        triangles: countTriangles(BIG_MODEL, big),
        madeFrom: `${source.replace(/\.gz$/i, '')}, each triangle split into 4 at its edge midpoints`,
      };
    }
    const bytes: Uint8Array = readFileSync(join(dir, file));
    if (file.toLowerCase().endsWith('.gz')) {
      const name = file.slice(0, -3);
      const unpacked = gunzipSync(bytes);
      const path = join(workDir, name);
      writeFileSync(path, unpacked);
      return { name, path, triangles: countTriangles(name, unpacked) };
    }
    return { name: file, path: join(dir, file), triangles: countTriangles(file, bytes) };
  });
}
