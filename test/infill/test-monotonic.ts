/**
 * Test helper: checks the monotonic rule on printed lines. Of segments in print order, those that run along
 * a family of parallel lines (within a degree of its direction and at least `minLength` long) are put in
 * rows across the family, `spacing` apart; a segment breaks the rule when, as it is laid, lines already
 * printed lie beside it on both sides: in the row before and in the row after, overlapping it along the
 * lines. Units are the caller's (µm or mm), the same for all arguments.
 */

export interface Segment {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

export interface MonotonicReport {
  /** Segments along the family that were checked. */
  lines: number;
  /** Segments laid between two lines already printed. */
  violations: number;
}

export function monotonicViolations(
  segments: readonly Segment[],
  angleDeg: number,
  spacing: number,
  minLength: number,
): MonotonicReport {
  const a = (angleDeg * Math.PI) / 180;
  const c = Math.cos(a),
    s = Math.sin(a);
  const along: Array<{ v: number; lo: number; hi: number }> = [];
  for (const g of segments) {
    const dx = g.x1 - g.x0,
      dy = g.y1 - g.y0;
    const len = Math.hypot(dx, dy);
    if (len < minLength) continue;
    // within a degree of the family's direction, either way along it
    if (Math.abs(dx * c + dy * s) < len * Math.cos(Math.PI / 180)) continue;
    const u0 = g.x0 * c + g.y0 * s,
      u1 = g.x1 * c + g.y1 * s;
    along.push({ v: -g.x0 * s + g.y0 * c, lo: Math.min(u0, u1), hi: Math.max(u0, u1) });
  }
  if (along.length === 0) return { lines: 0, violations: 0 };
  const vMin = Math.min(...along.map((l) => l.v));
  const printed = new Map<number, Array<{ lo: number; hi: number }>>();
  const beside = (row: number, lo: number, hi: number) =>
    (printed.get(row) ?? []).some((p) => Math.min(p.hi, hi) - Math.max(p.lo, lo) > spacing / 2);
  let violations = 0;
  for (const l of along) {
    const row = Math.round((l.v - vMin) / spacing);
    if (beside(row - 1, l.lo, l.hi) && beside(row + 1, l.lo, l.hi)) violations++;
    const list = printed.get(row) ?? [];
    list.push({ lo: l.lo, hi: l.hi });
    printed.set(row, list);
  }
  return { lines: along.length, violations };
}
