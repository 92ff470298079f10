/**
 * Support checks of one print against its model, layer by layer, on rasters of every layer's material (see
 * support-raster.ts). The material of the layers just below a layer (down to the allowed Z gap), closed over gaps
 * up to supportSpanMm (sparse support lines and tree tips hold the area between them; a wall grows nothing
 * outward), is what holds the layer:
 * - overhang: the layer's section minus the section of the model layer below grown by layerHeight·tan(threshold),
 *   strips narrower than half a line width and specks left out; supported where that closed material lies under
 *   it (half a raster cell of slack);
 * - over nothing: the layer's part extrusion farther than layerHeight·tan(threshold) from the closed material,
 *   and outside the interior of the model layer below (sparse infill under skin is the part's own design, judged
 *   by the infill check);
 * - inside: support and interface beads deeper than half a line width inside the model's section at their layer;
 * - Z gaps: from the top of support to the overhang above it, and from the model to support standing on it.
 * The first model layer rests on the bed (or on the raft, which then must lie under it).
 */
import type { GcodeLayer } from './gcode-types.js';
import type { Grid } from './grid.js';
import { columnsOf, gridAround, newBitmap } from './grid.js';
import type { LayerFrame, ModelZ } from './model-z.js';
import { dilate, dropSmallComponents, erode, grownClosings, squaredDistance } from './morphology.js';
import type { GapStats, LayerSupport, SupportSummary } from './report-types.js';
import type { SectionCache } from './section-cache.js';
import { sectionSpans } from './section.js';
import type { Spans } from './spans.js';
import {
  dilateSpans, emptySpans, erodeSpans, isEmptySpans, spansBoolean, spansBounds, spansToBitmap,
} from './spans.js';
import { WeightedHistogram } from './stats.js';
import type { LayerRaster } from './support-raster.js';
import { Cell, LayerRasters } from './support-raster.js';

/**
 * Overhang strips narrower than this (line widths) are left out: along a wall a little steeper than the threshold
 * the overhang is a strip of a raster cell or two whose measure is raster noise.
 */
export const OVERHANG_MIN_WIDTH_LINE_WIDTHS = 0.5;
/** Support beads deeper than this inside the section count as inside the part (line widths). */
export const INSIDE_TOLERANCE_LINE_WIDTHS = 0.5;
/** Z gaps are looked for this many layer heights below the layer (mm of gap beyond are not measured). */
export const GAP_SCAN_LAYERS = 6;
/** The low end of a gap distribution: the gap below which this share of the measured area lies. */
export const GAP_LOW_QUANTILE = 0.02;
/** Resolution of gap statistics (mm). */
const GAP_BIN_MM = 0.001;
/** Support rasters use cells of at least this many line widths (mm per line width). */
export const SUPPORT_CELL_LINE_WIDTHS = 0.25;
/** Over-nothing candidates search discs around each cell while that reads fewer cells than this many windows. */
const DISC_SEARCH_LIMIT = 4;
/** Layers listed as worst. */
const WORST_LISTED = 5;
/** Distances between cell centres compared with the threshold's allowance carry this slack (mm). */
const REACH_SLACK_MM = 1e-3;
/** Z comparisons between layers allow this much (mm). */
const Z_SLACK_MM = 1e-4;

export interface SupportOptions {
  layerHeight: number;
  lineWidth: number;
  wallThickness: number;
  overhangAngleDeg: number;
  supportGapLayers: number;
  supportSpanMm: number;
  overhangMinAreaMm2: number;
  /** Cell of the analyser's rasters (mm); the support rasters use it or a coarser one. */
  cell: number;
  filamentArea: number;
  widthSource: 'flow' | 'nominal';
  /** Layer heights of a layer's part and support material (mm). */
  partHeight: (frame: LayerFrame) => number;
  supportHeight: (frame: LayerFrame) => number;
}

interface WorstOverhang {
  layer: number;
  z: number;
  areaMm2: number;
  unsupportedMm2: number;
}
interface WorstNothing {
  layer: number;
  z: number;
  areaMm2: number;
  fraction: number;
}

export class SupportAnalysis {
  readonly cell: number;
  private readonly grid: Grid;
  private readonly rasters: LayerRasters;
  /** The threshold angle's allowance: how far a layer may reach past the one below (mm). */
  private readonly reachMm: number;
  private readonly spansByZ = new Map<number, Spans>();
  private overhangArea = 0;
  private overhangSupported = 0;
  private partArea = 0;
  private overNothingArea = 0;
  private insideArea = 0;
  private insideWorst: number | null = null;
  private insideWorstArea = 0;
  private supportArea = 0;
  private supportLayers = 0;
  private readonly worstOverhang: WorstOverhang[] = [];
  private readonly worstNothing: WorstNothing[] = [];
  private readonly topGaps: WeightedHistogram;
  private readonly bottomGaps: WeightedHistogram;
  private readonly topByLayers: Float64Array;
  private readonly bottomByLayers: Float64Array;

  constructor(
    private readonly layers: readonly GcodeLayer[],
    private readonly z: ModelZ,
    private readonly sections: SectionCache,
    bounds: [number, number, number, number],
    private readonly o: SupportOptions,
  ) {
    this.cell = Math.max(o.cell, SUPPORT_CELL_LINE_WIDTHS * o.lineWidth);
    // Raster edges sit within half a cell of the true edges: the allowance is measured between cell centres.
    this.reachMm = o.layerHeight * Math.tan((o.overhangAngleDeg * Math.PI) / 180) + this.cell / 2 + REACH_SLACK_MM;
    const margin = o.supportSpanMm + 2 * o.lineWidth + this.reachMm;
    this.grid = gridAround(bounds[0], bounds[1], bounds[2], bounds[3], this.cell, margin);
    this.rasters = new LayerRasters(layers, z.frames, this.grid, {
      lineWidth: o.lineWidth,
      filamentArea: o.filamentArea,
      widthSource: o.widthSource,
      partHeight: o.partHeight,
      supportHeight: o.supportHeight,
    });
    const maxGap = (GAP_SCAN_LAYERS + 1) * o.layerHeight;
    this.topGaps = new WeightedHistogram(maxGap, GAP_BIN_MM);
    this.bottomGaps = new WeightedHistogram(maxGap, GAP_BIN_MM);
    this.topByLayers = new Float64Array(GAP_SCAN_LAYERS + 2);
    this.bottomByLayers = new Float64Array(GAP_SCAN_LAYERS + 2);
  }

  /**
   * Measures layer l; `sectionZ` is the model height its part material is judged at (see layer-analysis.ts).
   * Layers are measured bottom to top.
   */
  measure(l: number, sectionZ: number): LayerSupport | null {
    const frame = this.z.frames[l]!;
    if (frame.raft) return null;
    const o = this.o;
    const c2 = this.cell * this.cell;
    const layer = this.layers[l]!;
    const here = this.rasters.get(l);
    const out: LayerSupport = {
      overhangAreaMm2: 0, overhangSupportedMm2: 0, partAreaMm2: 0, overNothingMm2: 0, supportAreaMm2: 0, insideMm2: 0,
    };

    if (here.supportCells > 0) {
      this.supportLayers++;
      const zs = frame.hasPart ? sectionZ : round6(frame.modelZ - o.supportHeight(frame) / 2);
      const inner = erodeSpans(this.spansAt(zs), INSIDE_TOLERANCE_LINE_WIDTHS * o.lineWidth);
      out.supportAreaMm2 = here.supportCells * c2;
      out.insideMm2 = countMaskedInSpans(inner, this.grid, here.bits, Cell.Support | Cell.Interface) * c2;
      this.supportArea += out.supportAreaMm2;
      this.insideArea += out.insideMm2;
      if (out.insideMm2 > this.insideWorstArea) {
        this.insideWorstArea = out.insideMm2;
        this.insideWorst = l;
      }
      this.measureBottomGap(l, frame);
    }
    if (!frame.hasPart) {
      this.release(l);
      return out;
    }

    out.partAreaMm2 = here.partCells * c2;
    this.partArea += out.partAreaMm2;
    const first = l === this.z.firstModelLayer;
    if (first && this.z.raftLayerCount === 0) {
      this.release(l);
      return out;
    }

    const zBottom = layer.z - o.partHeight(frame);
    const below: number[] = [];
    for (let k = l - 1; k >= 0 && this.layers[k]!.z >= zBottom - o.supportGapLayers * o.layerHeight - Z_SLACK_MM; k--) {
      below.push(k);
    }
    const section = this.spansAt(sectionZ);
    const zPrev = round6(sectionZ - o.layerHeight);
    const previous = zPrev > this.sections.zMin ? this.spansAt(zPrev) : emptySpans(this.cell);

    // The model's overhang on this layer (none on the first model layer: it rests on the bed or the raft).
    let overhang: { win: Grid; bitmap: Uint8Array } | null = null;
    if (!first) {
      const grown = dilateSpans(previous, o.layerHeight * Math.tan((o.overhangAngleDeg * Math.PI) / 180));
      const region = spansBoolean(section, grown, 'subtract');
      const b = spansBounds(region);
      if (b) {
        const win = this.window(b, 2 * this.cell);
        const raw = newBitmap(win);
        spansToBitmap(region, win, raw);
        // Strips narrower than OVERHANG_MIN_WIDTH (an opening) and specks are not overhangs.
        const r = (OVERHANG_MIN_WIDTH_LINE_WIDTHS * o.lineWidth) / 2 / this.cell;
        const bitmap = dilate(erode(raw, win.cols, win.rows, r, false), win.cols, win.rows, r);
        for (let k = 0; k < bitmap.length; k++) bitmap[k] = bitmap[k]! & raw[k]!;
        dropSmallComponents(bitmap, win.cols, win.rows, Math.ceil(o.overhangMinAreaMm2 / c2));
        let n = 0;
        for (let k = 0; k < bitmap.length; k++) n += bitmap[k]!;
        if (n > 0) {
          overhang = { win, bitmap };
          out.overhangAreaMm2 = n * c2;
        }
      }
    }

    // Part cells beyond the reach of all material below and outside the interior of the model layer below.
    const candidates = this.overNothingCandidates(here, below, previous);

    if (overhang || candidates.length > 0) {
      const bounds = this.cellBounds(overhang, candidates);
      // The footprint at a cell depends on material up to twice the closing radius away (see grownClosings).
      const grow = 2 * Math.max(o.supportSpanMm / 2, this.reachMm) + 2 * this.cell;
      const win = this.window(bounds, grow);
      const within = this.footprint(win, below);
      // An overhang cell has material under it when it lies in that closed material grown by half a cell of raster
      // slack, not by the threshold's allowance, which the overhang region has already left out.
      const cellGrow = 0.5 + REACH_SLACK_MM / this.cell;
      const reachGrow = this.reachMm / this.cell;
      if (overhang) {
        let hit = 0;
        forEachSet(overhang.bitmap, overhang.win, (i, j) => {
          if (within((j - win.j0) * win.cols + (i - win.i0), cellGrow)) hit++;
        });
        out.overhangSupportedMm2 = hit * c2;
        this.measureTopGap(l, zBottom, overhang);
      }
      let missing = 0;
      for (const k of candidates) {
        const i = (k % this.grid.cols) + this.grid.i0;
        const j = Math.floor(k / this.grid.cols) + this.grid.j0;
        if (!within((j - win.j0) * win.cols + (i - win.i0), reachGrow)) missing++;
      }
      out.overNothingMm2 = missing * c2;
    }

    this.overhangArea += out.overhangAreaMm2;
    this.overhangSupported += out.overhangSupportedMm2;
    this.overNothingArea += out.overNothingMm2;
    const unsupported = out.overhangAreaMm2 - out.overhangSupportedMm2;
    if (unsupported > 0) {
      pushWorst(this.worstOverhang, { layer: l, z: layer.z, areaMm2: out.overhangAreaMm2, unsupportedMm2: unsupported },
        (w) => w.unsupportedMm2);
    }
    if (out.overNothingMm2 > 0) {
      pushWorst(this.worstNothing, {
        layer: l, z: layer.z, areaMm2: out.overNothingMm2, fraction: out.overNothingMm2 / out.partAreaMm2,
      }, (w) => w.areaMm2);
    }
    this.release(l);
    return out;
  }

  /** The support part of the report; `volume` comes from supportVolumes. */
  summary(volume: SupportSummary['volume']): SupportSummary {
    const o = this.o;
    return {
      overhangAngleDeg: o.overhangAngleDeg,
      overhangAreaMm2: this.overhangArea,
      overhangSupportedMm2: this.overhangSupported,
      overhangSupported: this.overhangArea > 0 ? this.overhangSupported / this.overhangArea : null,
      overhangWorstLayers: this.worstOverhang,
      partAreaMm2: this.partArea,
      overNothingMm2: this.overNothingArea,
      overNothing: this.partArea > 0 ? this.overNothingArea / this.partArea : null,
      overNothingWorstLayers: this.worstNothing,
      insideAreaMm2: this.insideArea,
      insideWorstLayer: this.insideWorst,
      insideWorstMm2: this.insideWorstArea,
      supportAreaMm2: this.supportArea,
      supportLayers: this.supportLayers,
      topGap: gapStats(this.topGaps, this.topByLayers, o.layerHeight),
      bottomGap: gapStats(this.bottomGaps, this.bottomByLayers, o.layerHeight),
      volume,
    };
  }

  /**
   * Full-grid indices of part cells of `here` with no material of the layers `below` within the reach, outside
   * the interior of the model layer below. Cells right above material are skipped four at a time; the rest look
   * for material in the disc of the reach around them.
   */
  private overNothingCandidates(here: LayerRaster, below: number[], previous: Spans): number[] {
    const out: number[] = [];
    const b = here.partBounds;
    if (!b) return out;
    const g = this.grid;
    const under = below.map((k) => this.rasters.get(k).bits);
    const under4 = under.map(words);
    const bits = words(here.bits);
    const perRow = g.cols >>> 2;
    const open: number[] = [];
    for (let j = b[1]; j < b[3]; j++) {
      const row = (j - g.j0) * perRow;
      for (let w = row + ((b[0] - g.i0) >>> 2); w < row + ((b[2] - g.i0 + 3) >>> 2); w++) {
        let part = (bits[w]! >>> 1) & LOW_BYTES;
        if (part === 0) continue;
        for (const r of under4) part &= ~r[w]!;
        part &= LOW_BYTES;
        for (let k = 0; part !== 0; k++, part >>>= 8) if ((part & 1) !== 0) open.push(4 * w + k);
      }
    }
    if (open.length === 0) return out;
    // Over the interior of the model layer below (its sparse infill) is not over nothing.
    const interior = erodeSpans(previous, this.o.wallThickness);
    const outside = isEmptySpans(interior) ? open : outsideSpans(open, g, interior);
    if (outside.length === 0) return out;
    const rc = this.reachMm / this.cell;
    // A disc search per cell, or one distance transform over the cells' window when that is cheaper.
    const bounds = this.cellBounds(null, outside);
    const win = this.window(bounds, this.reachMm + 2 * this.cell);
    if (outside.length * Math.PI * rc * rc > DISC_SEARCH_LIMIT * win.cols * win.rows) {
      const any = this.windowOf(win, below, Cell.Any);
      const d = squaredDistance(any, win.cols, win.rows, 1);
      const r2 = rc * rc + 1e-9;
      for (const q of outside) {
        const i = (q % g.cols) + g.i0;
        const j = Math.floor(q / g.cols) + g.j0;
        if (d[(j - win.j0) * win.cols + (i - win.i0)]! > r2) out.push(q);
      }
      return out;
    }
    const reach = Math.floor(rc);
    const r2 = rc * rc;
    for (const q of outside) {
      const ci = q % g.cols;
      const cj = (q - ci) / g.cols;
      let held = false;
      for (let dj = -reach; dj <= reach && !held; dj++) {
        const jj = cj + dj;
        if (jj < 0 || jj >= g.rows) continue;
        const span = Math.floor(Math.sqrt(Math.max(0, r2 - dj * dj)));
        const from = jj * g.cols + Math.max(0, ci - span);
        const to = jj * g.cols + Math.min(g.cols - 1, ci + span);
        for (const r of under) {
          for (let k = from; k <= to; k++) {
            if (r[k] !== 0) {
              held = true;
              break;
            }
          }
          if (held) break;
        }
      }
      if (!held) out.push(q);
    }
    return out;
  }

  /** The cells of window `win` where any of the layers `below` has one of `mask`'s bits. */
  private windowOf(win: Grid, below: number[], mask: number): Uint8Array {
    const any = newBitmap(win);
    const g = this.grid;
    for (const k of below) {
      const r = this.rasters.get(k).bits;
      for (let j = 0; j < win.rows; j++) {
        const src = (j + win.j0 - g.j0) * g.cols + (win.i0 - g.i0);
        const dst = j * win.cols;
        for (let i = 0; i < win.cols; i++) if ((r[src + i]! & mask) !== 0) any[dst + i] = 1;
      }
    }
    return any;
  }

  /** Material of the layers `below` on window `win`, closed over supportSpanMm, to be grown by up to the reach. */
  private footprint(win: Grid, below: number[]): (k: number, growCells: number) => boolean {
    const any = this.windowOf(win, below, Cell.Any);
    const r = Math.max(this.o.supportSpanMm / 2, this.reachMm) / this.cell;
    return grownClosings(any, win.cols, win.rows, r);
  }

  /** Per overhang cell: the gap down to the highest support or interface under it. */
  private measureTopGap(l: number, zBottom: number, overhang: { win: Grid; bitmap: Uint8Array }): void {
    const o = this.o;
    const win = overhang.win;
    const g = this.grid;
    const open: number[] = [];
    forEachSet(overhang.bitmap, win, (i, j) => open.push((j - g.j0) * g.cols + (i - g.i0)));
    const limit = zBottom - GAP_SCAN_LAYERS * o.layerHeight - Z_SLACK_MM;
    let left = open;
    for (let k = l - 1; k >= 0 && left.length > 0 && this.layers[k]!.z >= limit; k--) {
      const r = this.rasters.get(k).bits;
      const gap = Math.max(0, zBottom - this.layers[k]!.z);
      const next: number[] = [];
      let hit = 0;
      for (const q of left) {
        if ((r[q]! & (Cell.Support | Cell.Interface)) !== 0) hit++;
        else next.push(q);
      }
      if (hit > 0) this.addGap(this.topGaps, this.topByLayers, gap, hit);
      left = next;
    }
  }

  /** Per cell where support starts: the gap down to the part under it, when part (not support) is the first. */
  private measureBottomGap(l: number, frame: LayerFrame): void {
    const b = this.rasters.get(l).supportBounds;
    if (l === 0 || !b) return;
    const o = this.o;
    const g = this.grid;
    const here = this.rasters.get(l).bits;
    let prev = -1;
    for (let k = l - 1; k >= 0; k--) {
      if (this.z.frames[k]!.hasSupport) {
        prev = k;
        break;
      }
    }
    const before = prev >= 0 ? this.rasters.get(prev).bits : null;
    const holds = Cell.Support | Cell.Interface | Cell.Raft;
    let open: number[] = [];
    const hw = words(here);
    const bw = before ? words(before) : null;
    const perRow = g.cols >>> 2;
    for (let j = b[1]; j < b[3]; j++) {
      const row = (j - g.j0) * perRow;
      for (let w = row + ((b[0] - g.i0) >>> 2); w < row + ((b[2] - g.i0 + 3) >>> 2); w++) {
        // Support or interface here, and no support, interface or raft in the layer of support below.
        let start = ((hw[w]! >>> 2) | (hw[w]! >>> 3)) & LOW_BYTES;
        if (start === 0) continue;
        if (bw) start &= ~((bw[w]! >>> 2) | (bw[w]! >>> 3) | (bw[w]! >>> 4));
        start &= LOW_BYTES;
        for (let k = 0; start !== 0; k++, start >>>= 8) if ((start & 1) !== 0) open.push(4 * w + k);
      }
    }
    if (open.length === 0) return;
    const zBottom = this.layers[l]!.z - o.supportHeight(frame);
    const limit = zBottom - GAP_SCAN_LAYERS * o.layerHeight - Z_SLACK_MM;
    for (let k = l - 1; k >= 0 && open.length > 0 && this.layers[k]!.z >= limit; k--) {
      const r = this.rasters.get(k).bits;
      const gap = Math.max(0, zBottom - this.layers[k]!.z);
      const next: number[] = [];
      let onPart = 0;
      for (const q of open) {
        const v = r[q]!;
        if ((v & Cell.Any) === 0) next.push(q);
        else if ((v & holds) === 0) onPart++;
      }
      if (onPart > 0) this.addGap(this.bottomGaps, this.bottomByLayers, gap, onPart);
      open = next;
    }
  }

  private addGap(h: WeightedHistogram, byLayers: Float64Array, gapMm: number, cells: number): void {
    const area = cells * this.cell * this.cell;
    h.add(gapMm, area);
    const n = Math.min(byLayers.length - 1, Math.max(0, Math.round(gapMm / this.o.layerHeight)));
    byLayers[n] = byLayers[n]! + area;
  }

  /** Lattice bounds [i0, j0, i1, j1) of the overhang's and the candidates' cells. */
  private cellBounds(
    overhang: { win: Grid; bitmap: Uint8Array } | null, candidates: number[],
  ): [number, number, number, number] {
    let i0 = Infinity, j0 = Infinity, i1 = -Infinity, j1 = -Infinity;
    if (overhang) {
      const w = overhang.win;
      i0 = w.i0;
      j0 = w.j0;
      i1 = w.i0 + w.cols;
      j1 = w.j0 + w.rows;
    }
    const g = this.grid;
    for (const q of candidates) {
      const i = (q % g.cols) + g.i0;
      const j = Math.floor(q / g.cols) + g.j0;
      if (i < i0) i0 = i;
      if (i + 1 > i1) i1 = i + 1;
      if (j < j0) j0 = j;
      if (j + 1 > j1) j1 = j + 1;
    }
    const c = this.cell;
    return [i0 * c, j0 * c, i1 * c, j1 * c];
  }

  /** A window of the support grid around [xmin, ymin, xmax, ymax] (mm) grown by `margin`, clamped to the grid. */
  private window(b: [number, number, number, number], margin: number): Grid {
    const w = gridAround(b[0], b[1], b[2], b[3], this.cell, margin);
    const g = this.grid;
    const i0 = Math.max(g.i0, w.i0);
    const j0 = Math.max(g.j0, w.j0);
    const i1 = Math.min(g.i0 + g.cols, w.i0 + w.cols);
    const j1 = Math.min(g.j0 + g.rows, w.j0 + w.rows);
    return { cell: this.cell, i0, j0, cols: Math.max(1, i1 - i0), rows: Math.max(1, j1 - j0) };
  }

  /** The model's section at height z as spans on the support lattice (cached while nearby layers need it). */
  private spansAt(z: number): Spans {
    const key = Math.round(z * 1e5);
    let s = this.spansByZ.get(key);
    if (!s) {
      s = sectionSpans(this.sections.get(z).segments, this.cell);
      this.spansByZ.set(key, s);
    }
    return s;
  }

  /** Forgets rasters and sections that the layers above layer l no longer need. */
  private release(l: number): void {
    const o = this.o;
    const zKeep = this.layers[l]!.z - (GAP_SCAN_LAYERS + o.supportGapLayers + 2) * o.layerHeight;
    let k = l;
    while (k > 0 && this.layers[k - 1]!.z >= zKeep) k--;
    this.rasters.releaseBelow(k);
    const zModel = this.z.frames[l]!.modelZ - 3 * o.layerHeight;
    for (const key of this.spansByZ.keys()) if (key / 1e5 < zModel) this.spansByZ.delete(key);
  }
}

/** 1 in every byte of a word: masks four cells' flags at once (Cell bits: Any 0, Part 1, Support 2, Interface 3, Raft 4). */
const LOW_BYTES = 0x01010101;

/** A raster's cells four to a word (grid columns are a multiple of 4). */
function words(bits: Uint8Array): Uint32Array {
  return new Uint32Array(bits.buffer, bits.byteOffset, bits.length >>> 2);
}

function round6(z: number): number {
  return Math.round(z * 1e6) / 1e6;
}

/** Cells of the grid whose centres lie in the region and that have any of `mask`'s bits. */
function countMaskedInSpans(s: Spans, grid: Grid, bitmap: Uint8Array, mask: number): number {
  let n = 0;
  for (let r = 0; r < grid.rows; r++) {
    const rs = grid.j0 + r - s.j0;
    if (rs < 0 || rs >= s.rows) continue;
    const base = r * grid.cols;
    for (let q = s.start[rs]!; q < s.start[rs + 1]!; q++) {
      const [first, last] = columnsOf(grid, s.xs[2 * q]!, s.xs[2 * q + 1]!);
      for (let k = base + first; k <= base + last; k++) if ((bitmap[k]! & mask) !== 0) n++;
    }
  }
  return n;
}

/**
 * The cells of `cells` (full-grid indices in increasing order) whose centres lie outside the region, walking each
 * row's intervals along with the cells.
 */
function outsideSpans(cells: number[], g: Grid, s: Spans): number[] {
  const out: number[] = [];
  let row = -1;
  let q = 0;
  let end = 0;
  for (const k of cells) {
    const i = k % g.cols;
    const j = (k - i) / g.cols;
    if (j !== row) {
      row = j;
      const r = j + g.j0 - s.j0;
      q = r >= 0 && r < s.rows ? s.start[r]! : 0;
      end = r >= 0 && r < s.rows ? s.start[r + 1]! : 0;
    }
    const x = (i + g.i0 + 0.5) * g.cell;
    while (q < end && s.xs[2 * q + 1]! < x) q++;
    if (q < end && s.xs[2 * q]! <= x) continue;
    out.push(k);
  }
  return out;
}

/** Calls visit(i, j) with the lattice indices of every set cell of a window bitmap. */
function forEachSet(bitmap: Uint8Array, win: Grid, visit: (i: number, j: number) => void): void {
  for (let j = 0; j < win.rows; j++) {
    const base = j * win.cols;
    for (let i = 0; i < win.cols; i++) if (bitmap[base + i] !== 0) visit(i + win.i0, j + win.j0);
  }
}

function pushWorst<T>(list: T[], item: T, key: (t: T) => number): void {
  list.push(item);
  list.sort((a, b) => key(b) - key(a));
  if (list.length > WORST_LISTED) list.length = WORST_LISTED;
}

function gapStats(h: WeightedHistogram, byLayers: Float64Array, layerHeight: number): GapStats {
  let area = 0;
  for (const v of byLayers) area += v;
  const median = h.quantile(0.5);
  const low = h.quantile(GAP_LOW_QUANTILE);
  const layers = (mm: number) => (Number.isFinite(mm) ? Math.round(mm / layerHeight) : null);
  return {
    areaMm2: area,
    medianMm: Number.isFinite(median) ? median : null,
    minMm: Number.isFinite(low) ? low : null,
    medianLayers: layers(median),
    minLayers: layers(low),
    byLayers: Array.from(byLayers, (v) => (area > 0 ? v / area : 0)),
  };
}
