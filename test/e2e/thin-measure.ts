/**
 * Test-only measurement of how thin features were printed, read from the G-code alone: per polygon (a fin, a
 * taper) the plastic laid there against its volume, the share of its area the beads cover, and the bead area
 * spilling outside it; over a whole file the share of the part's extrusion that is narrower than a bound.
 *
 * A bead is an extrusion segment drawn as a capsule as wide as its line: width = E · filament area / (length ·
 * layer height), the rectangle flow model the slicer writes E with. The layer height is the one the G-code
 * declares (`;HEIGHT:`), else the Z step from the layer below.
 */
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { Feature } from '../../tools/analysis/feature-names.js';
import type { ParsedGcode } from '../../tools/analysis/gcode-types.js';
import { segmentDistance2 } from '#strata/geometry/types.js';
import { polygonArea, type Polygon } from './thin-shapes.js';

export type { Point, Polygon } from './thin-shapes.js';

/** Features of the part itself: walls, skin and infill (not skirt, brim, support, raft or ironing). */
export const PART_FEATURES: readonly number[] = [Feature.WallOuter, Feature.WallInner, Feature.Skin, Feature.Fill];

/** One layer's extrusion segments as beads. */
export interface BeadLayer {
  /** Print Z, mm. */
  z: number;
  /** Layer height, mm. */
  height: number;
  count: number;
  x0: Float32Array;
  y0: Float32Array;
  x1: Float32Array;
  y1: Float32Array;
  /** Filament, mm. */
  e: Float32Array;
  /** Feature code (see analysis/feature-names.ts). */
  feature: Uint8Array;
  /** Line width, mm. */
  width: Float64Array;
  /** XY length, mm. */
  length: Float64Array;
}

export interface BeadOptions {
  /** Filament diameter, mm (default 1.75). */
  filamentDiameter?: number;
  /** Feature codes kept (default PART_FEATURES). */
  features?: readonly number[];
}

/** Cross-section of the filament, mm². */
export function filamentAreaMm2(diameter = 1.75): number {
  return (Math.PI * diameter * diameter) / 4;
}

function parsed(gcode: string | ParsedGcode): ParsedGcode {
  return typeof gcode === 'string' ? parseGcode(gcode) : gcode;
}

/** The G-code's layers of extrusion segments with their widths, keeping only `features`. */
export function beadLayers(gcode: string | ParsedGcode, options: BeadOptions = {}): BeadLayer[] {
  const p = parsed(gcode);
  const area = filamentAreaMm2(options.filamentDiameter ?? 1.75);
  const keep = new Set(options.features ?? PART_FEATURES);
  const out: BeadLayer[] = [];
  for (const layer of p.layers) {
    const ex = layer.extrusions;
    const height = layer.declaredHeight ?? layer.thickness;
    const idx: number[] = [];
    for (let i = 0; i < ex.count; i++) if (keep.has(ex.feature[i])) idx.push(i);
    const n = idx.length;
    const b: BeadLayer = {
      z: layer.z,
      height,
      count: n,
      x0: new Float32Array(n),
      y0: new Float32Array(n),
      x1: new Float32Array(n),
      y1: new Float32Array(n),
      e: new Float32Array(n),
      feature: new Uint8Array(n),
      width: new Float64Array(n),
      length: new Float64Array(n),
    };
    idx.forEach((i, k) => {
      b.x0[k] = ex.x0[i];
      b.y0[k] = ex.y0[i];
      b.x1[k] = ex.x1[i];
      b.y1[k] = ex.y1[i];
      b.e[k] = ex.e[i];
      b.feature[k] = ex.feature[i];
      const len = Math.hypot(ex.x1[i] - ex.x0[i], ex.y1[i] - ex.y0[i]);
      b.length[k] = len;
      b.width[k] = len > 0 && height > 0 ? (ex.e[i] * area) / (len * height) : 0;
    });
    out.push(b);
  }
  return out;
}

/** Whether a point is inside a polygon (even-odd). */
export function pointInPolygon(x: number, y: number, poly: Polygon): boolean {
  let inside = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const [xi, yi] = poly[i],
      [xj, yj] = poly[j];
    if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** Distance from a point to a polygon's boundary. */
export function distanceToBoundary(x: number, y: number, poly: Polygon): number {
  let best = Infinity;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    best = Math.min(best, segmentDistance2(x, y, poly[j][0], poly[j][1], poly[i][0], poly[i][1]));
  }
  return Math.sqrt(best);
}

/** Whether a point is inside the polygon grown by `grow` mm (round joins): inside, or within `grow` of its edge. */
export function inGrownPolygon(x: number, y: number, poly: Polygon, grow: number): boolean {
  return pointInPolygon(x, y, poly) || (grow > 0 && distanceToBoundary(x, y, poly) <= grow);
}

export interface ZRange {
  /** Layers whose print Z lies in [zMin, zMax] are measured, mm. */
  zMin: number;
  zMax: number;
}

export interface MeasureOptions extends BeadOptions {
  /** Raster cell, mm (default 0.02). */
  cellMm?: number;
  /** A segment counts towards a polygon's volume when its midpoint lies in the polygon grown by this (0.05 mm). */
  volumeGrowMm?: number;
  /** Bead area beyond the polygon grown by this is outside (0.1 mm). */
  outsideGrowMm?: number;
  /** Bead area outside is looked for this far around the polygon's bounding box (1 mm). */
  outsideWindowMm?: number;
  /** Areas where beads are not counted as outside any measured polygon (e.g. the body a fin stands on). */
  allowed?: readonly Polygon[];
}

export interface PolygonMeasure {
  /** Extruded volume of the segments whose midpoints lie in the polygon (grown by 0.05), over its area × height span. */
  volumeRatio: number;
  /** Share of the polygon's area under beads, averaged over the layers in range. */
  coverage: number;
  /** Bead area outside the polygon grown by 0.1 mm, within the window around it, averaged over the layers, mm². */
  outsideMm2: number;
  /** The polygon's area, mm². */
  areaMm2: number;
  /** Extruded volume counted (the numerator of volumeRatio), mm³. */
  volumeMm3: number;
  /** Sum of the heights of the layers in range, mm. */
  heightSpanMm: number;
  /** Layers in range. */
  layers: number;
  /** Coverage of each layer in range, bottom up. */
  layerCoverage: number[];
  /** Narrowest and widest bead whose midpoint is in the polygon (null when there is none), mm. */
  minWidthMm: number | null;
  maxWidthMm: number | null;
}

interface Grid {
  x0: number;
  y0: number;
  nx: number;
  ny: number;
  cell: number;
  /** 1: inside the polygon; 2: outside the grown polygon (and every allowed area); 0: the band between. */
  cls: Uint8Array;
  inside: number;
}

function makeGrid(
  poly: Polygon,
  o: Required<Pick<MeasureOptions, 'cellMm' | 'outsideGrowMm' | 'outsideWindowMm'>>,
  allowed: readonly Polygon[],
): Grid {
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (const [x, y] of poly) {
    minX = Math.min(minX, x);
    minY = Math.min(minY, y);
    maxX = Math.max(maxX, x);
    maxY = Math.max(maxY, y);
  }
  const cell = o.cellMm,
    w = o.outsideWindowMm;
  const x0 = minX - w,
    y0 = minY - w;
  const nx = Math.ceil((maxX - minX + 2 * w) / cell),
    ny = Math.ceil((maxY - minY + 2 * w) / cell);
  const cls = new Uint8Array(nx * ny);
  let inside = 0;
  for (let j = 0; j < ny; j++) {
    const y = y0 + (j + 0.5) * cell;
    for (let i = 0; i < nx; i++) {
      const x = x0 + (i + 0.5) * cell;
      let c: number;
      if (pointInPolygon(x, y, poly)) {
        c = 1;
        inside++;
      } else if (distanceToBoundary(x, y, poly) <= o.outsideGrowMm) {
        c = 0;
      } else {
        c = allowed.some((a) => inGrownPolygon(x, y, a, o.outsideGrowMm)) ? 0 : 2;
      }
      cls[j * nx + i] = c;
    }
  }
  return { x0, y0, nx, ny, cell, cls, inside };
}

/** Marks the cells of `grid` whose centres lie under any bead of the layer. */
function rasterBeads(grid: Grid, layer: BeadLayer, covered: Uint8Array): void {
  covered.fill(0);
  const { x0, y0, nx, ny, cell } = grid;
  const gx1 = x0 + nx * cell,
    gy1 = y0 + ny * cell;
  for (let k = 0; k < layer.count; k++) {
    const r = layer.width[k] / 2;
    if (!(r > 0)) continue;
    const ax = layer.x0[k],
      ay = layer.y0[k],
      bx = layer.x1[k],
      by = layer.y1[k];
    const lx = Math.min(ax, bx) - r,
      hx = Math.max(ax, bx) + r,
      ly = Math.min(ay, by) - r,
      hy = Math.max(ay, by) + r;
    if (hx < x0 || lx > gx1 || hy < y0 || ly > gy1) continue;
    const i0 = Math.max(0, Math.floor((lx - x0) / cell)),
      i1 = Math.min(nx - 1, Math.floor((hx - x0) / cell));
    const j0 = Math.max(0, Math.floor((ly - y0) / cell)),
      j1 = Math.min(ny - 1, Math.floor((hy - y0) / cell));
    const r2 = r * r;
    for (let j = j0; j <= j1; j++) {
      const y = y0 + (j + 0.5) * cell;
      for (let i = i0; i <= i1; i++) {
        const idx = j * nx + i;
        if (covered[idx]) continue;
        if (segmentDistance2(x0 + (i + 0.5) * cell, y, ax, ay, bx, by) <= r2) covered[idx] = 1;
      }
    }
  }
}

/** Layers whose print Z lies in the range. */
export function layersInRange(layers: readonly BeadLayer[], range: ZRange): BeadLayer[] {
  const eps = 1e-6;
  return layers.filter((l) => l.z >= range.zMin - eps && l.z <= range.zMax + eps);
}

/**
 * Measure the beads laid in each polygon over the layers whose Z lies in `range`: volume ratio, coverage and
 * area outside (see PolygonMeasure).
 */
export function measurePolygons(
  gcode: string | ParsedGcode | readonly BeadLayer[],
  polygons: readonly Polygon[],
  range: ZRange,
  options: MeasureOptions = {},
): PolygonMeasure[] {
  const all = Array.isArray(gcode)
    ? (gcode as readonly BeadLayer[])
    : beadLayers(gcode as string | ParsedGcode, options);
  const layers = layersInRange(all, range);
  const fa = filamentAreaMm2(options.filamentDiameter ?? 1.75);
  const o = {
    cellMm: options.cellMm ?? 0.02,
    outsideGrowMm: options.outsideGrowMm ?? 0.1,
    outsideWindowMm: options.outsideWindowMm ?? 1,
  };
  const volumeGrow = options.volumeGrowMm ?? 0.05;
  const heightSpan = layers.reduce((s, l) => s + l.height, 0);
  return polygons.map((poly) => {
    const area = Math.abs(polygonArea(poly));
    const grid = makeGrid(poly, o, options.allowed ?? []);
    const covered = new Uint8Array(grid.cls.length);
    const cellArea = o.cellMm * o.cellMm;
    let volume = 0,
      outside = 0;
    let minW = Infinity,
      maxW = -Infinity;
    const layerCoverage: number[] = [];
    for (const layer of layers) {
      for (let k = 0; k < layer.count; k++) {
        const mx = (layer.x0[k] + layer.x1[k]) / 2,
          my = (layer.y0[k] + layer.y1[k]) / 2;
        if (!inGrownPolygon(mx, my, poly, volumeGrow)) continue;
        volume += layer.e[k] * fa;
        minW = Math.min(minW, layer.width[k]);
        maxW = Math.max(maxW, layer.width[k]);
      }
      rasterBeads(grid, layer, covered);
      let inCovered = 0,
        outCovered = 0;
      for (let i = 0; i < covered.length; i++) {
        if (!covered[i]) continue;
        if (grid.cls[i] === 1) inCovered++;
        else if (grid.cls[i] === 2) outCovered++;
      }
      layerCoverage.push(grid.inside > 0 ? inCovered / grid.inside : 0);
      outside += outCovered * cellArea;
    }
    const n = layers.length;
    return {
      volumeRatio: area > 0 && heightSpan > 0 ? volume / (area * heightSpan) : 0,
      coverage: n > 0 ? layerCoverage.reduce((s, c) => s + c, 0) / n : 0,
      outsideMm2: n > 0 ? outside / n : 0,
      areaMm2: area,
      volumeMm3: volume,
      heightSpanMm: heightSpan,
      layers: n,
      layerCoverage,
      minWidthMm: minW === Infinity ? null : minW,
      maxWidthMm: maxW === -Infinity ? null : maxW,
    };
  });
}

/**
 * Share of the part's extrusion length (walls, skin, infill: not skirt or support) laid in lines narrower than
 * `minWidthMm`, over the whole file.
 */
export function underWidthFraction(
  gcode: string | ParsedGcode | readonly BeadLayer[],
  minWidthMm: number,
  options: BeadOptions = {},
): number {
  const layers = Array.isArray(gcode)
    ? (gcode as readonly BeadLayer[])
    : beadLayers(gcode as string | ParsedGcode, options);
  let total = 0,
    under = 0;
  for (const l of layers) {
    for (let k = 0; k < l.count; k++) {
      total += l.length[k];
      if (l.width[k] < minWidthMm) under += l.length[k];
    }
  }
  return total > 0 ? under / total : 0;
}
