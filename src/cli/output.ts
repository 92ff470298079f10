/**
 * Where the CLI writes: a file, written to a temporary file beside it and renamed into place only
 * when everything is written (so a failure, Ctrl-C or a full disk leaves the old file as it was and
 * no temporary file behind), or standard output. An output that is one of the inputs is refused
 * before anything is written. Write errors become one line, "cannot write PATH: no space left on
 * device"; a reader that closes the pipe early ends the command quietly (PipeClosed). A write-protected
 * file is not replaced (as `cp` without `-f` would not), and temporary files a killed run left beside
 * the target are removed by the next run that writes it.
 */
import {
  accessSync,
  chmodSync,
  closeSync,
  constants,
  fsyncSync,
  lstatSync,
  openSync,
  readdirSync,
  realpathSync,
  renameSync,
  statSync,
  unlinkSync,
  writeSync,
} from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { StrataError } from '../errors.js';

/** Thrown when the reader of standard output has gone (EPIPE): the command stops without a message. */
export class PipeClosed extends Error {
  constructor() {
    super('the reader of standard output has closed it');
    this.name = 'PipeClosed';
  }
}

export interface Output {
  /** As the user named it ('-' for standard output). */
  readonly path: string;
  /** Text (UTF-8) or bytes. */
  write(chunk: string | Uint8Array): void;
  /** Put the written data in place (rename the temporary file). */
  commit(): void;
  /** Throw away what was written; the target stays as it was. Safe to call more than once. */
  abort(): void;
}

const REASONS: Readonly<Record<string, string>> = {
  ENOSPC: 'no space left on device',
  EDQUOT: 'disk quota exceeded',
  EIO: 'input/output error',
  EFBIG: 'file too large',
  EACCES: 'permission denied',
  EPERM: 'operation not permitted',
  EROFS: 'read-only file system',
  ENOENT: 'no such folder',
  ENOTDIR: 'a part of the path is not a folder',
  EISDIR: 'it is a folder',
  ENAMETOOLONG: 'file name too long',
  EMFILE: 'too many open files',
  ENFILE: 'too many open files',
  EBUSY: 'the file is busy',
  ETXTBSY: 'the file is busy',
  EXDEV: 'the temporary file is on another device',
  EINVAL: 'the file cannot be written this way',
};

/** The one-line reason for a failed file operation ("no space left on device"). */
export function reasonOf(e: unknown): string {
  const code = (e as NodeJS.ErrnoException | null)?.code;
  if (code && REASONS[code]) return REASONS[code];
  const msg = e instanceof Error ? e.message : String(e);
  return (msg.split('\n')[0] ?? msg).replace(/^[A-Z]+: /, '').replace(/, \w+( '.*')?$/, '');
}

export function writeFailed(path: string, e: unknown): StrataError | PipeClosed {
  if ((e as NodeJS.ErrnoException | null)?.code === 'EPIPE') return new PipeClosed();
  return new StrataError('WRITE_FAILED', `cannot write ${path}: ${reasonOf(e)}`);
}

/** Write all of `buf` to `fd`, retrying short writes and a full non-blocking pipe. */
function writeAll(fd: number, buf: Uint8Array): void {
  let off = 0;
  while (off < buf.length) {
    try {
      off += writeSync(fd, buf, off, buf.length - off);
    } catch (e) {
      if ((e as NodeJS.ErrnoException).code !== 'EAGAIN') throw e;
      Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, 2);
    }
  }
}

/** What a path is on disk, following links: device and inode, or undefined when it does not exist. */
function identity(path: string): { dev: number; ino: number; file: boolean; mode: number } | undefined {
  try {
    const s = statSync(path);
    return { dev: s.dev, ino: s.ino, file: s.isFile(), mode: s.mode };
  } catch {
    return undefined;
  }
}

export interface NamedInput {
  path: string;
  /** What the input is, for the message: "model", "config file", "infill image"… */
  what: string;
}

/**
 * Refuse an output that is one of the inputs: the same path, or the same file through a hard or
 * symbolic link. `defaulted` says the output name was made from the model's name.
 */
export function refuseInputAsOutput(out: string, inputs: readonly NamedInput[], defaulted: boolean): void {
  if (out === '-') return;
  const target = identity(out);
  for (const input of inputs) {
    if (input.path === '-') continue;
    const same =
      resolve(input.path) === resolve(out) || (target !== undefined && sameFile(target, identity(input.path)));
    if (!same) continue;
    const how = resolve(input.path) === resolve(out) ? '' : ' (the same file through a link)';
    throw new StrataError(
      'BAD_FILE',
      defaulted
        ? `the default output ${out} is the ${input.what} ${input.path} itself${how}: writing G-code there would destroy it; name the output with -o`
        : `the output ${out} is the ${input.what} ${input.path}${how}: writing there would destroy it; choose another -o`,
    );
  }
}

function sameFile(a: { dev: number; ino: number }, b: { dev: number; ino: number } | undefined): boolean {
  return b !== undefined && a.dev === b.dev && a.ino === b.ino;
}

/** Temporary files not yet renamed or removed, so a signal handler can remove them. */
const pending = new Set<AtomicFile>();

/** Remove every temporary file still open (for signal and exit handlers). */
export function abortPendingOutputs(): void {
  for (const f of [...pending]) f.abort();
}

/** A temporary file older than this whose process is gone was left by a killed run, ms. */
export const STALE_TEMP_MS = 10 * 60 * 1000;

/** The temporary file's name for a target: hidden, with the writing process's id. */
function tempName(base: string): string {
  return `.${base}.${process.pid}.${Math.random().toString(36).slice(2, 10)}.tmp`;
}

function isAlive(pid: number): boolean {
  try {
    process.kill(pid, 0);
    return true;
  } catch (e) {
    // EPERM: it runs, as another user
    return (e as NodeJS.ErrnoException).code === 'EPERM';
  }
}

/**
 * Remove the temporary files of `base` in `dir` that a run killed before it could clean up left
 * (SIGKILL, a power cut): our name pattern, untouched for STALE_TEMP_MS, their process gone.
 */
export function removeStaleTemps(dir: string, base: string, now = Date.now()): void {
  const escaped = base.replace(/[.*+?^$|()[\]{}\\]/g, '\\$&');
  const pattern = new RegExp(`^\\.${escaped}\\.(\\d+)\\.[0-9a-z]{1,8}\\.tmp$`);
  let names: string[];
  try {
    names = readdirSync(dir);
  } catch {
    return;
  }
  for (const name of names) {
    const m = pattern.exec(name);
    if (!m || Number(m[1]) === process.pid || isAlive(Number(m[1]))) continue;
    const path = join(dir, name);
    try {
      const s = lstatSync(path);
      if (s.isFile() && now - s.mtimeMs > STALE_TEMP_MS) unlinkSync(path);
    } catch {
      // gone already, or not ours to remove
    }
  }
}

/** Refuse to replace a file that is write-protected (no write permission bits, or none for us). */
function refuseProtected(path: string, target: string, mode: number): void {
  let writable = (mode & 0o222) !== 0;
  if (writable) {
    try {
      accessSync(target, constants.W_OK);
    } catch {
      writable = false;
    }
  }
  if (!writable)
    throw new StrataError(
      'WRITE_FAILED',
      `cannot write ${path}: the file is write-protected (make it writable, or choose another -o)`,
    );
}

class AtomicFile implements Output {
  readonly path: string;
  readonly #target: string;
  readonly #temp: string;
  readonly #mode: number | undefined;
  #fd: number | null;

  constructor(path: string) {
    this.path = path;
    const existing = identity(path);
    // write through a symbolic link: replace the file it points at, and keep the link
    let target = resolve(path);
    try {
      target = realpathSync(path);
    } catch {
      // a new file
    }
    this.#target = target;
    this.#mode = existing?.mode;
    if (existing) refuseProtected(path, target, existing.mode);
    removeStaleTemps(dirname(target), basename(target));
    this.#temp = join(dirname(target), tempName(basename(target)));
    try {
      this.#fd = openSync(this.#temp, 'wx', 0o666);
    } catch (e) {
      throw writeFailed(path, e);
    }
    pending.add(this);
  }

  write(chunk: string | Uint8Array): void {
    if (this.#fd === null) throw new StrataError('WRITE_FAILED', `cannot write ${this.path}: the output is closed`);
    try {
      writeAll(this.#fd, typeof chunk === 'string' ? Buffer.from(chunk, 'utf8') : chunk);
    } catch (e) {
      this.abort();
      throw writeFailed(this.path, e);
    }
  }

  commit(): void {
    if (this.#fd === null) throw new StrataError('WRITE_FAILED', `cannot write ${this.path}: the output is closed`);
    const fd = this.#fd;
    try {
      fsyncSync(fd);
      closeSync(fd);
      this.#fd = null;
      // an existing file keeps its permissions
      if (this.#mode !== undefined) chmodSync(this.#temp, this.#mode & 0o7777);
      renameSync(this.#temp, this.#target);
      pending.delete(this);
    } catch (e) {
      this.abort();
      throw writeFailed(this.path, e);
    }
  }

  abort(): void {
    if (this.#fd !== null) {
      try {
        closeSync(this.#fd);
      } catch {
        // already closed
      }
      this.#fd = null;
    }
    if (!pending.has(this)) return;
    pending.delete(this);
    try {
      unlinkSync(this.#temp);
    } catch {
      // gone already
    }
  }
}

/** A device or pipe given as output (/dev/null, a FIFO): written directly, nothing to rename. */
class DirectFile implements Output {
  readonly path: string;
  #fd: number | null;
  constructor(path: string, fd: number | null) {
    this.path = path;
    this.#fd = fd;
  }
  write(chunk: string | Uint8Array): void {
    if (this.#fd === null) return;
    try {
      writeAll(this.#fd, typeof chunk === 'string' ? Buffer.from(chunk, 'utf8') : chunk);
    } catch (e) {
      throw writeFailed(this.path === '-' ? 'standard output' : this.path, e);
    }
  }
  commit(): void {
    this.#close();
  }
  abort(): void {
    this.#close();
  }
  #close(): void {
    if (this.#fd === null || this.#fd === 1) return;
    try {
      closeSync(this.#fd);
    } catch {
      // nothing to do
    }
    this.#fd = null;
  }
}

/** Open the output: '-' is standard output, a regular (or new) file is written atomically. */
export function openOutput(path: string): Output {
  if (path === '-') return new DirectFile('-', 1);
  const existing = identity(path);
  if (existing && !existing.file) {
    let isDir = false;
    try {
      isDir = statSync(path).isDirectory();
    } catch {
      // raced away
    }
    if (isDir) throw new StrataError('WRITE_FAILED', `cannot write ${path}: it is a folder`);
    try {
      return new DirectFile(path, openSync(path, 'w'));
    } catch (e) {
      throw writeFailed(path, e);
    }
  }
  return new AtomicFile(path);
}
