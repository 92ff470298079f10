/**
 * QOI ("Quite OK Image") encoder, from the format's published specification: a 14-byte header
 * (`qoif`, width, height, 4 channels, sRGB), then chunks (index, run, small and luma differences,
 * full RGB or RGBA) and the 8-byte end marker. Prusa printers' firmware reads QOI thumbnails.
 */
import type { RgbaImage } from './types.js';

const OP_INDEX = 0x00;
const OP_DIFF = 0x40;
const OP_LUMA = 0x80;
const OP_RUN = 0xc0;
const OP_RGB = 0xfe;
const OP_RGBA = 0xff;
const MAX_RUN = 62;

export function encodeQoi(image: RgbaImage): Uint8Array {
  const { width, height, data } = image;
  const pixels = width * height;
  const out = new Uint8Array(14 + pixels * 5 + 8);
  let o = 0;
  const u32 = (v: number) => {
    out[o++] = (v >>> 24) & 255;
    out[o++] = (v >>> 16) & 255;
    out[o++] = (v >>> 8) & 255;
    out[o++] = v & 255;
  };
  out[o++] = 0x71; // q
  out[o++] = 0x6f; // o
  out[o++] = 0x69; // i
  out[o++] = 0x66; // f
  u32(width);
  u32(height);
  out[o++] = 4; // channels
  out[o++] = 0; // sRGB with linear alpha
  const seen = new Uint8Array(64 * 4);
  let pr = 0,
    pg = 0,
    pb = 0,
    pa = 255;
  let run = 0;
  for (let p = 0; p < pixels; p++) {
    const r = data[p * 4]!,
      g = data[p * 4 + 1]!,
      b = data[p * 4 + 2]!,
      a = data[p * 4 + 3]!;
    if (r === pr && g === pg && b === pb && a === pa) {
      run++;
      if (run === MAX_RUN || p === pixels - 1) {
        out[o++] = OP_RUN | (run - 1);
        run = 0;
      }
      continue;
    }
    if (run > 0) {
      out[o++] = OP_RUN | (run - 1);
      run = 0;
    }
    const h = ((r * 3 + g * 5 + b * 7 + a * 11) % 64) * 4;
    if (seen[h] === r && seen[h + 1] === g && seen[h + 2] === b && seen[h + 3] === a) {
      out[o++] = OP_INDEX | (h >> 2);
    } else {
      seen[h] = r;
      seen[h + 1] = g;
      seen[h + 2] = b;
      seen[h + 3] = a;
      if (a === pa) {
        // differences wrap around like unsigned bytes
        const dr = ((r - pr + 384) % 256) - 128;
        const dg = ((g - pg + 384) % 256) - 128;
        const db = ((b - pb + 384) % 256) - 128;
        const drg = dr - dg;
        const dbg = db - dg;
        if (dr >= -2 && dr <= 1 && dg >= -2 && dg <= 1 && db >= -2 && db <= 1) {
          out[o++] = OP_DIFF | ((dr + 2) << 4) | ((dg + 2) << 2) | (db + 2);
        } else if (dg >= -32 && dg <= 31 && drg >= -8 && drg <= 7 && dbg >= -8 && dbg <= 7) {
          out[o++] = OP_LUMA | (dg + 32);
          out[o++] = ((drg + 8) << 4) | (dbg + 8);
        } else {
          out[o++] = OP_RGB;
          out[o++] = r;
          out[o++] = g;
          out[o++] = b;
        }
      } else {
        out[o++] = OP_RGBA;
        out[o++] = r;
        out[o++] = g;
        out[o++] = b;
        out[o++] = a;
      }
    }
    pr = r;
    pg = g;
    pb = b;
    pa = a;
  }
  for (let k = 0; k < 7; k++) out[o++] = 0;
  out[o++] = 1;
  return out.slice(0, o);
}

/** Decode a QOI file (for tests and tools): the inverse of encodeQoi. Throws on a malformed file. */
export function decodeQoi(bytes: Uint8Array): RgbaImage {
  if (bytes.length < 22 || bytes[0] !== 0x71 || bytes[1] !== 0x6f || bytes[2] !== 0x69 || bytes[3] !== 0x66)
    throw new Error('not a QOI file');
  const u32 = (i: number) => ((bytes[i]! << 24) | (bytes[i + 1]! << 16) | (bytes[i + 2]! << 8) | bytes[i + 3]!) >>> 0;
  const width = u32(4);
  const height = u32(8);
  const data = new Uint8Array(width * height * 4);
  const seen = new Uint8Array(64 * 4);
  let r = 0,
    g = 0,
    b = 0,
    a = 255;
  let i = 14;
  const end = bytes.length - 8;
  for (let p = 0; p < width * height; ) {
    if (i >= end) throw new Error('QOI data ends early');
    const op = bytes[i++]!;
    let run = 1;
    if (op === OP_RGB) {
      r = bytes[i++]!;
      g = bytes[i++]!;
      b = bytes[i++]!;
    } else if (op === OP_RGBA) {
      r = bytes[i++]!;
      g = bytes[i++]!;
      b = bytes[i++]!;
      a = bytes[i++]!;
    } else if ((op & 0xc0) === OP_INDEX) {
      const h = (op & 63) * 4;
      r = seen[h]!;
      g = seen[h + 1]!;
      b = seen[h + 2]!;
      a = seen[h + 3]!;
    } else if ((op & 0xc0) === OP_DIFF) {
      r = (r + ((op >> 4) & 3) - 2) & 255;
      g = (g + ((op >> 2) & 3) - 2) & 255;
      b = (b + (op & 3) - 2) & 255;
    } else if ((op & 0xc0) === OP_LUMA) {
      const next = bytes[i++]!;
      const dg = (op & 63) - 32;
      g = (g + dg) & 255;
      r = (r + dg + (next >> 4) - 8) & 255;
      b = (b + dg + (next & 15) - 8) & 255;
    } else {
      run = (op & 63) + 1;
    }
    const h = ((r * 3 + g * 5 + b * 7 + a * 11) % 64) * 4;
    seen[h] = r;
    seen[h + 1] = g;
    seen[h + 2] = b;
    seen[h + 3] = a;
    for (let k = 0; k < run && p < width * height; k++, p++) {
      data[p * 4] = r;
      data[p * 4 + 1] = g;
      data[p * 4 + 2] = b;
      data[p * 4 + 3] = a;
    }
  }
  return { width, height, data };
}
