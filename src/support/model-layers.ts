/**
 * What every support generator needs to know about the model, layer by layer, read from the regions: the
 * section, the overhang to hold up (minus short bridges when those are left to bridge), where support may
 * not go (the part grown by the XY gap, less under overhangs), the shadow of the part for build-plate-only
 * support, and the split of a support area into roof, body and floor.
 */
import { area, boundsOf, difference, intersection, offset, union } from '../geometry/clip.js';
import { UM_PER_MM, type Bounds, type ExPolygon } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import type { LayerOutlines, SupportAreas } from '../regions/types.js';
import { sectionOf } from '../regions/types.js';
import { evenLayers } from '../slice/layers.js';
import { AreaIndex } from '../geometry/area-index.js';
import { LENGTH_EPS_UM } from '../geometry/tolerances.js';

/** Under an overhang, support may come this close to the part, in support line widths ("Z overrides XY"). */
export const OVERHANG_XY_WIDTHS = 0.5;
/** Parts of a support area narrower than this many line widths cannot be printed and are dropped. */
export const MIN_SUPPORT_WIDTHS = 1;

export class ModelLayers {
  readonly layers: readonly LayerOutlines[];
  readonly cfg: Config;
  readonly #sections = new Map<number, ExPolygon[]>();
  /** Per layer, the section as a point index (made on first use). */
  readonly #index = new Map<number, AreaIndex>();
  /** Per layer, the bounds of each island of the section (made on first use). */
  readonly #boxes = new Map<number, Bounds[]>();
  /** Union of the sections of layers 0..j (build-plate placement), filled on demand bottom-up. */
  readonly #shadow: ExPolygon[][] = [];
  /** gapOverhang(), made on first use. */
  #gapOver: ExPolygon[] | null = null;

  /**
   * With uneven layers (adaptive, a layer range's own height), the Z gaps in layers, per layer: the top gap
   * above support layer j, the layer support under overhang layer m reaches up to, the bottom gap below
   * support layer j. Null with even layers: the config's counts.
   */
  readonly #gaps: { top: Int32Array; topOf: Int32Array; bottom: Int32Array } | null;
  /** overhangLayersOver by support layer, made on first use (uneven layers). */
  #over: number[][] | null = null;
  /** The most layers of a top Z gap anywhere. */
  readonly maxTopGap: number;

  constructor(layers: readonly LayerOutlines[], cfg: Config) {
    this.layers = layers;
    this.cfg = cfg;
    if (evenLayers(layers, cfg.layerHeight)) {
      this.#gaps = null;
      this.maxTopGap = cfg.supportTopGapLayers;
      return;
    }
    // a gap given in mm is as many layers as fit (a layer counts when its middle lies within it); none given is one layer
    const heights = Int32Array.from(layers, (l) => Math.round(l.height * 1000));
    const topMm = cfg.supportZGap,
      bottomMm = cfg.supportBottomZGap ?? cfg.supportZGap;
    const n = layers.length;
    const top = new Int32Array(n),
      topOf = new Int32Array(n),
      bottom = new Int32Array(n);
    for (let j = 0; j < n; j++) {
      top[j] = topMm === null ? 1 : gapLayers(heights, j, topMm, 1);
      topOf[j] = j - 1 - (topMm === null ? 1 : gapLayers(heights, j, topMm, -1));
      bottom[j] = bottomMm === null ? 1 : gapLayers(heights, j, bottomMm, -1);
    }
    this.#gaps = { top, topOf, bottom };
    this.maxTopGap = top.reduce((a, b) => Math.max(a, b), 0);
  }

  /** Layers of the top Z gap over support layer j (between its top and the part). */
  topGap(j: number): number {
    return this.#gaps
      ? this.#gaps.top[Math.max(0, Math.min(j, this.#gaps.top.length - 1))]
      : this.cfg.supportTopGapLayers;
  }

  /** The layer support under the overhang of layer m reaches up to, below its top Z gap (negative: none fits). */
  supportTop(m: number): number {
    return this.#gaps && m >= 0 && m < this.#gaps.topOf.length
      ? this.#gaps.topOf[m]
      : m - 1 - this.cfg.supportTopGapLayers;
  }

  /**
   * The overhang layers whose support reaches up to layer j (supportTop(m) = j), lowest first: with even
   * layers m = j + 1 + topGap, with uneven ones none, one or several.
   */
  overhangLayersOver(j: number): number[] {
    if (!this.#gaps) return [j + 1 + this.cfg.supportTopGapLayers];
    if (!this.#over) {
      this.#over = this.layers.map((): number[] => []);
      this.#gaps.topOf.forEach((t, m) => {
        if (t >= 0) this.#over![t].push(m);
      });
    }
    return j >= 0 && j < this.#over.length ? this.#over[j] : [];
  }

  /** Layers of the bottom Z gap under support layer j (between the part below and the support). */
  bottomGap(j: number): number {
    return this.#gaps
      ? this.#gaps.bottom[Math.max(0, Math.min(j, this.#gaps.bottom.length - 1))]
      : this.cfg.supportBottomGapLayers;
  }

  get count(): number {
    return this.layers.length;
  }

  /** The model's section of layer j ([] outside the model). */
  section(j: number): ExPolygon[] {
    if (j < 0 || j >= this.layers.length) return [];
    let s = this.#sections.get(j);
    if (!s) this.#sections.set(j, (s = sectionOf(this.layers[j])));
    return s;
  }

  /** Layer j's section as a point index. */
  sectionIndex(j: number): AreaIndex {
    let ix = this.#index.get(j);
    if (!ix) this.#index.set(j, (ix = new AreaIndex(this.section(j))));
    return ix;
  }

  /** The bounds of each island of layer j's section. */
  sectionBoxes(j: number): Bounds[] {
    let b = this.#boxes.get(j);
    if (!b) this.#boxes.set(j, (b = this.section(j).map((a) => boundsOf([a]))));
    return b;
  }

  /** Forget sections above layer j (support is computed top-down). */
  release(j: number): void {
    for (const k of this.#sections.keys()) if (k > j) this.#sections.delete(k);
    for (const k of this.#index.keys()) if (k > j) this.#index.delete(k);
    for (const k of this.#boxes.keys()) if (k > j) this.#boxes.delete(k);
  }

  /** Forget what was kept for layers below j (drawing goes from the bed up). */
  releaseBelow(j: number): void {
    for (const k of this.#index.keys()) if (k < j) this.#index.delete(k);
    for (const k of this.#boxes.keys()) if (k < j) this.#boxes.delete(k);
  }

  /** Support line width, µm. */
  get widthUm(): number {
    return Math.round(this.cfg.supportLineWidthMm * UM_PER_MM);
  }

  /** The overhang of layer m that support must hold (short bridges left out when the setting asks). */
  overhang(m: number): ExPolygon[] {
    if (m <= 0 || m >= this.layers.length) return [];
    const o = this.layers[m].overhang;
    const span = this.cfg.supportSkipBridges * UM_PER_MM;
    if (o.length === 0 || span <= 0) return o;
    const below = this.section(m - 1);
    // the overhang starts this far out from the layer below: anchors are sought a line width beyond that
    const reach =
      this.layers[m].height * UM_PER_MM * Math.tan((this.cfg.supportThreshold * Math.PI) / 180) + this.widthUm;
    return o.filter((piece) => !isShortBridge(piece, below, span, reach));
  }

  /**
   * Where support may not be on layer j: the part grown by the XY gap, except that under the part's own
   * overhanging edge (the part of the section the layer below does not hold) support may come as close as
   * OVERHANG_XY_WIDTHS, so that it reaches right under sloping surfaces.
   */
  collision(j: number): ExPolygon[] {
    const model = this.section(j);
    if (model.length === 0) return [];
    const xy = this.cfg.supportXYGap * UM_PER_MM;
    const near = OVERHANG_XY_WIDTHS * this.widthUm;
    // on the first layer, the part within the XY gap of the overhang that support holds from there (gapOverhang)
    const over = j > 0 ? this.layers[j].overhang : offset(this.gapOverhang(), xy);
    if (over.length === 0 || xy <= near) return offset(model, Math.max(xy, near));
    const held = difference(model, over);
    return union(offset(held, xy), offset(model, near));
  }

  /**
   * The overhang of the layers within the top Z gap over the first layer (the first layers of a rounded or
   * chamfered underside): no room under it for the gap, so support holds it from the first layer with none,
   * as PrusaSlicer and CuraEngine do.
   */
  gapOverhang(): ExPolygon[] {
    if (!this.#gapOver) {
      this.#gapOver = [];
      for (let m = 1; m < this.count && this.supportTop(m) < 0; m++)
        for (const p of this.overhang(m)) this.#gapOver.push(p);
    }
    return this.#gapOver;
  }

  /** The part's shadow: every section from layer 0 to j, merged. */
  shadow(j: number): ExPolygon[] {
    if (j < 0) return [];
    for (let k = this.#shadow.length; k <= j; k++) {
      const prev = k > 0 ? this.#shadow[k - 1] : [];
      const s = this.section(k);
      this.#shadow.push(s.length === 0 ? prev : prev.length === 0 ? union(s) : union(prev, s));
    }
    return this.#shadow[j];
  }

  /**
   * The islands of the sections of layers j+a .. j+b (inclusive), as one list: they may overlap, which the
   * booleans (non-zero fill) read as their union, so none is computed.
   */
  sectionsBetween(j: number, a: number, b: number): ExPolygon[] {
    if (a === b) return this.section(j + a);
    const parts: ExPolygon[] = [];
    for (let k = j + a; k <= j + b; k++) for (const p of this.section(k)) parts.push(p);
    return parts;
  }

  /** `sectionsBetween(j, a, b)` as a point index: the section's own (kept) index when that is one layer. */
  indexBetween(j: number, a: number, b: number): AreaIndex {
    return a === b ? this.sectionIndex(j + a) : new AreaIndex(this.sectionsBetween(j, a, b));
  }

  /**
   * Split the support area of layer j into roof (under the part, within the interface layers above the top
   * Z gap), floor (on the part, within the floor layers above the bottom Z gap) and body.
   */
  split(j: number, s: readonly ExPolygon[]): SupportAreas {
    const cfg = this.cfg;
    if (s.length === 0) return { body: [], roof: [], floor: [] };
    const top = this.topGap(j);
    const roofAbove =
      cfg.supportInterfaceLayers > 0 ? this.sectionsBetween(j, 1, top + cfg.supportInterfaceLayers) : [];
    const roof = roofAbove.length ? intersection(s, roofAbove) : [];
    const bottom = this.bottomGap(j);
    const floorBelow =
      cfg.supportFloorLayers > 0 && cfg.supportPlacement === 'everywhere'
        ? this.sectionsBetween(j, -(bottom + cfg.supportFloorLayers), -(bottom + 1))
        : [];
    let floor = floorBelow.length ? intersection(s, floorBelow) : [];
    if (roof.length && floor.length) floor = difference(floor, roof);
    const dense = roof.length && floor.length ? union(roof, floor) : roof.length ? roof : floor;
    const body = dense.length ? difference(s, dense) : s.slice();
    return { body, roof, floor };
  }
}

/**
 * How many layers from layer j (not counted) up (`dir` 1) or down (-1) a Z gap of `gapMm` takes: those whose
 * middle lies within it (with even layers, gap / height rounded, halves up, as the config's counts).
 */
function gapLayers(heightsUm: Int32Array, j: number, gapMm: number, dir: 1 | -1): number {
  const gap = gapMm * 1000 + LENGTH_EPS_UM;
  let k = 0,
    below = 0;
  for (let i = j + dir; i >= 0 && i < heightsUm.length; i += dir) {
    if (below + heightsUm[i] / 2 > gap) return k;
    below += heightsUm[i];
    k++;
  }
  // past the model's layers: as many more as the last one's height would fit
  const h = heightsUm[dir > 0 ? heightsUm.length - 1 : 0] || 1;
  return k + Math.max(0, Math.floor((gap - below) / h + 0.5));
}

/**
 * Whether an overhang piece is a short bridge: held by the layer below on at least two sides, and no point of
 * it further than half the span from what holds it.
 */
export function isShortBridge(piece: ExPolygon, below: readonly ExPolygon[], spanUm: number, reachUm: number): boolean {
  if (below.length === 0) return false;
  const anchors = intersection(offset([piece], reachUm), below);
  if (anchors.length < 2) return false;
  return difference([piece], offset(anchors, spanUm / 2)).length === 0;
}

/** Drop what a support line cannot print: pieces narrower than a line, and specks. */
export function printable(s: readonly ExPolygon[], widthUm: number): ExPolygon[] {
  if (s.length === 0) return [];
  const r = (MIN_SUPPORT_WIDTHS * widthUm) / 2;
  const opened = offset(offset(s, -r), r);
  return opened.filter((a) => area([a]) >= widthUm * widthUm);
}
