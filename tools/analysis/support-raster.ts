/**
 * Each printed layer's extrusions as one bitmap of flag bits on a grid that covers the model (plus a margin), for
 * the support checks: which cells hold part material, support, support interface or raft. Rasters are made on
 * demand and kept while the layers above still need them.
 */
import { Feature, isPartFeature } from './feature-names.js';
import type { GcodeLayer } from './gcode-types.js';
import type { Grid } from './grid.js';
import { newBitmap } from './grid.js';
import type { LayerFrame } from './model-z.js';
import { isRaftMaterial } from './model-z.js';
import { beadWidth, segmentLength, stampCapsule } from './raster.js';

/** Flag bits of a layer raster's cells. */
export const Cell = {
  /** Any material that can hold what is printed above it: part, support, interface, raft. */
  Any: 1,
  Part: 2,
  Support: 4,
  Interface: 8,
  Raft: 16,
} as const;

/** Kinds of extruded material, by how the support checks treat them. */
export const Material = { Part: 0, Support: 1, Interface: 2, Raft: 3, Other: 4 } as const;

/** The kind of a segment of feature `code` on a layer with frame `frame`. */
export function materialOf(code: number, frame: LayerFrame): number {
  if (isRaftMaterial(code, frame)) return Material.Raft;
  if (isPartFeature(code)) return Material.Part;
  if (code === Feature.Support) return Material.Support;
  if (code === Feature.SupportInterface) return Material.Interface;
  return Material.Other;
}

const BITS = [Cell.Part, Cell.Support, Cell.Interface, Cell.Raft, 0];

/** Bead widths are clamped to [MIN_BEAD_MM, MAX_BEAD_LINE_WIDTHS × lineWidth] (raft base lines are wide). */
const MIN_BEAD_MM = 0.05;
const MAX_BEAD_LINE_WIDTHS = 4;

export interface RasterOptions {
  lineWidth: number;
  filamentArea: number;
  widthSource: 'flow' | 'nominal';
  /** Layer heights of the part and the support material of a layer (see layer-analysis.ts). */
  partHeight: (frame: LayerFrame) => number;
  supportHeight: (frame: LayerFrame) => number;
}

/** A layer's raster with its cell counts and the lattice bounds [i0, j0, i1, j1) of its part and support cells. */
export interface LayerRaster {
  bits: Uint8Array;
  partCells: number;
  supportCells: number;
  partBounds: [number, number, number, number] | null;
  supportBounds: [number, number, number, number] | null;
}

export class LayerRasters {
  private readonly cache = new Map<number, LayerRaster>();
  /** Bitmaps of released layers, reused. */
  private readonly spare: Uint8Array[] = [];

  constructor(
    private readonly layers: readonly GcodeLayer[],
    private readonly frames: readonly LayerFrame[],
    readonly grid: Grid,
    private readonly o: RasterOptions,
  ) {}

  get(l: number): LayerRaster {
    let r = this.cache.get(l);
    if (!r) {
      r = this.rasterize(l);
      this.cache.set(l, r);
    }
    return r;
  }

  /** Forgets the rasters of layers below index l. */
  releaseBelow(l: number): void {
    for (const [k, r] of this.cache) {
      if (k >= l) continue;
      this.cache.delete(k);
      this.spare.push(r.bits);
    }
  }

  private rasterize(l: number): LayerRaster {
    const t = this.layers[l]!.extrusions;
    const frame = this.frames[l]!;
    const spare = this.spare.pop();
    const bitmap = spare ? spare.fill(0) : newBitmap(this.grid);
    const o = this.o;
    const hPart = o.partHeight(frame);
    const hSupport = o.supportHeight(frame);
    // Part material first, which may simply set its cells; the other kinds then add their bits.
    const kinds = new Uint8Array(t.count);
    let others = 0;
    for (let i = 0; i < t.count; i++) {
      kinds[i] = materialOf(t.feature[i]!, frame);
      if (kinds[i] !== Material.Part && kinds[i] !== Material.Other) others++;
    }
    for (let pass = 0; pass < (others > 0 ? 2 : 1); pass++) {
      for (let i = 0; i < t.count; i++) {
        const kind = kinds[i]!;
        if (kind === Material.Other || (kind === Material.Part) !== (pass === 0)) continue;
        const len = segmentLength(t, i);
        const h = kind === Material.Part ? hPart : hSupport;
        const raw = o.widthSource === 'nominal' ? o.lineWidth : beadWidth(t.e[i]!, len, h, o.filamentArea);
        const w = Math.min(MAX_BEAD_LINE_WIDTHS * o.lineWidth, Math.max(MIN_BEAD_MM, raw));
        const bits = Cell.Any | BITS[kind]!;
        stampCapsule(bitmap, this.grid, t.x0[i]!, t.y0[i]!, t.x1[i]!, t.y1[i]!, w / 2, bits, pass === 1);
      }
    }
    return this.withCounts(bitmap);
  }

  /** Counts part and support cells four at a time, and their bounds (rows and words that hold any). */
  private withCounts(bits: Uint8Array): LayerRaster {
    const { cols, rows, i0, j0 } = this.grid;
    const words = new Uint32Array(bits.buffer, bits.byteOffset, bits.length >>> 2);
    const part = new Bounds();
    const support = new Bounds();
    let partCells = 0;
    let supportCells = 0;
    const wordsPerRow = cols >>> 2;
    for (let j = 0; j < rows; j++) {
      const first = j * wordsPerRow;
      for (let w = first; w < first + wordsPerRow; w++) {
        const v = words[w]!;
        if ((v & ANY_BYTES) === 0) continue;
        const p = (v >>> PART_SHIFT) & LOW_BYTES;
        const s = ((v >>> SUPPORT_SHIFT) | (v >>> INTERFACE_SHIFT)) & LOW_BYTES;
        const i = 4 * (w - first) + i0;
        if (p !== 0) {
          partCells += Math.imul(p, LOW_BYTES) >>> 24;
          part.add(i, j + j0, 4);
        }
        if (s !== 0) {
          supportCells += Math.imul(s, LOW_BYTES) >>> 24;
          support.add(i, j + j0, 4);
        }
      }
    }
    return { bits, partCells, supportCells, partBounds: part.get(), supportBounds: support.get() };
  }
}

/** 1 in every byte of a word, and the Any bit in every byte. */
const LOW_BYTES = 0x01010101;
const ANY_BYTES = Cell.Any * LOW_BYTES;
/** Bit positions of the flags. */
const PART_SHIFT = 1;
const SUPPORT_SHIFT = 2;
const INTERFACE_SHIFT = 3;

class Bounds {
  private i0 = Infinity;
  private j0 = Infinity;
  private i1 = -Infinity;
  private j1 = -Infinity;
  /** Adds cells i .. i + width - 1 of row j. */
  add(i: number, j: number, width: number): void {
    if (i < this.i0) this.i0 = i;
    if (i + width > this.i1) this.i1 = i + width;
    if (j < this.j0) this.j0 = j;
    if (j >= this.j1) this.j1 = j + 1;
  }
  get(): [number, number, number, number] | null {
    return this.i1 > this.i0 ? [this.i0, this.j0, this.i1, this.j1] : null;
  }
}
