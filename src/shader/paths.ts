/**
 * Infill paths from a label field (shader or image): the boundaries between cells of different
 * labels over the infill region, refined by bisection, linked, simplified, clipped to the region and
 * chained with short travel. A multi-pass shader gives one set of paths per pass.
 */
import { segmentDistance2, type ExPolygon, type Polyline, type Pt } from '../geometry/types.js';
import { boundsOf, clipLines, offset } from '../geometry/clip.js';
import { StrataError } from '../errors.js';
import { orderPaths } from '../order/index.js';
import { linkCrossings } from './contour-link.js';
import type { LabelFn } from './label-grid.js';
import { sampleLabelGrid } from './label-grid.js';
import { isClosed, polylineLength, simplifyMmPath, toMicrons } from './polyline-tools.js';
import type { CompiledShader, ParamValues, ShaderInstance } from './shader.js';

/** Density: a constant percentage, or a field of (x, y, z) in mm → percentage (0–100). */
export type DensitySource = number | ((x: number, y: number, z: number) => number);

export interface ExtractOptions {
  /** Nozzle diameter, mm (default 0.4). */
  nozzleDiameter?: number;
  /** Grid spacing, mm (default nozzleDiameter / 4). */
  resolution?: number;
  /** Bisection accuracy, mm (default 0.0005). */
  tolerance?: number;
  /** Douglas–Peucker tolerance for the linked paths, mm (default 0.005). */
  simplify?: number;
  /** Clipped pieces shorter than this are dropped, mm (default nozzleDiameter / 2). */
  minLength?: number;
  /** Largest number of grid samples per pass (default 8 million, about 160 MB of grid). */
  maxSamples?: number;
  /** Where the nozzle is before the first path, µm (default: the region's lower-left corner). */
  start?: Pt;
  /** Lattice shift as a fraction of the grid spacing (default 0.2718). */
  phase?: number;
}

export interface ShaderLayerInput {
  /** The area to fill, µm. */
  region: ExPolygon[];
  /** Height of the layer's top (the z passed to the shader), mm. */
  z: number;
  /** Layer thickness, mm (layer_height()). Default 0.2. */
  layerHeight?: number;
  /** density() in percent (default 20). */
  density?: DensitySource;
  /** ui_ parameter overrides. */
  params?: ParamValues;
}

/** The least bisection accuracy, mm: a zero tolerance, or one below the float spacing, would bisect forever. */
const MIN_BISECTION_TOLERANCE_MM = 1e-6;

interface Resolved {
  h: number;
  tolerance: number;
  simplify: number;
  minLength: number;
  maxSamples: number;
  phase: number;
}

function resolve(opts: ExtractOptions): Resolved {
  const nozzle = opts.nozzleDiameter ?? 0.4;
  const h = opts.resolution ?? nozzle / 4;
  if (!(h > 0) || !Number.isFinite(h))
    throw new StrataError('BAD_SETTING', `custom infill: resolution must be a positive number of mm, got ${h}`);
  if (!(nozzle > 0))
    throw new StrataError('BAD_SETTING', `custom infill: nozzle diameter must be positive, got ${nozzle}`);
  return {
    h,
    tolerance: Math.max(MIN_BISECTION_TOLERANCE_MM, Math.min(opts.tolerance ?? 0.0005, h / 4)),
    simplify: opts.simplify ?? 0.005,
    minLength: opts.minLength ?? nozzle / 2,
    maxSamples: opts.maxSamples ?? 8_000_000,
    phase: opts.phase ?? 0.2718,
  };
}

/**
 * Boundaries between the cells of a label field over a region: one pass. Returns ordered
 * polylines in µm, clipped to the region.
 */
export function labelBoundaries(label: LabelFn, region: readonly ExPolygon[], opts: ExtractOptions = {}): Polyline[] {
  if (region.length === 0) return [];
  const r = resolve(opts);
  const all = boundsOf(region);
  if (!(all.maxX > all.minX && all.maxY > all.minY)) return [];
  // Islands are sampled one by one, so far-apart parts do not make one huge grid.
  const out: Polyline[] = [];
  let budget = r.maxSamples;
  for (const island of region) {
    const part = [island];
    const b = boundsOf(part);
    if (!(b.maxX > b.minX && b.maxY > b.minY)) continue;
    const marginMm = 2 * r.h;
    const grown = offset(part, Math.ceil(marginMm * 1000));
    const bounds = {
      minX: b.minX / 1000 - marginMm,
      minY: b.minY / 1000 - marginMm,
      maxX: b.maxX / 1000 + marginMm,
      maxY: b.maxY / 1000 + marginMm,
    };
    const grid = sampleLabelGrid(label, grown, bounds, {
      h: r.h,
      tolerance: r.tolerance,
      margin: marginMm,
      maxSamples: budget,
      phase: r.phase,
    });
    budget -= grid.nx * grid.ny;
    const lines: Polyline[] = [];
    for (const p of linkCrossings(grid, label)) {
      const q = toMicrons(simplifyMmPath(p, r.simplify));
      if (q.length >= 2) lines.push(q);
    }
    for (const p of clipLines(lines, part)) {
      if (p.length >= 2 && polylineLength(p) >= r.minLength * 1000 && !alongBoundary(p, part)) out.push(p);
    }
  }
  return chainPaths(out, opts.start ?? { x: all.minX, y: all.minY });
}

/** Consecutive open paths whose ends are at most this far apart are joined into one, µm. */
const JOIN_GAP = 5;

/**
 * Paths in print order from `start` (nearest-first, ties as the grid search finds them: see order/nearest.ts):
 * an open path entered at either end, turned round when at its last; a closed one (its first point repeated
 * last) found by its first point and started at its vertex nearest the nozzle. Consecutive open paths whose ends
 * touch (within JOIN_GAP) are joined into one.
 */
export function chainPaths(paths: readonly Polyline[], start: Pt): Polyline[] {
  const kept = paths.filter((p) => p.length >= 2);
  const closed = kept.map(isClosed);
  // the vertex each closed path starts at, found as the order comes to it
  const startAt = new Int32Array(kept.length);
  const order = orderPaths(
    {
      count: kept.length,
      entries: (i) => (closed[i] ? [kept[i][0]] : [kept[i][0], kept[i][kept[i].length - 1]]),
      line: (i) => !closed[i],
      exit: (i, entry, at) => {
        const p = kept[i];
        if (!closed[i]) return entry === 0 ? p[p.length - 1] : p[0];
        startAt[i] = nearestVertex(p, at);
        return p[startAt[i]];
      },
    },
    { from: start, ties: 'grid' },
  );
  const out: Polyline[] = [];
  let at = start;
  for (const [i, entry] of order) {
    let p = kept[i];
    if (closed[i]) p = startClosedAt(p, startAt[i]);
    else if (entry === 1) p = p.slice().reverse();
    const prev = out[out.length - 1];
    const gap = prev === undefined ? Infinity : Math.hypot(p[0].x - at.x, p[0].y - at.y);
    if (prev !== undefined && gap <= JOIN_GAP && !isClosed(prev) && !closed[i]) {
      out[out.length - 1] = prev.concat(gap === 0 ? p.slice(1) : p);
    } else out.push(p);
    at = p[p.length - 1];
  }
  return out;
}

/** The vertex of a closed path (its first point repeated last) nearest `at`, the first on a tie. */
function nearestVertex(p: Polyline, at: Pt): number {
  let best = 0;
  let bestD = Infinity;
  for (let i = 0; i < p.length - 1; i++) {
    const d = (p[i].x - at.x) ** 2 + (p[i].y - at.y) ** 2;
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  return best;
}

/** A closed path (its first point repeated last) started at its vertex k. */
function startClosedAt(p: Polyline, k: number): Polyline {
  if (k === 0) return p;
  const ring = p.slice(0, -1);
  const out = [...ring.slice(k), ...ring.slice(0, k)];
  out.push(out[0]);
  return out;
}

function nearBoundary(px: number, py: number, region: readonly ExPolygon[], tol2: number): boolean {
  for (const e of region) {
    for (const ring of [e.outer, ...e.holes]) {
      for (let i = 0, j = ring.length - 1; i < ring.length; j = i++)
        if (segmentDistance2(px, py, ring[j].x, ring[j].y, ring[i].x, ring[i].y) <= tol2) return true;
    }
  }
  return false;
}

/**
 * Whether a clipped path runs along the region's edge (a cell boundary that coincides with it):
 * such a path would only retrace the wall, and the clipper keeps or drops it inconsistently.
 */
function alongBoundary(p: Polyline, region: readonly ExPolygon[]): boolean {
  const tol2 = 4;
  for (let i = 1; i < p.length; i++) {
    if (!nearBoundary((p[i - 1].x + p[i].x) / 2, (p[i - 1].y + p[i].y) / 2, region, tol2)) return false;
  }
  return true;
}

function densityFn(d: DensitySource | undefined): (x: number, y: number, z: number) => number {
  if (d === undefined) return () => 20;
  if (typeof d === 'number') {
    if (!Number.isFinite(d)) throw new StrataError('BAD_SETTING', 'custom infill: density must be a number');
    return () => d;
  }
  return (x, y, z) => {
    const v = d(x, y, z);
    return Number.isFinite(v) ? Math.min(100, Math.max(0, v)) : 0;
  };
}

/** One instance per call site: pass a ShaderInstance to reuse its warmed-up code across layers. */
function instanceOf(shader: CompiledShader | ShaderInstance): ShaderInstance {
  return 'instantiate' in shader ? shader.instantiate() : shader;
}

/**
 * Paths of an infill shader for one layer, one list per pass (pass 0 first). Each pass is
 * extracted and ordered separately; pass k+1 starts where pass k ended.
 */
export function shaderPathsByPass(
  shader: CompiledShader | ShaderInstance,
  layer: ShaderLayerInput,
  opts: ExtractOptions = {},
): Polyline[][] {
  const inst = instanceOf(shader);
  const env = {
    params: layer.params,
    density: densityFn(layer.density),
    nozzleDiameter: opts.nozzleDiameter ?? 0.4,
    layerHeight: layer.layerHeight ?? 0.2,
  };
  inst.configure({ ...env, pass: 0 });
  const passes = inst.numPasses();
  inst.resetWork();
  const z = layer.z;
  const out: Polyline[][] = [];
  let start = opts.start;
  for (let pass = 0; pass < passes; pass++) {
    if (pass > 0) inst.configure({ ...env, pass });
    const label: LabelFn = (x, y) => inst.label(x, y, z);
    const paths = labelBoundaries(label, layer.region, { ...opts, start });
    out.push(paths);
    const last = paths[paths.length - 1];
    if (last !== undefined) start = last[last.length - 1];
  }
  return out;
}

/** All passes' paths of an infill shader for one layer, in print order. */
export function shaderPaths(
  shader: CompiledShader | ShaderInstance,
  layer: ShaderLayerInput,
  opts: ExtractOptions = {},
): Polyline[] {
  return shaderPathsByPass(shader, layer, opts).flat();
}
