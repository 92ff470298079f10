/**
 * Reading the command line's inputs within a limit per kind, asynchronously and in chunks, so that a
 * device or a pipe that never ends (`--config /dev/zero`, `strata slice -` at a terminal) stops at
 * the limit with one line naming it and the file, and Ctrl-C or SIGTERM is handled between chunks
 * (a synchronous read would hold the event loop, and with it the signal handlers, until it ended).
 * A regular file's size is checked before anything is read.
 */
import { open, type FileHandle } from 'node:fs/promises';
import { extname } from 'node:path';
import { StrataError } from '../errors.js';
import { MAX_MODEL_TRIANGLES } from '../mesh/limits.js';

const MiB = 1024 * 1024;

/** Bytes read at a time. */
const CHUNK = 1 * MiB;

export type InputKind = 'model' | 'config' | 'shader' | 'image';

/** Largest input of each kind, bytes, and how the limit is put in words. */
export const INPUT_LIMITS: Readonly<Record<InputKind, { bytes: number; why?: string }>> = {
  // a binary STL of the most triangles a model may have: 84 bytes of header and count, 50 a triangle
  model: {
    bytes: 84 + 50 * MAX_MODEL_TRIANGLES,
    why: `a binary STL of ${MAX_MODEL_TRIANGLES / 1e6} million triangles`,
  },
  config: { bytes: 16 * MiB },
  // (the shader compiler takes a quarter of this in characters; IceSL's shaders are a few kB)
  shader: { bytes: 1 * MiB },
  image: { bytes: 64 * MiB },
};

/** A G-code file's settings are in its first and last lines: of a large one, only these many bytes of its head are read. */
const GCODE_HEAD = 64 * 1024;

function sizeText(bytes: number): string {
  return bytes >= MiB ? `${Math.round(bytes / MiB)} MiB` : `${Math.round(bytes / 1024)} KiB`;
}

function tooLarge(path: string, what: string, kind: InputKind): StrataError {
  const { bytes, why } = INPUT_LIMITS[kind];
  const name = path === '-' ? 'standard input' : path;
  return new StrataError(
    'LIMIT_EXCEEDED',
    `cannot read ${name}: the ${what} is larger than the ${sizeText(bytes)} allowed${why ? ` (${why})` : ''}`,
  );
}

function unreadable(path: string, e: unknown): StrataError {
  if (e instanceof StrataError) return e;
  const code = (e as NodeJS.ErrnoException).code;
  const why =
    code === 'ENOENT'
      ? 'no such file'
      : code === 'EISDIR'
        ? 'it is a folder'
        : code === 'EACCES'
          ? 'permission denied'
          : code === 'ENXIO'
            ? 'no such device'
            : (e as Error).message;
  return new StrataError('BAD_FILE', `cannot read ${path === '-' ? 'standard input' : path}: ${why}`);
}

/** Join chunks into one array. */
function joined(chunks: Uint8Array[], total: number): Uint8Array {
  if (chunks.length === 1) return chunks[0];
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

/** Read a handle from `position` (or from where it stands, for devices and pipes) until its end, or refuse past `limit`. */
async function readAll(
  fh: FileHandle,
  limit: number,
  onTooLarge: () => StrataError,
  position: number | null = null,
  upTo = Infinity,
): Promise<Uint8Array> {
  const chunks: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const want = Math.min(CHUNK, upTo - total);
    if (want <= 0) break;
    const buf = new Uint8Array(want);
    const { bytesRead } = await fh.read(buf, 0, want, position === null ? null : position + total);
    if (bytesRead === 0) break;
    total += bytesRead;
    if (total > limit) throw onTooLarge();
    chunks.push(bytesRead === want ? buf : buf.subarray(0, bytesRead));
  }
  return joined(chunks, total);
}

/**
 * A regular file of known size, read into one buffer of that size in chunks (no joining copy); a
 * file that shrank while being read gives what it had.
 */
async function readSized(fh: FileHandle, size: number): Promise<Uint8Array> {
  const out = new Uint8Array(size);
  let total = 0;
  while (total < size) {
    const { bytesRead } = await fh.read(out, total, Math.min(4 * CHUNK, size - total), total);
    if (bytesRead === 0) return out.subarray(0, total);
    total += bytesRead;
  }
  return out;
}

/** Standard input, in the chunks it arrives in, up to `limit` bytes. */
async function readStdin(limit: number, onTooLarge: () => StrataError): Promise<Uint8Array> {
  const stdin = process.stdin;
  const chunks: Uint8Array[] = [];
  let total = 0;
  try {
    for await (const chunk of stdin as AsyncIterable<Buffer>) {
      total += chunk.length;
      if (total > limit) throw onTooLarge();
      chunks.push(chunk);
    }
  } finally {
    // a terminal or a pipe left open would keep the process waiting
    stdin.destroy();
  }
  return joined(chunks, total);
}

/**
 * The bytes of `path` ('-' is standard input), at most the limit of its kind; `what` names it in
 * messages ("model", "config file"). Of a G-code file larger than a config may be, only its head and
 * tail are read (where slicers write their settings).
 */
export async function readInput(path: string, kind: InputKind, what: string): Promise<Uint8Array> {
  const limit = INPUT_LIMITS[kind].bytes;
  const onTooLarge = () => tooLarge(path, what, kind);
  if (path === '-') return readStdin(limit, onTooLarge).catch((e) => Promise.reject(unreadable(path, e)));
  let fh: FileHandle | undefined;
  try {
    fh = await open(path, 'r');
    const s = await fh.stat();
    if (s.isDirectory()) throw Object.assign(new Error('it is a folder'), { code: 'EISDIR' });
    if (!s.isFile()) return await readAll(fh, limit, onTooLarge);
    if (s.size <= limit) return await readSized(fh, s.size);
    if (kind === 'config' && /^\.(gcode|gco|g)$/i.test(extname(path))) return await headAndTail(fh, s.size, limit);
    throw onTooLarge();
  } catch (e) {
    throw unreadable(path, e);
  } finally {
    await fh?.close().catch(() => {});
  }
}

/** The first and last bytes of a large G-code file (cut at whole lines), `limit` in all. */
async function headAndTail(fh: FileHandle, size: number, limit: number): Promise<Uint8Array> {
  const head = await readAll(fh, limit, () => new StrataError('LIMIT_EXCEEDED', 'unreachable'), 0, GCODE_HEAD);
  const tailBytes = limit - GCODE_HEAD;
  const tail = await readAll(
    fh,
    limit,
    () => new StrataError('LIMIT_EXCEEDED', 'unreachable'),
    size - tailBytes,
    tailBytes,
  );
  const headEnd = head.lastIndexOf(0x0a) + 1;
  const tailStart = tail.indexOf(0x0a) + 1;
  return joined([head.subarray(0, headEnd), tail.subarray(tailStart)], headEnd + tail.length - tailStart);
}
