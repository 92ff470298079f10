/**
 * Each printed layer's extrusions as one bitmap of flag bits on a grid that covers the model (plus a margin), for
 * the support checks: which cells hold part material, support, support interface or raft, and which lie within
 * reach (the threshold angle's allowance) of any of them. Rasters are made on demand and kept while the layers
 * above still need them.
 */
import { isPartFeature, isSupportFeature, Feature } from './feature-names.js';
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
  /** Within `reachMm` of Any. */
  Reach: 32,
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
  /** Radius by which the Reach bit grows material (mm). */
  reachMm: number;
  /** Layer heights of the part and the support material of a layer (see layer-analysis.ts). */
  partHeight: (frame: LayerFrame) => number;
  supportHeight: (frame: LayerFrame) => number;
}

export class LayerRasters {
  private readonly cache = new Map<number, Uint8Array>();

  constructor(
    private readonly layers: readonly GcodeLayer[],
    private readonly frames: readonly LayerFrame[],
    readonly grid: Grid,
    private readonly o: RasterOptions,
  ) {}

  get(l: number): Uint8Array {
    let r = this.cache.get(l);
    if (!r) {
      r = this.rasterize(l);
      this.cache.set(l, r);
    }
    return r;
  }

  /** Forgets the rasters of layers below index l. */
  releaseBelow(l: number): void {
    for (const k of this.cache.keys()) if (k < l) this.cache.delete(k);
  }

  private rasterize(l: number): Uint8Array {
    const t = this.layers[l]!.extrusions;
    const frame = this.frames[l]!;
    const bitmap = newBitmap(this.grid);
    const o = this.o;
    const hPart = o.partHeight(frame);
    const hSupport = o.supportHeight(frame);
    for (let pass = 0; pass < 2; pass++) {
      for (let i = 0; i < t.count; i++) {
        const kind = materialOf(t.feature[i]!, frame);
        if (kind === Material.Other) continue;
        const len = segmentLength(t, i);
        const h = kind === Material.Part ? hPart : hSupport;
        const raw = o.widthSource === 'nominal' ? o.lineWidth : beadWidth(t.e[i]!, len, h, o.filamentArea);
        const w = Math.min(MAX_BEAD_LINE_WIDTHS * o.lineWidth, Math.max(MIN_BEAD_MM, raw));
        const [r, bits] = pass === 0 ? [w / 2 + o.reachMm, Cell.Reach] : [w / 2, Cell.Any | BITS[kind]!];
        stampCapsule(bitmap, this.grid, t.x0[i]!, t.y0[i]!, t.x1[i]!, t.y1[i]!, r, bits, true);
      }
    }
    return bitmap;
  }
}

/** Whether a layer holds support or interface (not raft) extrusion. */
export function hasSupportMaterial(layer: GcodeLayer, frame: LayerFrame): boolean {
  const t = layer.extrusions;
  for (let i = 0; i < t.count; i++) {
    if (isSupportFeature(t.feature[i]!) && !isRaftMaterial(t.feature[i]!, frame)) return true;
  }
  return false;
}
