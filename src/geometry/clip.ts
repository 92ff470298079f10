/**
 * The thin geometry facade: union, difference, intersection, offset and open-path clipping over
 * Clipper2, in integer micrometres. Nothing else in Strata imports the clipping library. The engine is
 * Clipper2 compiled to WebAssembly (clipper2-wasm, see clipper-wasm.ts): on 3DBenchy a slice took 0.79 ×
 * the wall time of the same library in TypeScript (clipper2-ts, clipper-ts.ts), which stays as the reference
 * engine the tests hold the WebAssembly one against (`clipOperations` over it); nothing in the product loads it.
 */
import type { Bounds, ExPolygon, Polygon, Polyline, Pt } from './types.js';
import { MiterWork, rawMiterOffset } from './miter-offset.js';
import { pointInRing, ringBounds, ringInside } from './contain.js';
import { EdgeWork, islandsApart, islandsIfSimple, MAX_RINGS } from './simple-rings.js';
import * as wasmEngine from './clipper-wasm.js';

/** A clipping engine's operations, as both engine modules (clipper-wasm.ts, clipper-ts.ts) export them. */
export type ClipEngine = Pick<
  typeof wasmEngine,
  'booleanAreas' | 'unionDroppingCollinear' | 'inflateAreas' | 'strokeAreas' | 'clipOpen' | 'simplifyClosed'
>;

export type Join = 'miter' | 'round' | 'square';

/** Arc tolerance for round joins, µm: chord error allowed when offsetting curves. */
const ARC_TOLERANCE_UM = 5;
const MITER_LIMIT = 3;

/** Rings of a list of islands, as one flat list for the clipper (outer CCW, holes CW). */
export function flatten(areas: readonly ExPolygon[]): Polygon[] {
  const out: Polygon[] = [];
  for (const a of areas) {
    out.push(a.outer);
    for (const h of a.holes) out.push(h);
  }
  return out;
}

/** The clipping operations, over one engine. */
export interface ClipOperations {
  unionRings(rings: readonly Polygon[]): ExPolygon[];
  evenOddAreas(rings: readonly Polygon[]): ExPolygon[];
  union(a: readonly ExPolygon[], b?: readonly ExPolygon[]): ExPolygon[];
  difference(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[];
  intersection(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[];
  offset(areas: readonly ExPolygon[], deltaUm: number, join?: Join): ExPolygon[];
  strokeArea(
    lines: readonly Polyline[],
    loops: readonly Polygon[],
    widthUm: number,
    join?: 'round' | 'miter',
  ): ExPolygon[];
  clipLines(lines: readonly Polyline[], areas: readonly ExPolygon[]): Polyline[];
  clipLinesOutside(lines: readonly Polyline[], areas: readonly ExPolygon[]): Polyline[];
  simplifyRings(rings: readonly Polygon[], toleranceUm: number): Polygon[];
  simplifyAreas(areas: readonly ExPolygon[], toleranceUm: number): ExPolygon[];
}

/**
 * The operations over one engine. The slicer's are over the WebAssembly engine (the functions this module
 * exports); the tests make a second set over the TypeScript reference engine and hold the two together.
 */
export function clipOperations(engine: ClipEngine): ClipOperations {
  // The working arrays of the offset's own kernels (the raw mitre offset, the simplicity test), kept with this set
  // of operations as the engine keeps its memory, and grown to the largest call: a slice offsets thousands of short
  // rings, and arrays made afresh for each call cost more than the work done in them (3DBenchy: about 1.5 % of the
  // slice). They hold nothing between calls: every call is synchronous, calls nothing that could call back into it,
  // and overwrites what it reads, so two slices in one process, which take turns on these operations as they do
  // on the engine, never see each other's data.
  const miterWork = new MiterWork();
  const edgeWork = new EdgeWork();

  function run(
    op: wasmEngine.Op,
    subject: readonly Polygon[],
    clip: readonly Polygon[],
    rule: wasmEngine.Rule,
  ): ExPolygon[] {
    return engine.booleanAreas(op, subject, clip, rule);
  }

  /** Union of rings with the non-zero rule (overlapping islands merge). */
  function unionRings(rings: readonly Polygon[]): ExPolygon[] {
    return run('union', rings, [], 'nonzero');
  }

  /** Union of rings with the even-odd rule: nested rings alternate solid/hole (raw slice loops). */
  function evenOddAreas(rings: readonly Polygon[]): ExPolygon[] {
    return run('union', rings, [], 'evenodd');
  }

  function union(a: readonly ExPolygon[], b: readonly ExPolygon[] = []): ExPolygon[] {
    return run('union', flatten(a), flatten(b), 'nonzero');
  }

  function difference(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[] {
    if (a.length === 0) return [];
    if (b.length === 0) return a.slice();
    // islands of a strictly inside b leave nothing; islands of b clear of a's bounds cut nothing
    const kept = a.filter((island) => !ringInside(island.outer, b));
    if (kept.length === 0) return [];
    return run('difference', flatten(kept), flatten(touching(b, boundsOf(kept))), 'nonzero');
  }

  function intersection(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[] {
    if (a.length === 0 || b.length === 0) return [];
    // islands of either side clear of the other side's bounds add nothing to the result
    const aIn = touching(a, boundsOf(b));
    if (aIn.length === 0) return [];
    const bIn = touching(b, boundsOf(aIn));
    if (bIn.length === 0) return [];
    return run('intersection', flatten(aIn), flatten(bIn), 'nonzero');
  }

  /** Grow (delta > 0) or shrink (delta < 0) areas by delta µm. */
  function offset(areas: readonly ExPolygon[], deltaUm: number, join: Join = 'miter'): ExPolygon[] {
    if (areas.length === 0) return [];
    if (deltaUm === 0) return areas.slice();
    const rings = flatten(areas);
    const raw =
      join === 'miter' && Math.abs(deltaUm) >= 1 ? rawMiterOffset(rings, deltaUm, MITER_LIMIT, miterWork) : null;
    if (!raw) return engine.inflateAreas(rings, deltaUm, join, 'polygon', MITER_LIMIT, ARC_TOLERANCE_UM);
    const unite = (rings: Pt[][]) => engine.unionDroppingCollinear(rings, 'positive');
    if (raw.loops) return unite(raw.rings);
    // most offsets of a layer's islands stay simple: then they need no union; many islands are taken apart
    if (raw.rings.length > MAX_RINGS && areas.length > 1) return islandsApart(raw.rings, areas, unite, edgeWork);
    // else the union that resolves overlaps of the raw offset, as the general offsetter finishes
    return islandsIfSimple(raw.rings, areas, edgeWork) ?? unite(raw.rings);
  }

  /**
   * What beads `widthUm` wide leave on the layer: the area swept along open polylines and closed loops, µm. With
   * 'round' joins and ends it is the bead's footprint (arcs within ARC_TOLERANCE_UM); 'miter' joins and square ends
   * are much cheaper and add a little at corners and ends (up to (1 - π/4)·(width/2)² each).
   */
  function strokeArea(
    lines: readonly Polyline[],
    loops: readonly Polygon[],
    widthUm: number,
    join: 'round' | 'miter' = 'round',
  ): ExPolygon[] {
    if ((lines.length === 0 && loops.length === 0) || !(widthUm > 0)) return [];
    return engine.strokeAreas(
      lines,
      loops,
      widthUm / 2,
      join,
      join === 'round' ? 'round' : 'square',
      MITER_LIMIT,
      ARC_TOLERANCE_UM,
    );
  }

  /** Clip open polylines to areas: the parts inside. */
  function clipLines(lines: readonly Polyline[], areas: readonly ExPolygon[]): Polyline[] {
    if (lines.length === 0 || areas.length === 0) return [];
    return engine.clipOpen('intersection', lines, flatten(areas));
  }

  /** Clip open polylines to areas: the parts outside. */
  function clipLinesOutside(lines: readonly Polyline[], areas: readonly ExPolygon[]): Polyline[] {
    if (lines.length === 0) return [];
    if (areas.length === 0) return lines.slice();
    return engine.clipOpen('difference', lines, flatten(areas));
  }

  /** Simplify rings: drop vertices closer than toleranceUm to the line through their neighbours. */
  function simplifyRings(rings: readonly Polygon[], toleranceUm: number): Polygon[] {
    return engine.simplifyClosed(rings, toleranceUm).filter((r) => r.length >= 3);
  }

  /** Simplify islands ring by ring; an island whose outer ring falls below three points is dropped, as are such holes. */
  function simplifyAreas(areas: readonly ExPolygon[], toleranceUm: number): ExPolygon[] {
    const s = engine.simplifyClosed(flatten(areas), toleranceUm);
    const res: ExPolygon[] = [];
    let k = 0;
    for (const a of areas) {
      const outer = s[k++];
      const holes = s.slice(k, k + a.holes.length).filter((h) => h.length >= 3);
      k += a.holes.length;
      if (outer.length >= 3) res.push({ outer, holes });
    }
    return res;
  }

  return {
    unionRings,
    evenOddAreas,
    union,
    difference,
    intersection,
    offset,
    strokeArea,
    clipLines,
    clipLinesOutside,
    simplifyRings,
    simplifyAreas,
  };
}

const ops = clipOperations(wasmEngine);
/** Union of rings with the non-zero rule (overlapping islands merge). */
export const unionRings = ops.unionRings;
/** Union of rings with the even-odd rule: nested rings alternate solid/hole (raw slice loops). */
export const evenOddAreas = ops.evenOddAreas;
export const union = ops.union;
export const difference = ops.difference;
export const intersection = ops.intersection;
/** Grow (delta > 0) or shrink (delta < 0) areas by delta µm. */
export const offset = ops.offset;
/** What beads `widthUm` wide leave on the layer (see clipOperations). */
export const strokeArea = ops.strokeArea;
/** Clip open polylines to areas: the parts inside. */
export const clipLines = ops.clipLines;
/** Clip open polylines to areas: the parts outside. */
export const clipLinesOutside = ops.clipLinesOutside;
/** Simplify rings: drop vertices closer than toleranceUm to the line through their neighbours. */
export const simplifyRings = ops.simplifyRings;
/** Simplify islands ring by ring. */
export const simplifyAreas = ops.simplifyAreas;

/** Open-then-close (shrink then grow): removes features narrower than 2·radius µm. */
export function opening(areas: readonly ExPolygon[], radiusUm: number): ExPolygon[] {
  return offset(offset(areas, -radiusUm), radiusUm);
}

/** Close-then-open (grow then shrink): fills gaps and notches narrower than 2·radius µm, joining nearby areas. */
export function closing(areas: readonly ExPolygon[], radiusUm: number): ExPolygon[] {
  return offset(offset(areas, radiusUm), -radiusUm);
}

/** The islands whose outer ring's bounds overlap `box` (all of them, as the same array, when none is clear of it). */
function touching(areas: readonly ExPolygon[], box: Bounds): readonly ExPolygon[] {
  let out: ExPolygon[] | null = null;
  for (let i = 0; i < areas.length; i++) {
    const keep = ringTouches(areas[i].outer, box);
    if (!keep && !out) out = areas.slice(0, i);
    else if (keep && out) out.push(areas[i]);
  }
  return out ?? areas;
}

function ringTouches(ring: readonly Pt[], box: Bounds): boolean {
  const { minX, minY, maxX, maxY } = ringBounds(ring);
  return minX <= box.maxX && maxX >= box.minX && minY <= box.maxY && maxY >= box.minY;
}

/** Signed area of a ring in µm² (positive = counter-clockwise). */
export function ringArea(ring: readonly Pt[]): number {
  let a = 0;
  const n = ring.length;
  for (let i = 0, j = n - 1; i < n; j = i++) a += (ring[j].x + ring[i].x) * (ring[j].y - ring[i].y);
  return -a / 2;
}

/** Area of islands (outer minus holes) in µm². */
export function area(areas: readonly ExPolygon[]): number {
  let a = 0;
  for (const e of areas) {
    a += Math.abs(ringArea(e.outer));
    for (const h of e.holes) a -= Math.abs(ringArea(h));
  }
  return a;
}

export function boundsOf(areas: readonly ExPolygon[]): Bounds {
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (const a of areas) {
    for (const p of a.outer) {
      if (p.x < minX) minX = p.x;
      if (p.y < minY) minY = p.y;
      if (p.x > maxX) maxX = p.x;
      if (p.y > maxY) maxY = p.y;
    }
  }
  return { minX, minY, maxX, maxY };
}

/** Whether a point lies inside a ring (even-odd; contain.ts). */
export { pointInRing };

/** Whether a point lies inside an island (inside the outer ring and in no hole). */
export function pointInArea(p: Pt, a: ExPolygon): boolean {
  if (!pointInRing(p, a.outer)) return false;
  for (const h of a.holes) if (pointInRing(p, h)) return false;
  return true;
}
