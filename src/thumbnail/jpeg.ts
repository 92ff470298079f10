/**
 * A baseline JPEG (JFIF) encoder, written from the standard (ITU-T T.81): YCbCr without subsampling,
 * 8×8 forward DCT, the standard's example quantisation tables scaled by quality the way the IJG library
 * does, and Huffman tables built for the image itself (the standard's Annex K.2 procedure: code lengths
 * from symbol counts, limited to 16 bits), so no fixed code tables are needed. Alpha is ignored: callers
 * composite onto a background first.
 */
import type { RgbaImage } from './types.js';

/** Example quantisation tables of the standard (Annex K.1), row by row. */
const LUMA_Q = [
  16, 11, 10, 16, 24, 40, 51, 61, 12, 12, 14, 19, 26, 58, 60, 55, 14, 13, 16, 24, 40, 57, 69, 56, 14, 17, 22, 29, 51, 87, 80, 62,
  18, 22, 37, 56, 68, 109, 103, 77, 24, 35, 55, 64, 81, 104, 113, 92, 49, 64, 78, 87, 103, 121, 120, 101, 72, 92, 95, 98, 112, 100, 103, 99,
];
const CHROMA_Q = [
  17, 18, 24, 47, 99, 99, 99, 99, 18, 21, 26, 66, 99, 99, 99, 99, 24, 26, 56, 99, 99, 99, 99, 99, 47, 66, 99, 99, 99, 99, 99, 99,
  ...new Array<number>(32).fill(99),
];

/** Zig-zag order: ZIGZAG[k] is the row-major index of the k-th coefficient. */
const ZIGZAG: readonly number[] = (() => {
  const order: number[] = [];
  for (let s = 0; s < 15; s++) {
    const cells: number[] = [];
    for (let row = 0; row < 8; row++) {
      const col = s - row;
      if (col >= 0 && col < 8) cells.push(row * 8 + col);
    }
    // even diagonals run up-right (row decreasing), odd ones down-left
    if (s % 2 === 0) cells.reverse();
    order.push(...cells);
  }
  return order;
})();

/** cos((2x+1)uπ/16) · C(u)/2, for the separable DCT. */
const DCT: Float64Array = (() => {
  const t = new Float64Array(64);
  for (let u = 0; u < 8; u++) {
    for (let x = 0; x < 8; x++) t[u * 8 + x] = (u === 0 ? Math.SQRT1_2 : 1) * 0.5 * Math.cos(((2 * x + 1) * u * Math.PI) / 16);
  }
  return t;
})();

function scaledTable(base: readonly number[], quality: number): Uint8Array {
  const q = Math.min(100, Math.max(1, Math.round(quality)));
  const scale = q < 50 ? 5000 / q : 200 - 2 * q;
  const out = new Uint8Array(64);
  for (let i = 0; i < 64; i++) out[i] = Math.min(255, Math.max(1, Math.floor((base[i]! * scale + 50) / 100)));
  return out;
}

/** Quantised coefficients of one 8×8 block of samples (row-major), in zig-zag order. */
function transformBlock(block: Float64Array, quant: Uint8Array, tmp: Float64Array, out: Int16Array, offset: number): void {
  // rows
  for (let y = 0; y < 8; y++) {
    for (let u = 0; u < 8; u++) {
      let sum = 0;
      for (let x = 0; x < 8; x++) sum += DCT[u * 8 + x]! * block[y * 8 + x]!;
      tmp[y * 8 + u] = sum;
    }
  }
  // columns, then quantise in zig-zag order
  for (let k = 0; k < 64; k++) {
    const idx = ZIGZAG[k]!;
    const v = idx >> 3;
    const u = idx & 7;
    let sum = 0;
    for (let y = 0; y < 8; y++) sum += DCT[v * 8 + y]! * tmp[y * 8 + u]!;
    out[offset + k] = Math.round(sum / quant[idx]!);
  }
}

/** Bits needed for |v| (the JPEG magnitude category). */
function category(v: number): number {
  let a = v < 0 ? -v : v;
  let n = 0;
  while (a > 0) {
    n++;
    a >>= 1;
  }
  return n;
}

interface HuffmanTable {
  /** Codes per length 1..16. */
  counts: Uint8Array;
  /** Symbols in code order. */
  symbols: number[];
  code: Uint16Array;
  size: Uint8Array;
}

/** Build a Huffman table from symbol counts (Annex K.2 with the 16-bit limit of K.3). */
function buildTable(freq: Float64Array): HuffmanTable {
  const f = new Float64Array(257);
  f.set(freq.subarray(0, 256));
  f[256] = 1; // reserved, so that no code is all ones
  const codesize = new Int32Array(257);
  const others = new Int32Array(257).fill(-1);
  for (;;) {
    let v1 = -1, v2 = -1;
    for (let i = 0; i < 257; i++) {
      if (f[i]! <= 0) continue;
      if (v1 < 0 || f[i]! <= f[v1]!) v1 = i;
    }
    for (let i = 0; i < 257; i++) {
      if (f[i]! <= 0 || i === v1) continue;
      if (v2 < 0 || f[i]! <= f[v2]!) v2 = i;
    }
    if (v2 < 0) break;
    f[v1] = f[v1]! + f[v2]!;
    f[v2] = 0;
    codesize[v1]++;
    while (others[v1]! >= 0) {
      v1 = others[v1]!;
      codesize[v1]++;
    }
    others[v1] = v2;
    codesize[v2]++;
    while (others[v2]! >= 0) {
      v2 = others[v2]!;
      codesize[v2]++;
    }
  }
  const bits = new Int32Array(33);
  for (let i = 0; i < 257; i++) if (codesize[i]! > 0) bits[codesize[i]!]++;
  for (let i = 32; i > 16; i--) {
    while (bits[i]! > 0) {
      let j = i - 2;
      while (bits[j] === 0) j--;
      bits[i] -= 2;
      bits[i - 1]++;
      bits[j + 1] += 2;
      bits[j]--;
    }
  }
  let top = 16;
  while (bits[top] === 0) top--;
  bits[top]--; // drop the reserved symbol's code
  const symbols: number[] = [];
  for (let len = 1; len <= 32; len++) for (let s = 0; s < 256; s++) if (codesize[s] === len) symbols.push(s);
  const counts = new Uint8Array(16);
  for (let len = 1; len <= 16; len++) counts[len - 1] = bits[len]!;
  // canonical codes
  const code = new Uint16Array(256);
  const size = new Uint8Array(256);
  let next = 0;
  let k = 0;
  for (let len = 1; len <= 16; len++) {
    for (let n = 0; n < counts[len - 1]!; n++) {
      const s = symbols[k++]!;
      code[s] = next++;
      size[s] = len;
    }
    next <<= 1;
  }
  return { counts, symbols: symbols.slice(0, k), code, size };
}

class BitWriter {
  private bytes: number[] = [];
  private acc = 0;
  private n = 0;
  put(value: number, bits: number): void {
    for (let b = bits - 1; b >= 0; b--) {
      this.acc = (this.acc << 1) | ((value >> b) & 1);
      this.n++;
      if (this.n === 8) this.flushByte();
    }
  }
  private flushByte(): void {
    this.bytes.push(this.acc);
    if (this.acc === 0xff) this.bytes.push(0);
    this.acc = 0;
    this.n = 0;
  }
  finish(): number[] {
    while (this.n !== 0) {
      this.acc = (this.acc << 1) | 1;
      this.n++;
      if (this.n === 8) this.flushByte();
    }
    return this.bytes;
  }
}

/** Encode an image as a baseline JPEG of the given quality (1..100). */
export function encodeJpeg(image: RgbaImage, quality = 90): Uint8Array {
  const { width, height, data } = image;
  const qLuma = scaledTable(LUMA_Q, quality);
  const qChroma = scaledTable(CHROMA_Q, quality);
  const bw = Math.ceil(width / 8);
  const bh = Math.ceil(height / 8);
  const blocks = bw * bh;
  const coef = new Int16Array(blocks * 3 * 64);
  const block = new Float64Array(64);
  const tmp = new Float64Array(64);
  for (let by = 0; by < bh; by++) {
    for (let bx = 0; bx < bw; bx++) {
      const b = by * bw + bx;
      for (let comp = 0; comp < 3; comp++) {
        for (let y = 0; y < 8; y++) {
          const py = Math.min(height - 1, by * 8 + y);
          for (let x = 0; x < 8; x++) {
            const px = Math.min(width - 1, bx * 8 + x);
            const o = (py * width + px) * 4;
            const r = data[o]!, g = data[o + 1]!, bl = data[o + 2]!;
            const v =
              comp === 0
                ? 0.299 * r + 0.587 * g + 0.114 * bl
                : comp === 1
                  ? -0.168736 * r - 0.331264 * g + 0.5 * bl + 128
                  : 0.5 * r - 0.418688 * g - 0.081312 * bl + 128;
            block[y * 8 + x] = v - 128;
          }
        }
        transformBlock(block, comp === 0 ? qLuma : qChroma, tmp, coef, (b * 3 + comp) * 64);
      }
    }
  }
  // symbol statistics: [luma DC, luma AC, chroma DC, chroma AC]
  const freq = [0, 1, 2, 3].map(() => new Float64Array(256));
  const walk = (emit: (table: number, symbol: number, extra: number, extraBits: number) => void) => {
    const pred = [0, 0, 0];
    for (let b = 0; b < blocks; b++) {
      for (let comp = 0; comp < 3; comp++) {
        const base = (b * 3 + comp) * 64;
        const t = comp === 0 ? 0 : 2;
        const dc = coef[base]!;
        const diff = dc - pred[comp]!;
        pred[comp] = dc;
        const s = category(diff);
        emit(t, s, diff < 0 ? diff + (1 << s) - 1 : diff, s);
        let run = 0;
        for (let k = 1; k < 64; k++) {
          const v = coef[base + k]!;
          if (v === 0) {
            run++;
            continue;
          }
          while (run > 15) {
            emit(t + 1, 0xf0, 0, 0);
            run -= 16;
          }
          const sz = category(v);
          emit(t + 1, (run << 4) | sz, v < 0 ? v + (1 << sz) - 1 : v, sz);
          run = 0;
        }
        if (run > 0) emit(t + 1, 0x00, 0, 0);
      }
    }
  };
  walk((t, symbol) => freq[t]![symbol]++);
  const tables = freq.map(buildTable);
  const bits = new BitWriter();
  walk((t, symbol, extra, extraBits) => {
    const table = tables[t]!;
    bits.put(table.code[symbol]!, table.size[symbol]!);
    if (extraBits > 0) bits.put(extra, extraBits);
  });
  const scan = bits.finish();

  const out: number[] = [];
  const u16 = (v: number) => out.push((v >> 8) & 255, v & 255);
  out.push(0xff, 0xd8); // SOI
  out.push(0xff, 0xe0); // APP0 JFIF 1.01, no density units
  u16(16);
  out.push(0x4a, 0x46, 0x49, 0x46, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0);
  out.push(0xff, 0xdb); // DQT, both tables in zig-zag order
  u16(2 + 2 * 65);
  out.push(0);
  for (let k = 0; k < 64; k++) out.push(qLuma[ZIGZAG[k]!]!);
  out.push(1);
  for (let k = 0; k < 64; k++) out.push(qChroma[ZIGZAG[k]!]!);
  out.push(0xff, 0xc0); // SOF0
  u16(17);
  out.push(8);
  u16(height);
  u16(width);
  out.push(3, 1, 0x11, 0, 2, 0x11, 1, 3, 0x11, 1);
  const classes = [0x00, 0x10, 0x01, 0x11];
  for (let t = 0; t < 4; t++) {
    const table = tables[t]!;
    out.push(0xff, 0xc4); // DHT
    u16(2 + 1 + 16 + table.symbols.length);
    out.push(classes[t]!, ...table.counts, ...table.symbols);
  }
  out.push(0xff, 0xda); // SOS
  u16(12);
  out.push(3, 1, 0x00, 2, 0x11, 3, 0x11, 0, 63, 0);
  for (const b of scan) out.push(b);
  out.push(0xff, 0xd9); // EOI
  return Uint8Array.from(out);
}
