/**
 * Reading a zip archive (a 3MF package) one entry at a time, with a budget on what is unpacked.
 *
 * The central directory is read first, without inflating anything; an entry is inflated only when
 * asked for, and only if its declared size fits what is left of the budget and the archive's
 * unpacked-to-packed ratio stays believable. Inflation streams in small slices and stops as soon as
 * an entry produces more than it declared, so a lying or hostile archive ("zip bomb") costs at most
 * a few slices of work and memory before it is refused. No I/O here.
 *
 * Why not a zip library: fflate does the inflating (above), but its archive readers (unzip, Unzip) unpack
 * whole entries or trust the declared sizes, and none of the small, well-kept zip readers for browsers
 * enforces a budget and a packing ratio per entry. Those limits are the point of this reader, so the
 * directory walk (about a hundred lines) stays here.
 */
import { Inflate } from 'fflate';
import { StrataError } from '../errors.js';
import { printable } from './printable.js';

export interface ZipEntry {
  name: string;
  /** 0 stored, 8 deflated. */
  method: number;
  packedSize: number;
  size: number;
  /** Offset of the local header. */
  offset: number;
  encrypted: boolean;
}

export interface ZipBudget {
  /** Most bytes all entries read from this archive may unpack to together. */
  maxBytes: number;
  /** Name of the setting that raises maxBytes, for messages. */
  setting: string;
}

/**
 * Real model data (XML of coordinates) packs 3–20×; DEFLATE can reach ~1000×, which only crafted data
 * does. Past the first MIN_RATIO_CHECK_BYTES, what an archive unpacks to may not exceed this many times
 * the packed bytes it came from.
 */
export const MAX_INFLATE_RATIO = 200;
/** Unpacked bytes allowed before the ratio is enforced (small parts of any ratio are harmless). */
export const MIN_RATIO_CHECK_BYTES = 32 * 1024 * 1024;
/**
 * Packed bytes fed to the inflater at a time: at most ~1032× this comes out before a check, so the
 * slice follows the declared size (an entry that lies is caught within a few times its claim).
 */
const MIN_SLICE_BYTES = 4 * 1024;
const MAX_SLICE_BYTES = 256 * 1024;

const MiB = 1024 * 1024;

function damaged(why: string): StrataError {
  return new StrataError('BAD_FILE', `not a valid 3MF file: the zip archive is damaged (${why})`);
}

export class ZipArchive {
  readonly entries: ReadonlyMap<string, ZipEntry>;
  readonly #bytes: Uint8Array;
  readonly #dv: DataView;
  readonly #budget: ZipBudget;
  #unpacked = 0;
  #packed = 0;

  /** `key` maps an entry name to the key it is looked up by (e.g. normalised part names). */
  constructor(bytes: Uint8Array, budget: ZipBudget, key: (name: string) => string = (n) => n) {
    this.#bytes = bytes;
    this.#dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.#budget = budget;
    const entries = new Map<string, ZipEntry>();
    for (const e of this.#centralDirectory()) {
      const k = key(e.name);
      if (!entries.has(k)) entries.set(k, e);
    }
    this.entries = entries;
  }

  /** Bytes unpacked so far. */
  get unpackedBytes(): number {
    return this.#unpacked;
  }

  /** The entry's contents, inflated within the budget. */
  read(entry: ZipEntry): Uint8Array {
    const label = printable(entry.name);
    if (entry.encrypted) throw new StrataError('BAD_FILE', `3MF part ${label} is encrypted; Strata cannot read it`);
    if (entry.method !== 0 && entry.method !== 8) {
      throw new StrataError(
        'BAD_FILE',
        `3MF part ${label} uses zip compression method ${entry.method}; only stored and deflated parts can be read`,
      );
    }
    const left = this.#budget.maxBytes - this.#unpacked;
    if (entry.size > left) {
      throw new StrataError(
        'LIMIT_EXCEEDED',
        `3MF part ${label} unpacks to ${mib(entry.size)}, more than the ${mib(left)} left of the ${mib(this.#budget.maxBytes)} budget; raise ${this.#budget.setting} to read it`,
      );
    }
    const unpacked = this.#unpacked + entry.size;
    const packed = this.#packed + entry.packedSize;
    if (entry.method === 8 && unpacked > MIN_RATIO_CHECK_BYTES && unpacked > MAX_INFLATE_RATIO * packed) {
      throw new StrataError(
        'LIMIT_EXCEEDED',
        `3MF part ${label} claims to unpack ${mib(entry.packedSize)} into ${mib(entry.size)} (${Math.round(entry.size / Math.max(1, entry.packedSize))}×; model data packs at most ~20×): refused as a zip bomb`,
      );
    }
    const data = this.#entryData(entry);
    const out = entry.method === 0 ? data.slice() : inflateExactly(data, entry.size, label);
    this.#unpacked = unpacked;
    this.#packed = packed;
    return out;
  }

  #entryData(e: ZipEntry): Uint8Array {
    const b = this.#bytes;
    const o = e.offset;
    if (o + 30 > b.length || this.#dv.getUint32(o, true) !== 0x04034b50)
      throw damaged(`no local header for ${printable(e.name)}`);
    const start = o + 30 + this.#dv.getUint16(o + 26, true) + this.#dv.getUint16(o + 28, true);
    const end = start + e.packedSize;
    if (end > b.length) throw damaged(`${printable(e.name)} runs past the end of the file`);
    if (e.method === 0 && e.packedSize !== e.size) throw damaged(`stored part ${printable(e.name)} has two sizes`);
    return b.subarray(start, end);
  }

  #centralDirectory(): ZipEntry[] {
    const b = this.#bytes;
    const dv = this.#dv;
    // the end-of-central-directory record: 22 bytes plus a comment of up to 65535
    let eocd = -1;
    for (let i = b.length - 22; i >= Math.max(0, b.length - 22 - 65535); i--) {
      if (dv.getUint32(i, true) === 0x06054b50) {
        eocd = i;
        break;
      }
    }
    if (eocd < 0) throw damaged('no end-of-directory record; the file may be truncated');
    let count = dv.getUint16(eocd + 10, true);
    let cdSize = dv.getUint32(eocd + 12, true);
    let cdOffset = dv.getUint32(eocd + 16, true);
    if (count === 0xffff || cdSize === 0xffffffff || cdOffset === 0xffffffff) {
      // zip64: a locator just before the record points at the zip64 end record
      const loc = eocd - 20;
      if (loc < 0 || dv.getUint32(loc, true) !== 0x07064b50) throw damaged('zip64 sizes without a zip64 locator');
      const rec = u64(dv, loc + 8);
      if (rec + 56 > b.length || dv.getUint32(rec, true) !== 0x06064b50) throw damaged('zip64 end record missing');
      count = u64(dv, rec + 32);
      cdSize = u64(dv, rec + 40);
      cdOffset = u64(dv, rec + 48);
    }
    if (cdOffset + cdSize > b.length) throw damaged('the directory runs past the end of the file');
    // each directory entry takes at least 46 bytes, which bounds the count by the file size
    if (count * 46 > cdSize) throw damaged('the directory is shorter than its entry count');
    const out: ZipEntry[] = [];
    const names = new TextDecoder('utf-8');
    let p = cdOffset;
    for (let n = 0; n < count; n++) {
      if (p + 46 > cdOffset + cdSize || dv.getUint32(p, true) !== 0x02014b50)
        throw damaged('a directory entry is broken');
      const flags = dv.getUint16(p + 8, true);
      const method = dv.getUint16(p + 10, true);
      let packedSize = dv.getUint32(p + 20, true);
      let size = dv.getUint32(p + 24, true);
      const nameLen = dv.getUint16(p + 28, true);
      const extraLen = dv.getUint16(p + 30, true);
      const commentLen = dv.getUint16(p + 32, true);
      let offset = dv.getUint32(p + 42, true);
      const nameStart = p + 46;
      const extraStart = nameStart + nameLen;
      const next = extraStart + extraLen + commentLen;
      if (next > cdOffset + cdSize) throw damaged('a directory entry runs past the directory');
      const name = names.decode(b.subarray(nameStart, extraStart));
      if (size === 0xffffffff || packedSize === 0xffffffff || offset === 0xffffffff) {
        // zip64 extra field (id 1): the 64-bit values, in this order, for the fields that overflowed
        for (let q = extraStart; q + 4 <= extraStart + extraLen; ) {
          const id = dv.getUint16(q, true);
          const len = dv.getUint16(q + 2, true);
          if (id === 1) {
            let r = q + 4;
            const take = (): number => {
              if (r + 8 > q + 4 + len) throw damaged(`zip64 field of ${printable(name)} too short`);
              const v = u64(dv, r);
              r += 8;
              return v;
            };
            if (size === 0xffffffff) size = take();
            if (packedSize === 0xffffffff) packedSize = take();
            if (offset === 0xffffffff) offset = take();
            break;
          }
          q += 4 + len;
        }
      }
      out.push({ name, method, packedSize, size, offset, encrypted: (flags & 1) !== 0 });
      p = next;
    }
    return out;
  }
}

function u64(dv: DataView, at: number): number {
  if (at + 8 > dv.byteLength) throw damaged('a 64-bit field runs past the end of the file');
  const v = dv.getBigUint64(at, true);
  if (v > BigInt(Number.MAX_SAFE_INTEGER)) throw damaged('a 64-bit size is out of range');
  return Number(v);
}

/** Inflate raw DEFLATE data that must come to exactly `size` bytes, stopping as soon as it exceeds it. */
function inflateExactly(data: Uint8Array, size: number, label: string): Uint8Array {
  const out = new Uint8Array(size);
  let filled = 0;
  let over = false;
  let ended = false;
  const inflater = new Inflate((chunk, final) => {
    if (filled + chunk.length > size) {
      over = true;
      return;
    }
    out.set(chunk, filled);
    filled += chunk.length;
    if (final) ended = true;
  });
  const slice = Math.min(MAX_SLICE_BYTES, Math.max(MIN_SLICE_BYTES, Math.floor(size / 1024)));
  try {
    for (let at = 0; at < data.length && !over && !ended; at += slice) {
      const end = Math.min(data.length, at + slice);
      inflater.push(data.subarray(at, end), end === data.length);
    }
  } catch (e) {
    throw damaged(`${label}: ${printable(e instanceof Error ? e.message : String(e))}`);
  }
  if (over) throw damaged(`${label} unpacks to more than the ${size} bytes it declares`);
  if (filled !== size) throw damaged(`${label} unpacks to ${filled} bytes, not the ${size} it declares`);
  return out;
}

/** A size for messages: bytes, KiB or MiB. */
function mib(bytes: number): string {
  if (bytes < 1024) return `${bytes} bytes`;
  if (bytes < MiB) return `${Math.round(bytes / 1024)} KiB`;
  const v = bytes / MiB;
  return `${v >= 10 ? Math.round(v) : Math.round(v * 10) / 10} MiB`;
}
