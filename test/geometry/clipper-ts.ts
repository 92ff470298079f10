/**
 * The reference clipping engine: the same Clipper2 in TypeScript (clipper2-ts), behind the same functions as
 * clipper-wasm.ts. Nothing loads it in a slice; the tests make clip.ts's operations over it (`clipOperations`) and hold
 * the WebAssembly engine to it.
 */
import { Clipper, Clipper64, ClipperOffset, ClipType, EndType, FillRule, JoinType, PolyTree64 } from 'clipper2-ts';
import type { PolyPath64 } from 'clipper2-ts';
import type { ExPolygon, Polygon, Polyline, Pt } from '#strata/geometry/types.js';
import type { EndKind, JoinKind, Op, Rule } from '#strata/geometry/clipper-wasm.js';

const OPS: Record<Op, ClipType> = {
  union: ClipType.Union,
  difference: ClipType.Difference,
  intersection: ClipType.Intersection,
};
const RULES: Record<Rule, FillRule> = {
  nonzero: FillRule.NonZero,
  evenodd: FillRule.EvenOdd,
  positive: FillRule.Positive,
};
const JOINS: Record<JoinKind, JoinType> = { miter: JoinType.Miter, round: JoinType.Round, square: JoinType.Square };
const ENDS: Record<EndKind, EndType> = {
  polygon: EndType.Polygon,
  joined: EndType.Joined,
  round: EndType.Round,
  square: EndType.Square,
};

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

function islands(tree: PolyTree64): ExPolygon[] {
  const out: ExPolygon[] = [];
  collectTree(tree, out);
  return out;
}

export function booleanAreas(op: Op, subject: readonly Polygon[], clip: readonly Polygon[], rule: Rule): ExPolygon[] {
  const c = new Clipper64();
  if (subject.length) c.addSubject(subject as Polygon[]);
  if (clip.length) c.addClip(clip as Polygon[]);
  const tree = new PolyTree64();
  c.execute(OPS[op], RULES[rule], tree);
  return islands(tree);
}

export function unionDroppingCollinear(rings: readonly Polygon[], rule: Rule): ExPolygon[] {
  const c = new Clipper64();
  c.preserveCollinear = false;
  c.addSubject(rings as Polygon[]);
  const tree = new PolyTree64();
  c.execute(ClipType.Union, RULES[rule], tree);
  return islands(tree);
}

export function clipOpen(
  op: 'intersection' | 'difference',
  lines: readonly Polyline[],
  clip: readonly Polygon[],
): Polyline[] {
  const c = new Clipper64();
  c.addOpenSubject(lines as Polyline[]);
  c.addClip(clip as Polygon[]);
  const closed: Polygon[] = [];
  const open: Polyline[] = [];
  c.execute(OPS[op], FillRule.NonZero, closed, open);
  return open;
}

export function inflateAreas(
  rings: readonly Pt[][],
  delta: number,
  join: JoinKind,
  end: EndKind,
  miterLimit: number,
  arcTolerance: number,
): ExPolygon[] {
  const co = new ClipperOffset(miterLimit, arcTolerance);
  co.addPaths(rings as Pt[][], JOINS[join], ENDS[end]);
  const tree = new PolyTree64();
  co.execute(delta, tree);
  return islands(tree);
}

/** Open polylines (with `lineEnd` ends) and closed loops widened by `delta` on each side, in one offset. */
export function strokeAreas(
  lines: readonly Polyline[],
  loops: readonly Polygon[],
  delta: number,
  join: JoinKind,
  lineEnd: EndKind,
  miterLimit: number,
  arcTolerance: number,
): ExPolygon[] {
  const co = new ClipperOffset(miterLimit, arcTolerance);
  if (lines.length) co.addPaths(lines as Polyline[], JOINS[join], ENDS[lineEnd]);
  if (loops.length) co.addPaths(loops as Polygon[], JOINS[join], EndType.Joined);
  const tree = new PolyTree64();
  co.execute(delta, tree);
  return islands(tree);
}

export function simplifyClosed(rings: readonly Polygon[], epsilon: number): Polygon[] {
  return rings.map((r) => Clipper.simplifyPath(r as Polygon, epsilon, true) as Polygon);
}
