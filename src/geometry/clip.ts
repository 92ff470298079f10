/**
 * The thin geometry facade: union, difference, intersection, offset and open-path clipping over
 * Clipper2, in integer micrometres. Nothing else in Strata imports the clipping library. The engine is
 * Clipper2 compiled to WebAssembly (clipper2-wasm, see clipper-wasm.ts): on 3DBenchy a slice took 0.79 ×
 * the wall time of the same library in TypeScript (clipper2-ts), which stays as the reference engine the
 * tests hold the WebAssembly one against (`setClipBackend`).
 */
import {
  Clipper64,
  ClipperOffset,
  ClipType,
  EndType,
  FillRule,
  JoinType,
  PolyTree64,
  Clipper,
} from 'clipper2-ts';
import type { PolyPath64 } from 'clipper2-ts';
import type { Bounds, ExPolygon, Polygon, Polyline, Pt } from './types.js';
import { rawMiterOffset } from './miter-offset.js';
import { ringBounds, ringInside } from './contain.js';
import { islandsIfSimple } from './simple-rings.js';
import * as W from './clipper-wasm.js';

/** Which engine runs the clipping: an internal switch for tests and measurements, not part of the API. */
let backend: 'ts' | 'wasm' = 'wasm';
export function setClipBackend(b: 'ts' | 'wasm'): void {
  backend = b;
}

export type Join = 'miter' | 'round' | 'square';

/** Arc tolerance for round joins, µm: chord error allowed when offsetting curves. */
const ARC_TOLERANCE_UM = 5;
const MITER_LIMIT = 3;

function joinType(join: Join): JoinType {
  return join === 'round' ? JoinType.Round : join === 'square' ? JoinType.Square : JoinType.Miter;
}

/** Rings of a list of islands, as one flat list for the clipper (outer CCW, holes CW). */
export function flatten(areas: readonly ExPolygon[]): Polygon[] {
  const out: Polygon[] = [];
  for (const a of areas) {
    out.push(a.outer);
    for (const h of a.holes) out.push(h);
  }
  return out;
}

function collectTree(node: PolyPath64, out: ExPolygon[]): void {
  for (let i = 0; i < node.count; i++) {
    const outer = node.child(i) as PolyPath64;
    const holes: Polygon[] = [];
    for (let j = 0; j < outer.count; j++) {
      const hole = outer.child(j) as PolyPath64;
      holes.push(hole.poly as Polygon);
      collectTree(hole, out);
    }
    out.push({ outer: outer.poly as Polygon, holes });
  }
}

function run(type: ClipType, subject: readonly Polygon[], clip: readonly Polygon[], rule: FillRule): ExPolygon[] {
  if (backend === 'wasm') {
    const op = type === ClipType.Union ? 'union' : type === ClipType.Difference ? 'difference' : 'intersection';
    return W.booleanAreas(op, subject, clip, rule === FillRule.EvenOdd ? 'evenodd' : 'nonzero');
  }
  const c = new Clipper64();
  if (subject.length) c.addSubject(subject as Polygon[]);
  if (clip.length) c.addClip(clip as Polygon[]);
  const tree = new PolyTree64();
  c.execute(type, rule, tree);
  const out: ExPolygon[] = [];
  collectTree(tree, out);
  return out;
}

/** Union of rings with the non-zero rule (overlapping islands merge). */
export function unionRings(rings: readonly Polygon[]): ExPolygon[] {
  return run(ClipType.Union, rings, [], FillRule.NonZero);
}

/** Union of rings with the even-odd rule: nested rings alternate solid/hole (raw slice loops). */
export function evenOddAreas(rings: readonly Polygon[]): ExPolygon[] {
  return run(ClipType.Union, rings, [], FillRule.EvenOdd);
}

export function union(a: readonly ExPolygon[], b: readonly ExPolygon[] = []): ExPolygon[] {
  return run(ClipType.Union, flatten(a), flatten(b), FillRule.NonZero);
}

export function difference(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[] {
  if (a.length === 0) return [];
  if (b.length === 0) return a.slice();
  // islands of a strictly inside b leave nothing; islands of b clear of a's bounds cut nothing
  const kept = a.filter((island) => !ringInside(island.outer, b));
  if (kept.length === 0) return [];
  return run(ClipType.Difference, flatten(kept), flatten(touching(b, boundsOf(kept))), FillRule.NonZero);
}

export function intersection(a: readonly ExPolygon[], b: readonly ExPolygon[]): ExPolygon[] {
  if (a.length === 0 || b.length === 0) return [];
  // islands of either side clear of the other side's bounds add nothing to the result
  const aIn = touching(a, boundsOf(b));
  if (aIn.length === 0) return [];
  const bIn = touching(b, boundsOf(aIn));
  if (bIn.length === 0) return [];
  return run(ClipType.Intersection, flatten(aIn), flatten(bIn), FillRule.NonZero);
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

/** Grow (delta > 0) or shrink (delta < 0) areas by delta µm. */
export function offset(areas: readonly ExPolygon[], deltaUm: number, join: Join = 'miter'): ExPolygon[] {
  if (areas.length === 0) return [];
  if (deltaUm === 0) return areas.slice();
  const rings = flatten(areas);
  const tree = new PolyTree64();
  const raw = join === 'miter' && Math.abs(deltaUm) >= 1 ? rawMiterOffset(rings, deltaUm, MITER_LIMIT) : null;
  if (raw) {
    // most offsets of a layer's islands stay simple: then they need no union
    const simple = raw.loops ? null : islandsIfSimple(raw.rings, areas);
    if (simple) return simple;
    if (backend === 'wasm') return W.unionDroppingCollinear(raw.rings, 'positive');
    // the union that resolves overlaps of the raw offset, as the general offsetter finishes
    const c = new Clipper64();
    c.preserveCollinear = false;
    c.addSubject(raw.rings);
    c.execute(ClipType.Union, FillRule.Positive, tree);
  } else if (backend === 'wasm') {
    return W.inflateAreas(rings, deltaUm, join, 'polygon', MITER_LIMIT, ARC_TOLERANCE_UM);
  } else {
    const co = new ClipperOffset(MITER_LIMIT, ARC_TOLERANCE_UM);
    co.addPaths(rings, joinType(join), EndType.Polygon);
    co.execute(deltaUm, tree);
  }
  const out: ExPolygon[] = [];
  collectTree(tree, out);
  return out;
}

/**
 * What beads `widthUm` wide leave on the layer: the area swept along open polylines and closed loops, µm. With
 * 'round' joins and ends it is the bead's footprint (arcs within ARC_TOLERANCE_UM); 'miter' joins and square ends
 * are much cheaper and add a little at corners and ends (up to (1 - π/4)·(width/2)² each).
 */
export function strokeArea(
  lines: readonly Polyline[], loops: readonly Polygon[], widthUm: number, join: 'round' | 'miter' = 'round',
): ExPolygon[] {
  if ((lines.length === 0 && loops.length === 0) || !(widthUm > 0)) return [];
  if (backend === 'wasm') return W.strokeAreas(lines, loops, widthUm / 2, join, join === 'round' ? 'round' : 'square', MITER_LIMIT, ARC_TOLERANCE_UM);
  const co = new ClipperOffset(MITER_LIMIT, ARC_TOLERANCE_UM);
  const jt = joinType(join);
  if (lines.length) co.addPaths(lines as Polyline[], jt, join === 'round' ? EndType.Round : EndType.Square);
  if (loops.length) co.addPaths(loops as Polygon[], jt, EndType.Joined);
  const tree = new PolyTree64();
  co.execute(widthUm / 2, tree);
  const out: ExPolygon[] = [];
  collectTree(tree, out);
  return out;
}

/** Open-then-close (shrink then grow): removes features narrower than 2·radius µm. */
export function opening(areas: readonly ExPolygon[], radiusUm: number): ExPolygon[] {
  return offset(offset(areas, -radiusUm), radiusUm);
}

/** Close-then-open (grow then shrink): fills gaps and notches narrower than 2·radius µm, joining nearby areas. */
export function closing(areas: readonly ExPolygon[], radiusUm: number): ExPolygon[] {
  return offset(offset(areas, radiusUm), -radiusUm);
}

/** Clip open polylines to areas: the parts inside. */
export function clipLines(lines: readonly Polyline[], areas: readonly ExPolygon[]): Polyline[] {
  if (lines.length === 0 || areas.length === 0) return [];
  if (backend === 'wasm') return W.clipOpen('intersection', lines, flatten(areas));
  const c = new Clipper64();
  c.addOpenSubject(lines as Polyline[]);
  c.addClip(flatten(areas));
  const closed: Polygon[] = [];
  const open: Polyline[] = [];
  c.execute(ClipType.Intersection, FillRule.NonZero, closed, open);
  return open;
}

/** Clip open polylines to areas: the parts outside. */
export function clipLinesOutside(lines: readonly Polyline[], areas: readonly ExPolygon[]): Polyline[] {
  if (lines.length === 0) return [];
  if (areas.length === 0) return lines.slice();
  if (backend === 'wasm') return W.clipOpen('difference', lines, flatten(areas));
  const c = new Clipper64();
  c.addOpenSubject(lines as Polyline[]);
  c.addClip(flatten(areas));
  const closed: Polygon[] = [];
  const open: Polyline[] = [];
  c.execute(ClipType.Difference, FillRule.NonZero, closed, open);
  return open;
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

/** Simplify rings: drop vertices closer than toleranceUm to the line through their neighbours. */
export function simplifyRings(rings: readonly Polygon[], toleranceUm: number): Polygon[] {
  if (backend === 'wasm') return W.simplifyClosed(rings, toleranceUm).filter((s) => s.length >= 3);
  const out: Polygon[] = [];
  for (const r of rings) {
    const s = Clipper.simplifyPath(r as Polygon, toleranceUm, true) as Polygon;
    if (s.length >= 3) out.push(s);
  }
  return out;
}

export function simplifyAreas(areas: readonly ExPolygon[], toleranceUm: number): ExPolygon[] {
  if (backend === 'wasm') {
    const s = W.simplifyClosed(flatten(areas), toleranceUm);
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
  const out: ExPolygon[] = [];
  for (const a of areas) {
    const outer = Clipper.simplifyPath(a.outer, toleranceUm, true) as Polygon;
    if (outer.length < 3) continue;
    const holes = simplifyRings(a.holes, toleranceUm);
    out.push({ outer, holes });
  }
  return out;
}

export function boundsOf(areas: readonly ExPolygon[]): Bounds {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
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

/** Whether a point lies inside a ring (even-odd; on-edge counts as inside). */
export function pointInRing(p: Pt, ring: readonly Pt[]): boolean {
  let inside = false;
  const n = ring.length;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const a = ring[i], b = ring[j];
    if ((a.y > p.y) !== (b.y > p.y)) {
      const x = a.x + ((p.y - a.y) * (b.x - a.x)) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

/** Whether a point lies inside an island (inside the outer ring and in no hole). */
export function pointInArea(p: Pt, a: ExPolygon): boolean {
  if (!pointInRing(p, a.outer)) return false;
  for (const h of a.holes) if (pointInRing(p, h)) return false;
  return true;
}

