/**
 * Bounds on an infill image before it is decoded. The header gives the pixel count, which fixes
 * exactly how many bytes the image data must unpack to; the data is inflated (streamed, in slices)
 * only to check it does not unpack to more, so a small PNG that claims a tiny picture but holds a
 * "zip bomb" is refused after a few slices. Compressed side chunks (an ICC colour profile, zTXt and
 * iTXt text) play no part in the cells and are dropped before decoding, so they are never inflated.
 */
import { Unzlib } from 'fflate';
import { StrataError } from '../errors.js';

export interface PngHeader {
  width: number;
  height: number;
  depth: number;
  colorType: number;
  interlaced: boolean;
}

const SIGNATURE = [137, 80, 78, 71, 13, 10, 26, 10];
/** Chunks dropped before decoding: compressed data a cell image does not use. */
const DROPPED = new Set(['iCCP', 'zTXt', 'iTXt']);
/** Samples per pixel by colour type (grey, -, RGB, palette, grey+alpha, -, RGBA). */
const CHANNELS: Readonly<Record<number, number>> = { 0: 1, 2: 3, 3: 1, 4: 2, 6: 4 };
/** Packed bytes fed to the inflater at a time: at most ~1032× this comes out before a check, so the
 * slice follows what the pixels need (a lie is caught within a few times the honest size). */
const MIN_SLICE_BYTES = 256;
const MAX_SLICE_BYTES = 64 * 1024;

function bad(fileName: string, message: string): StrataError {
  return new StrataError('BAD_IMAGE', `${fileName}: ${message}`);
}

/** Width, height, bit depth, colour type and interlacing from the IHDR chunk, without decoding. */
export function readPngHeader(bytes: Uint8Array, fileName: string): PngHeader {
  if (bytes.length < 33 || SIGNATURE.some((b, i) => bytes[i] !== b)) throw bad(fileName, 'not a PNG file');
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const type = String.fromCharCode(bytes[12], bytes[13], bytes[14], bytes[15]);
  if (type !== 'IHDR') throw bad(fileName, 'broken PNG (no IHDR chunk)');
  return {
    width: dv.getUint32(16),
    height: dv.getUint32(20),
    depth: bytes[24],
    colorType: bytes[25],
    interlaced: bytes[28] === 1,
  };
}

/** Bytes the image's scanlines take once inflated (one filter byte per row, Adam7 passes when interlaced). */
export function pngDataBytes(h: PngHeader): number {
  const channels = CHANNELS[h.colorType];
  if (channels === undefined) return NaN;
  const bits = channels * h.depth;
  const rows = (w: number, n: number) => (w === 0 || n === 0 ? 0 : n * (1 + Math.ceil((w * bits) / 8)));
  if (!h.interlaced) return rows(h.width, h.height);
  // Adam7: starting column/row and step of each pass
  const passes = [
    [0, 0, 8, 8],
    [4, 0, 8, 8],
    [0, 4, 4, 8],
    [2, 0, 4, 4],
    [0, 2, 2, 4],
    [1, 0, 2, 2],
    [0, 1, 1, 2],
  ];
  let total = 0;
  for (const [x0, y0, dx, dy] of passes) total += rows(Math.ceil((h.width - x0) / dx), Math.ceil((h.height - y0) / dy));
  return total;
}

/**
 * Check that the image data unpacks to exactly what the header needs (no more), and return the PNG
 * without its compressed side chunks. Throws BAD_IMAGE for a broken file.
 */
export function guardPng(bytes: Uint8Array, fileName: string, head: PngHeader): Uint8Array {
  const need = pngDataBytes(head);
  if (!Number.isFinite(need)) throw bad(fileName, `unknown PNG colour type ${head.colorType}`);
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const kept: Uint8Array[] = [bytes.subarray(0, 8)];
  const slice = Math.min(MAX_SLICE_BYTES, Math.max(MIN_SLICE_BYTES, Math.floor(need / 1024)));
  let got = 0;
  let over = false;
  const inflater = new Unzlib((chunk) => {
    got += chunk.length;
    if (got > need) over = true;
  });
  let ended = false;
  for (let p = 8; p < bytes.length && !ended; ) {
    if (p + 12 > bytes.length) throw bad(fileName, 'broken PNG (truncated chunk)');
    const len = dv.getUint32(p);
    const type = String.fromCharCode(bytes[p + 4], bytes[p + 5], bytes[p + 6], bytes[p + 7]);
    const end = p + 12 + len;
    if (len > bytes.length || end > bytes.length)
      throw bad(fileName, `broken PNG (the ${type.replace(/[^\x20-\x7e]/g, '?')} chunk runs past the end of the file)`);
    if (type === 'IDAT') {
      try {
        for (let at = p + 8; at < p + 8 + len && !over; at += slice)
          inflater.push(bytes.subarray(at, Math.min(p + 8 + len, at + slice)));
      } catch (e) {
        throw bad(fileName, `cannot decode PNG (${String((e as Error)?.message ?? e).slice(0, 120)})`);
      }
      if (over)
        throw bad(
          fileName,
          `the image data unpacks to more than the ${need} bytes its ${head.width} × ${head.height} pixels need: refused`,
        );
    }
    if (type === 'IEND') ended = true;
    if (!DROPPED.has(type)) kept.push(bytes.subarray(p, end));
    p = end;
  }
  let size = 0;
  for (const k of kept) size += k.length;
  if (size === bytes.length) return bytes;
  const out = new Uint8Array(size);
  let o = 0;
  for (const k of kept) {
    out.set(k, o);
    o += k.length;
  }
  return out;
}
