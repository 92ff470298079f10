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
 * - Z gaps: from the top of support to the overhang above it, and from the model to support standing on it; the
 *   second model layer's top gap apart (over the first layer there is no room for a gap: support on the first
 *   layer holds the second layer's overhang with none, as PrusaSlicer's and CuraEngine's do).
 * The first model layer rests on the bed (or on the raft, which then must lie under it).
 */
import type { GcodeLayer } from './gcode-types.js';
import type { Grid } from './grid.js';
import { gridAround, newBitmap } from './grid.js';
import type { LayerFrame, ModelZ } from './model-z.js';
import { dilate, dropSmallComponents, erode, grownClosings } from './morphology.js';
import { overNothingCandidates } from './over-nothing.js';
import type { LayerSupport, SupportSummary } from './report-types.js';
import type { SectionCache } from './section-cache.js';
import { sectionSpans } from './section.js';
import type { Spans } from './spans.js';
import { dilateSpans, emptySpans, erodeSpans, spansBoolean, spansBounds, spansToBitmap } from './spans.js';
import { cellBounds, countMaskedInSpans, inWindow, setCells, windowIn, windowOf } from './support-cells.js';
import { GAP_SCAN_LAYERS, GapMeter, measureBottomGap, measureTopGap } from './support-gaps.js';
import { Cell, LayerRasters } from './support-raster.js';

/**
 * Overhang strips narrower than this (line widths) are left out: along a wall a little steeper than the threshold
 * the overhang is a strip of a raster cell or two whose measure is raster noise.
 */
export const OVERHANG_MIN_WIDTH_LINE_WIDTHS = 0.5;
/** Support beads deeper than this inside the section count as inside the part (line widths). */
export const INSIDE_TOLERANCE_LINE_WIDTHS = 0.5;
/** Support rasters use cells of at least this many line widths (mm per line width). */
export const SUPPORT_CELL_LINE_WIDTHS = 0.25;
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
  private readonly topGaps: GapMeter;
  /** Top gaps under the second model layer, over the first: there is no room there for a gap. */
  private readonly secondLayerGaps: GapMeter;
  private readonly bottomGaps: GapMeter;

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
    this.topGaps = new GapMeter(o.layerHeight, this.cell * this.cell);
    this.secondLayerGaps = new GapMeter(o.layerHeight, this.cell * this.cell);
    this.bottomGaps = new GapMeter(o.layerHeight, this.cell * this.cell);
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
      overhangAreaMm2: 0,
      overhangSupportedMm2: 0,
      partAreaMm2: 0,
      overNothingMm2: 0,
      supportAreaMm2: 0,
      insideMm2: 0,
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
      const zSupport = layer.z - o.supportHeight(frame);
      measureBottomGap(
        this.bottomGaps,
        this.layers,
        this.z.frames,
        this.rasters,
        l,
        zSupport,
        o.layerHeight,
        Math.ceil(o.lineWidth / this.rasters.grid.cell),
      );
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
        const win = windowIn(this.grid, b, 2 * this.cell);
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
    const candidates = overNothingCandidates(this.rasters, here, below, previous, this.reachMm, o.wallThickness);

    if (overhang || candidates.length > 0) {
      const bounds = cellBounds(this.grid, overhang?.win ?? null, candidates);
      // The footprint at a cell depends on material up to twice the closing radius away (see grownClosings).
      const grow = 2 * Math.max(o.supportSpanMm / 2, this.reachMm) + 2 * this.cell;
      const win = windowIn(this.grid, bounds, grow);
      const within = this.footprint(win, below);
      // An overhang cell has material under it when it lies in that closed material grown by half a cell of raster
      // slack, not by the threshold's allowance, which the overhang region has already left out.
      const cellGrow = 0.5 + REACH_SLACK_MM / this.cell;
      const reachGrow = this.reachMm / this.cell;
      if (overhang) {
        const cells = setCells(this.grid, overhang.bitmap, overhang.win);
        let hit = 0;
        for (const q of cells) if (within(inWindow(this.grid, win, q), cellGrow)) hit++;
        out.overhangSupportedMm2 = hit * c2;
        const second = this.z.firstModelLayer !== null && l === this.z.firstModelLayer + 1;
        measureTopGap(
          second ? this.secondLayerGaps : this.topGaps,
          this.layers,
          this.rasters,
          l,
          zBottom,
          cells,
          o.layerHeight,
        );
      }
      let missing = 0;
      for (const q of candidates) if (!within(inWindow(this.grid, win, q), reachGrow)) missing++;
      out.overNothingMm2 = missing * c2;
    }

    this.overhangArea += out.overhangAreaMm2;
    this.overhangSupported += out.overhangSupportedMm2;
    this.overNothingArea += out.overNothingMm2;
    const unsupported = out.overhangAreaMm2 - out.overhangSupportedMm2;
    if (unsupported > 0) {
      pushWorst(
        this.worstOverhang,
        { layer: l, z: layer.z, areaMm2: out.overhangAreaMm2, unsupportedMm2: unsupported },
        (w) => w.unsupportedMm2,
      );
    }
    if (out.overNothingMm2 > 0) {
      pushWorst(
        this.worstNothing,
        {
          layer: l,
          z: layer.z,
          areaMm2: out.overNothingMm2,
          fraction: out.overNothingMm2 / out.partAreaMm2,
        },
        (w) => w.areaMm2,
      );
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
      topGap: this.topGaps.stats(),
      topGapOverFirstLayer: this.secondLayerGaps.stats(),
      bottomGap: this.bottomGaps.stats(),
      volume,
    };
  }

  /** Material of the layers `below` on window `win`, closed over supportSpanMm, to be grown by up to the reach. */
  private footprint(win: Grid, below: number[]): (k: number, growCells: number) => boolean {
    const any = windowOf(this.rasters, win, below, Cell.Any);
    const r = Math.max(this.o.supportSpanMm / 2, this.reachMm) / this.cell;
    return grownClosings(any, win.cols, win.rows, r);
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

function round6(z: number): number {
  return Math.round(z * 1e6) / 1e6;
}

function pushWorst<T>(list: T[], item: T, key: (t: T) => number): void {
  list.push(item);
  list.sort((a, b) => key(b) - key(a));
  if (list.length > WORST_LISTED) list.length = WORST_LISTED;
}
