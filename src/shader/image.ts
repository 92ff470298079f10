/**
 * Infill images (IceSL's `cells.png`): a 24-bit PNG whose coloured shapes are the cells, tiled over
 * the plane with a pixel size in mm (IceSL's labeling_mm_per_pixel). Anti-aliased in-between
 * colours (small or thin clusters whose colour is a blend of two neighbouring colours) are merged
 * into their neighbours with a warning, instead of becoming tiny cells.
 */
import { decode } from 'fast-png';
import { StrataError } from '../errors.js';
import type { LabelFn } from './label-grid.js';
import { guardPng, pngDataBytes, readPngHeader } from './png-guard.js';

/** Largest image accepted, pixels. */
export const MAX_IMAGE_PIXELS = 16_777_216;
/** Default bound on the memory decoding an image takes (the inflateBudget setting's default), bytes. */
export const DEFAULT_IMAGE_BYTES = 512 * 1024 * 1024;

export interface CellImage {
  readonly fileName: string;
  readonly width: number;
  readonly height: number;
  /** Packed 0xRRGGBB per pixel, row 0 at the top, after anti-alias merging. */
  readonly pixels: Int32Array;
  readonly warnings: readonly string[];
  /** Pixels changed by the anti-alias merge. */
  readonly mergedPixels: number;
}

export interface ImageLoadOptions {
  fileName?: string;
  /** Most bytes decoding may take (the unpacked data and the pixels); default 512 MiB. */
  maxInflatedBytes?: number;
  /** Merge anti-aliased in-between colours (default true). */
  mergeAntialiasing?: boolean;
  /** Blend clusters up to this many pixels are merged (default 16); thin clusters of any size are. */
  maxBlendCluster?: number;
}

function badImage(fileName: string, message: string): StrataError {
  return new StrataError('BAD_IMAGE', `${fileName}: ${message}`);
}

/** Bytes decoding the image takes: its unpacked data, the decoded samples and the packed pixels. */
export function imageDecodeBytes(bytes: Uint8Array, fileName = 'cells.png'): number {
  const head = readPngHeader(bytes, fileName);
  return 2 * pngDataBytes(head) + 4 * head.width * head.height;
}

/** Decode a PNG into packed 0xRRGGBB pixels; converts grey/palette/16-bit, refuses transparency. */
export function decodeCellsPng(
  bytes: Uint8Array,
  fileName = 'cells.png',
  maxInflatedBytes = DEFAULT_IMAGE_BYTES,
): { width: number; height: number; pixels: Int32Array; warnings: string[] } {
  const head = readPngHeader(bytes, fileName);
  if (head.width === 0 || head.height === 0) throw badImage(fileName, 'the image is empty');
  if (head.width * head.height > MAX_IMAGE_PIXELS) {
    throw new StrataError(
      'LIMIT_EXCEEDED',
      `${fileName}: ${head.width} × ${head.height} pixels is more than the ${MAX_IMAGE_PIXELS} allowed`,
    );
  }
  const cost = imageDecodeBytes(bytes, fileName);
  if (cost > maxInflatedBytes) {
    throw new StrataError(
      'LIMIT_EXCEEDED',
      `${fileName}: decoding ${head.width} × ${head.height} pixels takes ${Math.ceil(cost / 1048576)} MiB, more than the ${Math.floor(maxInflatedBytes / 1048576)} MiB budget; raise inflateBudget or use a smaller image`,
    );
  }
  const clean = guardPng(bytes, fileName, head);
  let png;
  try {
    png = decode(clean);
  } catch (e) {
    throw badImage(fileName, `cannot decode PNG (${String((e as Error)?.message ?? e).slice(0, 120)})`);
  }
  const { width, height, channels, depth } = png;
  const n = width * height;
  const data = png.data;
  const pixels = new Int32Array(n);
  const warnings: string[] = [];
  const shift = depth === 16 ? 8 : 0;
  if (png.palette !== undefined) {
    if (png.transparency !== undefined && png.transparency.some((a) => a !== 255)) {
      throw badImage(fileName, 'the palette has transparency; infill images must be 24-bit RGB without alpha');
    }
    const pal = png.palette;
    const bitsPerRow = Math.ceil((width * depth) / 8);
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const bit = x * depth;
        const byte = data[y * bitsPerRow + (bit >> 3)];
        const idx = depth === 8 ? byte : (byte >> (8 - depth - (bit & 7))) & ((1 << depth) - 1);
        const c = pal[idx];
        if (c === undefined) throw badImage(fileName, 'palette index out of range');
        pixels[y * width + x] = (c[0] << 16) | (c[1] << 8) | c[2];
      }
    }
    warnings.push(`${fileName}: palette image converted to RGB`);
    return { width, height, pixels, warnings };
  }
  if (depth < 8) throw badImage(fileName, `${depth}-bit images are not supported; use a 24-bit RGB PNG`);
  if (channels === 2 || channels === 4) {
    const max = depth === 16 ? 65535 : 255;
    for (let i = 0; i < n; i++) {
      if (data[i * channels + channels - 1] !== max) {
        throw badImage(fileName, 'the image has transparent pixels; infill images must be 24-bit RGB without alpha');
      }
    }
    warnings.push(`${fileName}: opaque alpha channel ignored (IceSL expects a 24-bit RGB PNG)`);
  }
  if (channels === 3 || channels === 4) {
    for (let i = 0; i < n; i++) {
      const o = i * channels;
      pixels[i] = ((data[o] >> shift) << 16) | ((data[o + 1] >> shift) << 8) | (data[o + 2] >> shift);
    }
  } else if (channels === 1 || channels === 2) {
    for (let i = 0; i < n; i++) {
      const g = data[i * channels] >> shift;
      pixels[i] = (g << 16) | (g << 8) | g;
    }
  } else throw badImage(fileName, `unsupported PNG with ${channels} channels`);
  if (depth === 16) warnings.push(`${fileName}: 16-bit image reduced to 8 bits per channel`);
  return { width, height, pixels, warnings };
}

const rOf = (c: number) => (c >> 16) & 255;
const gOf = (c: number) => (c >> 8) & 255;
const bOf = (c: number) => c & 255;

function toLinear(v: number): number {
  const s = v / 255;
  return 255 * (s <= 0.04045 ? s / 12.92 : Math.pow((s + 0.055) / 1.055, 2.4));
}

/** Distance from c to segment ab and the segment parameter, in some RGB space. */
function segmentDistance(c: number[], a: number[], b: number[]): { d: number; t: number } {
  const ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const ac = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  if (len2 === 0) return { d: Infinity, t: 0 };
  const t = (ab[0] * ac[0] + ab[1] * ac[1] + ab[2] * ac[2]) / len2;
  const q = [ac[0] - t * ab[0], ac[1] - t * ab[1], ac[2] - t * ab[2]];
  return { d: Math.hypot(q[0], q[1], q[2]), t };
}

/** Whether colour c looks like a blend of a and b (in sRGB or in linear light). */
function isBlend(c: number, a: number, b: number): boolean {
  const srgb = (x: number) => [rOf(x), gOf(x), bOf(x)];
  const lin = (x: number) => [toLinear(rOf(x)), toLinear(gOf(x)), toLinear(bOf(x))];
  for (const f of [srgb, lin]) {
    const { d, t } = segmentDistance(f(c), f(a), f(b));
    const span = Math.sqrt((f(b)[0] - f(a)[0]) ** 2 + (f(b)[1] - f(a)[1]) ** 2 + (f(b)[2] - f(a)[2]) ** 2);
    if (t > 0.02 && t < 0.98 && d <= Math.max(6, 0.08 * span)) return true;
  }
  return false;
}

/**
 * Merge anti-aliased in-between colours into neighbouring cells. Returns the new pixels and how
 * many pixels and colours were merged. Neighbourhoods wrap around (the image tiles).
 */
export function mergeAntialiased(
  width: number,
  height: number,
  src: Int32Array,
  maxCluster = 16,
): { pixels: Int32Array; mergedPixels: number; mergedColors: number } {
  const n = width * height;
  const comp = new Int32Array(n).fill(-1);
  const compColor: number[] = [];
  const compSize: number[] = [];
  const compInterior: number[] = [];
  const left = (i: number) => (i % width === 0 ? i + width - 1 : i - 1);
  const right = (i: number) => (i % width === width - 1 ? i - width + 1 : i + 1);
  const up = (i: number) => (i < width ? i + n - width : i - width);
  const down = (i: number) => (i >= n - width ? i - n + width : i + width);
  const nbrs = (i: number, out: number[]) => {
    out[0] = left(i);
    out[1] = right(i);
    out[2] = up(i);
    out[3] = down(i);
  };
  const nb = [0, 0, 0, 0];
  const stack: number[] = [];
  for (let s = 0; s < n; s++) {
    if (comp[s] >= 0) continue;
    const id = compColor.length;
    const color = src[s];
    compColor.push(color);
    let size = 0;
    let interior = 0;
    comp[s] = id;
    stack.push(s);
    while (stack.length > 0) {
      const i = stack.pop() as number;
      size++;
      nbrs(i, nb);
      let same = 0;
      for (const j of nb) {
        if (src[j] !== color) continue;
        same++;
        if (comp[j] < 0) {
          comp[j] = id;
          stack.push(j);
        }
      }
      if (same === 4) interior++;
    }
    compSize.push(size);
    compInterior.push(interior);
  }
  const ncomp = compColor.length;
  if (ncomp <= 1) return { pixels: src.slice(), mergedPixels: 0, mergedColors: 0 };
  // Colours adjacent to each small or thin component.
  const candidates: boolean[] = compSize.map((s, c) => s <= maxCluster || compInterior[c] === 0);
  const neighbourColors = new Map<number, Set<number>>();
  for (let i = 0; i < n; i++) {
    const c = comp[i];
    if (!candidates[c]) continue;
    nbrs(i, nb);
    for (const j of nb) {
      if (comp[j] === c) continue;
      let set = neighbourColors.get(c);
      if (set === undefined) neighbourColors.set(c, (set = new Set()));
      if (set.size < 24) set.add(src[j]);
    }
  }
  const merged = new Uint8Array(ncomp);
  const mergedColorSet = new Set<number>();
  for (const [c, set] of neighbourColors) {
    const cols = [...set].filter((x) => x !== compColor[c]);
    let blend = false;
    for (let a = 0; a < cols.length && !blend; a++)
      for (let b = a + 1; b < cols.length && !blend; b++) blend = isBlend(compColor[c], cols[a], cols[b]);
    if (blend) {
      merged[c] = 1;
      mergedColorSet.add(compColor[c]);
    }
  }
  const out = src.slice();
  const free = new Uint8Array(n);
  let freeCount = 0;
  for (let i = 0; i < n; i++) {
    if (merged[comp[i]]) {
      free[i] = 1;
      freeCount++;
    }
  }
  if (freeCount === 0 || freeCount === n) return { pixels: out, mergedPixels: 0, mergedColors: 0 };
  const mergedPixels = freeCount;
  // Grow the kept cells into the freed pixels, one ring at a time; each pixel takes the
  // neighbouring colour closest to its own.
  let frontier: number[] = [];
  for (let i = 0; i < n; i++) {
    if (!free[i]) continue;
    nbrs(i, nb);
    if (nb.some((j) => !free[j])) frontier.push(i);
  }
  while (frontier.length > 0 && freeCount > 0) {
    const assign: [number, number][] = [];
    for (const i of frontier) {
      if (!free[i]) continue;
      nbrs(i, nb);
      let best = -1;
      let bestD = Infinity;
      for (const j of nb) {
        if (free[j]) continue;
        const c = out[j];
        const d = (rOf(c) - rOf(src[i])) ** 2 + (gOf(c) - gOf(src[i])) ** 2 + (bOf(c) - bOf(src[i])) ** 2;
        if (d < bestD) {
          bestD = d;
          best = c;
        }
      }
      if (best >= 0) assign.push([i, best]);
    }
    const next: number[] = [];
    for (const [i, c] of assign) {
      if (!free[i]) continue;
      out[i] = c;
      free[i] = 0;
      freeCount--;
    }
    for (const [i] of assign) {
      nbrs(i, nb);
      for (const j of nb) if (free[j]) next.push(j);
    }
    frontier = next;
  }
  return { pixels: out, mergedPixels, mergedColors: mergedColorSet.size };
}

/** Decode and clean up an infill image. */
export function loadCellImage(bytes: Uint8Array, opts: ImageLoadOptions = {}): CellImage {
  const fileName = opts.fileName ?? 'cells.png';
  const dec = decodeCellsPng(bytes, fileName, opts.maxInflatedBytes);
  const warnings = dec.warnings.slice();
  let pixels = dec.pixels;
  let mergedPixels = 0;
  if (opts.mergeAntialiasing ?? true) {
    const m = mergeAntialiased(dec.width, dec.height, dec.pixels, opts.maxBlendCluster ?? 16);
    pixels = m.pixels;
    mergedPixels = m.mergedPixels;
    if (m.mergedPixels > 0) {
      warnings.push(
        `${fileName}: merged ${m.mergedPixels} anti-aliased pixel(s) in ${m.mergedColors} in-between colour(s) into neighbouring cells; draw infill images without anti-aliasing`,
      );
    }
  }
  return { fileName, width: dec.width, height: dec.height, pixels, warnings, mergedPixels };
}

/** The image tiled over the plane as a label field: pixel (col, row) covers x ∈ [col·s, (col+1)·s), row 0 at the top. */
export function imageLabelFn(img: CellImage, pixelSize: number): LabelFn {
  if (!(pixelSize > 0) || !Number.isFinite(pixelSize))
    throw new StrataError('BAD_SETTING', `${img.fileName}: pixel size must be a positive number of mm`);
  const w = img.width;
  const h = img.height;
  const px = img.pixels;
  const inv = 1 / pixelSize;
  return (x: number, y: number): number => {
    let c = Math.floor(x * inv) % w;
    if (c < 0) c += w;
    let r = Math.floor(y * inv) % h;
    if (r < 0) r += h;
    return px[(h - 1 - r) * w + c];
  };
}
