import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { ExPolygon, Polyline, Pt } from '#strata/geometry/types.js';
import { monotonicFill } from '#strata/infill/monotonic.js';
import { solidFill } from '#strata/infill/solid-fill.js';
import { measuredDensity } from '#strata/infill/measure.js';
import { hull, SHAPE_CENTRE, square, TEST_SHAPES } from './test-shapes.js';
import { monotonicViolations, type Segment } from './test-monotonic.js';

const W = 450;

function segments(lines: readonly Polyline[]): Segment[] {
  const out: Segment[] = [];
  for (const l of lines)
    for (let i = 1; i < l.length; i++) out.push({ x0: l[i - 1].x, y0: l[i - 1].y, x1: l[i].x, y1: l[i].y });
  return out;
}

/** A square with a round hole in its middle (the hole splits every row that crosses it in two). */
function squareWithHole(): ExPolygon[] {
  const hole: Pt[] = [];
  for (let i = 0; i < 64; i++) {
    const a = (-2 * Math.PI * i) / 64;
    hole.push({
      x: Math.round(SHAPE_CENTRE.x + 6000 * Math.cos(a)),
      y: Math.round(SHAPE_CENTRE.y + 6000 * Math.sin(a)),
    });
  }
  return [{ outer: square()[0].outer, holes: [hole] }];
}

/** A comb (a square with four V notches from the top) and a square beside it: rows that split and end. */
function comb(): ExPolygon[] {
  const c = SHAPE_CENTRE;
  const outer: Pt[] = [
    { x: c.x - 15000, y: c.y - 15000 },
    { x: c.x + 15000, y: c.y - 15000 },
    { x: c.x + 15000, y: c.y + 15000 },
  ];
  // four V notches down from the top edge
  for (let t = 3; t >= 0; t--) {
    const x = c.x - 15000 + t * 7500;
    outer.push({ x: x + 3750, y: c.y - 5000 }, { x, y: c.y + 15000 });
  }
  return [{ outer, holes: [] }, ...square(8000, { x: c.x + 40000, y: c.y })];
}

const REGIONS: Record<string, () => ExPolygon[]> = {
  ...TEST_SHAPES,
  'square with a hole': squareWithHole,
  hull: () => hull(),
  comb,
};

test('monotonic fill never lays a line between two lines already printed, at any angle', () => {
  for (const [name, make] of Object.entries(REGIONS)) {
    for (const angle of [0, 45, 90, 135, 17]) {
      const lines = monotonicFill(make(), angle, W, SHAPE_CENTRE);
      const r = monotonicViolations(segments(lines), angle, W, 2 * W);
      assert.ok(r.lines > 20, `${name} at ${angle}°: ${r.lines} lines checked`);
      assert.equal(
        r.violations,
        0,
        `${name} at ${angle}°: ${r.violations} of ${r.lines} lines laid between printed ones`,
      );
    }
  }
});

test('the check finds what nearest-first lines do wrong around a hole', () => {
  // the rule is not trivially met: ordinary zig-zag lines, ordered nearest-first, break it here
  let broken = 0;
  for (const angle of [0, 45, 90])
    broken += monotonicViolations(
      segments(solidFill(squareWithHole(), angle, W, SHAPE_CENTRE)),
      angle,
      W,
      2 * W,
    ).violations;
  broken += monotonicViolations(segments(solidFill(comb(), 90, W, SHAPE_CENTRE)), 90, W, 2 * W).violations;
  assert.ok(broken > 0, 'nearest-first lines break the monotonic rule somewhere');
});

test('monotonic fill lays the same lines as solid fill, joined along the boundary where neighbours meet', () => {
  for (const [name, make] of Object.entries(REGIONS)) {
    const region = make();
    const mono = monotonicFill(region, 45, W, SHAPE_CENTRE);
    const raw = solidFill(region, 45, W, SHAPE_CENTRE, { connect: false });
    const along = (lines: Polyline[]) => {
      const r = monotonicViolations(segments(lines), 45, W, 0);
      return r.lines;
    };
    assert.equal(along(mono), along(raw), `${name}: every piece once`);
    // joined: far fewer paths than pieces in a region without many splits
    assert.ok(mono.length < raw.length / 3, `${name}: ${mono.length} paths for ${raw.length} pieces`);
    const d = measuredDensity({ lines: mono, loops: [] }, region, W);
    assert.ok(d > 0.95 && d < 1.1, `${name}: covers ${d.toFixed(3)}`);
  }
});

test('a convex region is one back-and-forth path; the output is the same every time', () => {
  const lines = monotonicFill(square(), 30, W, SHAPE_CENTRE);
  assert.equal(lines.length, 1);
  assert.deepEqual(
    monotonicFill(squareWithHole(), 45, W, SHAPE_CENTRE),
    monotonicFill(squareWithHole(), 45, W, SHAPE_CENTRE),
  );
  assert.deepEqual(monotonicFill([], 45, W, SHAPE_CENTRE), []);
});
