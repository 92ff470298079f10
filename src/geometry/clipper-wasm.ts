/**
 * The clipping engine: Clipper2 compiled to WebAssembly (clipper2-wasm), loaded once per thread, and the
 * conversion of plain rings to and from it. Only the facade (`clip.ts`) uses this module.
 *
 * Coordinates cross as doubles with precision 0 (the engine's scale 1): integer micrometres stay exact
 * in both directions, and every point the engine makes is rounded to an integer. Rings go in through one
 * typed staging buffer and one engine path, and come back through views of the engine's memory; every
 * engine object made for a call is deleted before it returns, so the engine's heap does not grow.
 *
 * Module state, and why it is no state a slice could see: the engine (one WebAssembly instance per thread,
 * loaded once with this module), the few engine objects made with it below (path lists, a result tree,
 * two clippers) and the staging buffer rings cross in through. Every call here is synchronous, leaves those
 * objects empty and overwrites the buffer before reading it, so they carry nothing from one call to the next:
 * they are part of the instance, cached with it so that no call pays for making them.
 */
import Clipper2Z from 'clipper2-wasm/dist/es/clipper2z.js';
import type {
  ClipType,
  EndType,
  FillRule,
  JoinType,
  MainModule,
  PathD,
  PathsD,
  PolyPathD,
} from 'clipper2-wasm/dist/clipper2z.js';
import type { ExPolygon, Polygon, Polyline, Pt } from './types.js';
import { nestRings } from './nest-rings.js';

/** The engine's scale as decimal places: 0 keeps integer micrometres integer. */
const PRECISION = 0;

const C: MainModule = await Clipper2Z();

export type Op = 'union' | 'difference' | 'intersection';
export type Rule = 'nonzero' | 'evenodd' | 'positive';
export type JoinKind = 'miter' | 'round' | 'square';
export type EndKind = 'polygon' | 'joined' | 'round' | 'square';

const OPS: Record<Op, ClipType> = {
  union: C.ClipType.Union,
  difference: C.ClipType.Difference,
  intersection: C.ClipType.Intersection,
};
const RULES: Record<Rule, FillRule> = {
  nonzero: C.FillRule.NonZero,
  evenodd: C.FillRule.EvenOdd,
  positive: C.FillRule.Positive,
};
const JOINS: Record<JoinKind, JoinType> = {
  miter: C.JoinType.Miter,
  round: C.JoinType.Round,
  square: C.JoinType.Square,
};
const ENDS: Record<EndKind, EndType> = {
  polygon: C.EndType.Polygon,
  joined: C.EndType.Joined,
  round: C.EndType.Round,
  square: C.EndType.Square,
};

// The engine objects every call uses (see the file comment): each call leaves them empty.
const scratchPath: PathD = new C.PathD();
const subjects: PathsD = new C.PathsD();
const clips: PathsD = new C.PathsD();
const tree: PolyPathD = new C.PolyPathD();
const keepCollinear = new C.ClipperD(PRECISION);
const dropCollinear = new C.ClipperD(PRECISION);
dropCollinear.SetPreserveCollinear(false);
/** The staging buffer (see the file comment): x, y, z triplets (z stays 0), the layout the engine's paths take in bulk. */
let coords = new Float64Array(3 * 1024);

/** Copy rings into an engine path list (cleared first). */
function load(into: PathsD, rings: readonly (readonly Pt[])[]): PathsD {
  into.clear();
  for (const r of rings) {
    const n = r.length;
    if (coords.length < 3 * n) coords = new Float64Array(Math.max(3 * n, 2 * coords.length));
    for (let i = 0, k = 0; i < n; i++, k += 3) {
      const p = r[i];
      coords[k] = p.x;
      coords[k + 1] = p.y;
    }
    scratchPath.assign(coords.subarray(0, 3 * n));
    into.push_back(scratchPath);
  }
  return into;
}

/** A ring from an engine path (a copy the caller deletes, or one it owns). */
function readPath(path: PathD): Pt[] {
  const v = path.view();
  const n = v.length / 3;
  const out: Pt[] = [];
  for (let i = 0, k = 0; i < n; i++, k += 3) out.push({ x: Math.round(v[k]), y: Math.round(v[k + 1]) });
  return out;
}

/** Every path of an engine path list, through the engine's objects (one per path). */
function readPathsByHandle(paths: PathsD, minPoints: number): Pt[][] {
  const out: Pt[][] = [];
  const n = paths.size();
  for (let i = 0; i < n; i++) {
    const p = paths.get(i); // a copy
    if (p.size() >= minPoints) out.push(readPath(p));
    p.delete();
  }
  return out;
}

/** The islands of a result tree through the engine's objects, in the facade's order (islands inside a hole before their host). */
function readTreeByHandle(node: PolyPathD, out: ExPolygon[]): void {
  const n = node.count();
  for (let i = 0; i < n; i++) {
    const outerNode = node.child(i); // owned by the tree: never deleted here
    const holes: Polygon[] = [];
    const m = outerNode.count();
    for (let j = 0; j < m; j++) {
      const holeNode = outerNode.child(j);
      const hp = holeNode.polygon();
      holes.push(readPath(hp));
      hp.delete();
      readTreeByHandle(holeNode, out);
    }
    const op = outerNode.polygon();
    out.push({ outer: readPath(op), holes });
    op.delete();
  }
}

/*
 * Reading results straight from the engine's memory. Every engine object handed to JavaScript costs about
 * a microsecond to make (and a finaliser to register), and a result tree needs two per ring: on a slice with
 * tree support that was 50 ms of handles. The layouts below are those of clipper2-wasm 0.4.0 (wasm32, libc++),
 * the exact version package.json names; `directReadsAgree` checks them at load against the object interface
 * and the handle path is used instead if they ever differ.
 *   std::vector<T>: begin, end, capacity (three 32-bit pointers);
 *   PointD: x, y (doubles), z (64-bit): 24 bytes;
 *   PolyPathD: vtable, parent, children (vector of pointers) at byte 8, scale (double) at 24, polygon (vector of PointD) at 32.
 */
const POINT_BYTES = 24;
const CHILDREN_AT = 8;
const POLYGON_AT = 32;

/** The engine's memory, as words and as doubles. */
interface Heap {
  u32: Uint32Array<ArrayBufferLike>;
  f64: Float64Array<ArrayBufferLike>;
}

/** Where an engine object lives in the engine's memory (embind keeps it on every handle). */
function addressOf(handle: PathsD | PolyPathD): number {
  return (handle as unknown as { $$: { ptr: number } }).$$.ptr;
}

// Views of the engine's memory, part of the instance cache (see the file comment): they show only the engine's
// own memory, and are made again when it has grown (its buffer is then a new one).
let heapBuffer: ArrayBufferLike | undefined;
let heap: Heap = { u32: new Uint32Array(0), f64: new Float64Array(0) };

/** Views of the engine's memory as it is now (it may grow between calls, and its buffer with it). */
function heapViews(): Heap {
  const buffer = (C as unknown as { HEAPU8: Uint8Array }).HEAPU8.buffer;
  if (buffer !== heapBuffer) {
    heapBuffer = buffer;
    heap = { u32: new Uint32Array(buffer), f64: new Float64Array(buffer) };
  }
  return heap;
}

/** The ring held by a vector of points at byte `at`. */
function ringAt({ u32, f64 }: Heap, at: number): Pt[] {
  const begin = u32[at >>> 2];
  const n = (u32[(at >>> 2) + 1] - begin) / POINT_BYTES;
  const out: Pt[] = [];
  for (let i = 0, k = begin >>> 3; i < n; i++, k += 3) out.push({ x: Math.round(f64[k]), y: Math.round(f64[k + 1]) });
  return out;
}

function readPathsDirect(paths: PathsD, minPoints: number): Pt[][] {
  const heap = heapViews();
  const u32 = heap.u32;
  const at = addressOf(paths) >>> 2;
  const out: Pt[][] = [];
  for (let v = u32[at], end = u32[at + 1]; v < end; v += 12) {
    const n = (u32[(v >>> 2) + 1] - u32[v >>> 2]) / POINT_BYTES;
    if (n >= minPoints) out.push(ringAt(heap, v));
  }
  return out;
}

function readTreeFrom(heap: Heap, node: number, out: ExPolygon[]): void {
  const u32 = heap.u32;
  for (let c = u32[(node + CHILDREN_AT) >>> 2], end = u32[(node + CHILDREN_AT + 4) >>> 2]; c < end; c += 4) {
    const outer = u32[c >>> 2];
    const holes: Polygon[] = [];
    for (let h = u32[(outer + CHILDREN_AT) >>> 2], hEnd = u32[(outer + CHILDREN_AT + 4) >>> 2]; h < hEnd; h += 4) {
      const hole = u32[h >>> 2];
      holes.push(ringAt(heap, hole + POLYGON_AT));
      readTreeFrom(heap, hole, out);
    }
    out.push({ outer: ringAt(heap, outer + POLYGON_AT), holes });
  }
}

function readTreeDirect(node: PolyPathD, out: ExPolygon[]): void {
  readTreeFrom(heapViews(), addressOf(node), out);
}

/** Whether reading memory gives what the object interface gives, on a tree with a hole and an island in it. */
function directReadsAgree(): boolean {
  try {
    const square = (c: number, r: number): Pt[] => [
      { x: c - r, y: c - r },
      { x: c + r, y: c - r },
      { x: c + r, y: c + r },
      { x: c - r, y: c + r },
    ];
    C.BooleanOpOutD(
      OPS.union,
      RULES.evenodd,
      load(subjects, [square(0, 100), square(0, 60), square(0, 20), square(300, 7)]),
      load(clips, []),
      tree,
      PRECISION,
    );
    const byHandle: ExPolygon[] = [];
    const direct: ExPolygon[] = [];
    readTreeByHandle(tree, byHandle);
    readTreeDirect(tree, direct);
    tree.clear();
    const res = C.InflatePathsD(subjects, 5, JOINS.miter, ENDS.polygon, 2, PRECISION, 0.25);
    const a = readPathsByHandle(res, 0);
    const b = readPathsDirect(res, 0);
    res.delete();
    subjects.clear();
    clips.clear();
    return (
      byHandle.length === 3 &&
      a.length === 2 &&
      JSON.stringify(byHandle) === JSON.stringify(direct) &&
      JSON.stringify(a) === JSON.stringify(b)
    );
  } catch {
    return false;
  }
}

/** Whether results are read from memory (true unless the layouts above stopped matching). */
export const DIRECT = directReadsAgree();
const readTree = DIRECT ? readTreeDirect : readTreeByHandle;

/** Every path of an engine path list, which is then deleted. */
function readPaths(paths: PathsD, minPoints: number): Pt[][] {
  const out = DIRECT ? readPathsDirect(paths, minPoints) : readPathsByHandle(paths, minPoints);
  paths.delete();
  return out;
}

function takeTree(): ExPolygon[] {
  const out: ExPolygon[] = [];
  readTree(tree, out);
  tree.clear();
  return out;
}

/** A boolean of closed rings, as islands (outer rings counter-clockwise, holes clockwise). */
export function booleanAreas(op: Op, subject: readonly Polygon[], clip: readonly Polygon[], rule: Rule): ExPolygon[] {
  C.BooleanOpOutD(OPS[op], RULES[rule], load(subjects, subject), load(clips, clip), tree, PRECISION);
  subjects.clear();
  clips.clear();
  return takeTree();
}

/** The union of rings with collinear points removed (the clean-up union of a raw offset). */
export function unionDroppingCollinear(rings: readonly Polygon[], rule: Rule): ExPolygon[] {
  dropCollinear.AddSubject(load(subjects, rings));
  subjects.clear();
  dropCollinear.ExecutePoly(OPS.union, RULES[rule], tree);
  dropCollinear.Clear();
  return takeTree();
}

/** Open polylines clipped against closed rings (non-zero): the parts inside (intersection) or outside (difference). */
export function clipOpen(
  op: 'intersection' | 'difference',
  lines: readonly Polyline[],
  clip: readonly Polygon[],
): Polyline[] {
  keepCollinear.AddOpenSubject(load(subjects, lines));
  keepCollinear.AddClip(load(clips, clip));
  subjects.clear();
  clips.clear();
  const closed = new C.PathsD();
  const open = new C.PathsD();
  keepCollinear.ExecutePath(OPS[op], RULES.nonzero, closed, open);
  keepCollinear.Clear();
  closed.delete();
  return readPaths(open, 2);
}

/** Rings grown (delta > 0) or shrunk by delta, as flat rings: outer rings counter-clockwise, holes clockwise. */
export function inflateRings(
  rings: readonly Pt[][],
  delta: number,
  join: JoinKind,
  end: EndKind,
  miterLimit: number,
  arcTolerance: number,
): Polygon[] {
  const res = C.InflatePathsD(
    load(subjects, rings),
    delta,
    JOINS[join],
    ENDS[end],
    miterLimit,
    PRECISION,
    arcTolerance,
  );
  subjects.clear();
  return readPaths(res, 3);
}

/** Offset rings as islands. */
export function inflateAreas(
  rings: readonly Pt[][],
  delta: number,
  join: JoinKind,
  end: EndKind,
  miterLimit: number,
  arcTolerance: number,
): ExPolygon[] {
  return nestRings(inflateRings(rings, delta, join, end, miterLimit, arcTolerance));
}

/**
 * The area swept by open polylines (with `lineEnd` ends) and closed loops, widened by `delta` on each
 * side, as islands: the two offsets are made apart (the engine takes one end type per call) and united.
 */
export function strokeAreas(
  lines: readonly Polyline[],
  loops: readonly Polygon[],
  delta: number,
  join: JoinKind,
  lineEnd: EndKind,
  miterLimit: number,
  arcTolerance: number,
): ExPolygon[] {
  if (lines.length === 0 || loops.length === 0) {
    return lines.length
      ? inflateAreas(lines, delta, join, lineEnd, miterLimit, arcTolerance)
      : inflateAreas(loops, delta, join, 'joined', miterLimit, arcTolerance);
  }
  const a = C.InflatePathsD(
    load(subjects, lines),
    delta,
    JOINS[join],
    ENDS[lineEnd],
    miterLimit,
    PRECISION,
    arcTolerance,
  );
  const b = C.InflatePathsD(
    load(subjects, loops),
    delta,
    JOINS[join],
    ENDS.joined,
    miterLimit,
    PRECISION,
    arcTolerance,
  );
  subjects.clear();
  C.BooleanOpOutD(OPS.union, RULES.nonzero, a, b, tree, PRECISION);
  a.delete();
  b.delete();
  return takeTree();
}

/** Each ring simplified (closed): vertices closer than epsilon to the line through their neighbours dropped. */
export function simplifyClosed(rings: readonly Polygon[], epsilon: number): Polygon[] {
  const res = C.SimplifyPathsD(load(subjects, rings), epsilon, true);
  subjects.clear();
  return readPaths(res, 0);
}
