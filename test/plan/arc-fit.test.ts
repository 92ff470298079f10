import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { gcodeToString } from '#strata/gcode/writer.js';
import { SCHEMA, SETTING_KEYS, type Settings } from '#strata/settings/schema.js';
import { fitPlanArcs, fitStepArcs, MAX_ARC_RADIUS_MM, SEGMENT_TOLERANCE_FACTOR } from '#strata/plan/arc-fit.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import { arcLengthMm, filamentPerMm } from '#strata/plan/moves.js';
import type { ExtrudeStep, PrintPlan } from '#strata/plan/types.js';

const TOL = 0.01;

function settings(overrides: Partial<Settings> = {}): Settings {
  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  return { ...(values as Settings), ...overrides };
}

const pt = (x: number, y: number): Pt => ({ x: Math.round(x * 1000), y: Math.round(y * 1000) });
const step = (points: Pt[], closed: boolean, feature: ExtrudeStep['feature'] = 'WALL-OUTER'): ExtrudeStep => ({
  kind: 'extrude',
  feature,
  points,
  closed,
  width: 0.4,
  height: 0.2,
  speed: 40,
  flow: 1,
});
/** n points on a circle (µm-rounded), from angle a0 over `sweep` radians. */
function circle(cx: number, cy: number, r: number, n: number, a0 = 0, sweep = 2 * Math.PI, closed = true): Pt[] {
  const pts: Pt[] = [];
  const count = closed ? n : n + 1;
  for (let i = 0; i < count; i++) {
    const a = a0 + (sweep * i) / n;
    pts.push(pt(cx + r * Math.cos(a), cy + r * Math.sin(a)));
  }
  return pts;
}
const plan = (...steps: ExtrudeStep[]): PrintPlan => ({
  layers: [{ index: 0, z: 0.2, height: 0.2, fan: 0, steps }],
  objects: [],
  bounds: { minX: 0, minY: 0, minZ: 0.2, maxX: 100, maxY: 100, maxZ: 0.2 },
});

/** Distance (mm) from p to the arc's circle. */
function offCircle(p: Pt, arc: { cx: number; cy: number }, r: number): number {
  return Math.abs(Math.hypot(p.x - arc.cx, p.y - arc.cy) - r) / 1000;
}

/** Checks every arc of a fitted step against the original points it replaced. */
function checkAgainst(original: Pt[], fitted: ExtrudeStep): void {
  const path = fitted.closed ? [...fitted.points, fitted.points[0]!] : fitted.points;
  const source = fitted.closed ? [...original, original[0]!] : original;
  let k = 0; // index into source
  for (let i = 1; i < path.length; i++) {
    const from = source.findIndex((p, idx) => idx >= k && p.x === path[i - 1]!.x && p.y === path[i - 1]!.y);
    const to = source.findIndex((p, idx) => idx > from && p.x === path[i]!.x && p.y === path[i]!.y);
    assert.ok(from >= 0 && to > from, 'kept points are original points, in order');
    const arc = fitted.arcs?.[i];
    if (arc) {
      const r = Math.hypot(path[i - 1]!.x - arc.cx, path[i - 1]!.y - arc.cy);
      for (let m = from; m <= to; m++)
        assert.ok(
          offCircle(source[m]!, arc, r) <= TOL + 1e-6,
          `point ${m} off its arc by ${offCircle(source[m]!, arc, r)}`,
        );
      for (let m = from; m < to; m++) {
        const mid = { x: (source[m]!.x + source[m + 1]!.x) / 2, y: (source[m]!.y + source[m + 1]!.y) / 2 };
        assert.ok(offCircle(mid as Pt, arc, r) <= SEGMENT_TOLERANCE_FACTOR * TOL + 1e-6, 'segment middle near the arc');
      }
    } else assert.equal(to, from + 1, 'a line replaces one segment');
    k = to;
  }
}

test('a polygon around a circle becomes a few arcs that pass within the tolerance of every point', () => {
  const original = circle(50, 50, 10, 180);
  const s = step([...original], true);
  const replaced = fitStepArcs(s, TOL);
  assert.equal(replaced, 180, 'every segment replaced');
  assert.ok(s.points.length <= 4, `${s.points.length} arcs`);
  assert.ok(s.arcs!.filter(Boolean).length === s.points.length, 'closing segment is an arc too');
  checkAgainst(original, s);
  // counter-clockwise points give counter-clockwise arcs
  assert.ok(s.arcs!.every((a) => a === undefined || !a.clockwise));
  const cw = step([...original].reverse(), true);
  fitStepArcs(cw, TOL);
  assert.ok(cw.arcs!.filter(Boolean).every((a) => a!.clockwise));
});

test('the arcs carry the same E as the circle within 0.1 %, and parse back to the same path', () => {
  const original = circle(50, 50, 10, 180);
  const lines = plan(step([...original], true));
  const arcs = plan(step([...original], true));
  fitPlanArcs(arcs, TOL);
  const s = settings({ minLayerTime: 0 });
  const eLines = estimatePlan(lines, s).filamentMm;
  const eArcs = estimatePlan(arcs, s).filamentMm;
  assert.ok(Math.abs(eArcs / eLines - 1) < 1e-3, `${eArcs} vs ${eLines}`);
  // the arc's E is exactly its length's: 2πr × E per mm
  const perMm = filamentPerMm(arcs.layers[0]!.steps[0] as ExtrudeStep, s);
  assert.ok(Math.abs(eArcs - 2 * Math.PI * 10 * perMm) < 1e-3);
  const gcode = gcodeToString(arcs, s, estimatePlan(arcs, s), { generator: 't' });
  assert.ok((gcode.match(/^G3 /gm) ?? []).length >= 2);
  const parsed = parseGcode(gcode);
  const layer = parsed.layers.find((l) => Math.abs(l.z - 0.2) < 1e-6)!;
  let e = 0,
    maxOff = 0;
  const t = layer.extrusions;
  for (let i = 0; i < t.count; i++) {
    e += t.e[i]!;
    maxOff = Math.max(maxOff, Math.abs(Math.hypot(t.x1[i]! - 50, t.y1[i]! - 50) - 10));
  }
  assert.ok(Math.abs(e - eArcs) < 1e-3, 'E written = E estimated');
  assert.ok(maxOff < 0.011, `parsed path within tolerance of the circle: ${maxOff}`);
});

test('corners, zig-zags and straight lines stay lines', () => {
  const square = [pt(0, 0), pt(10, 0), pt(10, 10), pt(0, 10)];
  const s1 = step([...square], true);
  assert.equal(fitStepArcs(s1, TOL), 0);
  assert.equal(s1.arcs, undefined);
  const zig: Pt[] = [];
  for (let i = 0; i < 20; i++) zig.push(pt(i % 2 ? 10 : 0, i * 0.4));
  assert.equal(fitStepArcs(step(zig, false, 'SKIN'), TOL), 0, 'skin zig-zag');
  const straight: Pt[] = [];
  for (let i = 0; i < 50; i++) straight.push(pt(i * 0.5, 3));
  assert.equal(fitStepArcs(step(straight, false), TOL), 0, 'collinear points');
  // a hexagon's vertices lie on a circle, but its sides are far from it
  assert.equal(fitStepArcs(step(circle(0, 0, 10, 6), true), TOL), 0, 'hexagon');
  // a nearly straight curve (radius above the largest arc) stays lines
  assert.equal(fitStepArcs(step(circle(0, 0, MAX_ARC_RADIUS_MM * 2, 1000, 0, 0.001, false), false), TOL), 0);
});

test('a rounded rectangle keeps its straight sides and gets arcs at the corners', () => {
  const pts: Pt[] = [];
  const corner = (cx: number, cy: number, a0: number) => {
    for (let i = 0; i <= 12; i++) {
      const a = a0 + (Math.PI / 2) * (i / 12);
      pts.push(pt(cx + 3 * Math.cos(a), cy + 3 * Math.sin(a)));
    }
  };
  corner(37, 3, -Math.PI / 2);
  corner(37, 17, 0);
  corner(3, 17, Math.PI / 2);
  corner(3, 3, Math.PI);
  const original = [...pts];
  const s = step(pts, true);
  fitStepArcs(s, TOL);
  const arcs = s.arcs!.filter(Boolean);
  assert.equal(arcs.length, 4, 'one arc per corner');
  for (const a of arcs) assert.ok(!a!.clockwise);
  assert.equal(s.points.length, 8, 'four arcs and the four straight sides between them');
  checkAgainst(original, s);
});

test('noise beyond the tolerance is not smoothed away', () => {
  const pts = circle(0, 0, 10, 90, 0, Math.PI, false).map((p, i) => (i % 2 ? { x: p.x + 60, y: p.y } : p));
  const original = [...pts];
  const s = step(pts, false);
  fitStepArcs(s, TOL);
  checkAgainst(original, s);
});

test('open arcs of a spiral and of gyroid-like waves fit, and the arc length is the swept angle times the radius', () => {
  const spiral: Pt[] = [];
  for (let i = 0; i <= 400; i++) {
    const a = i * 0.05;
    const r = 2 + a * 0.6;
    spiral.push(pt(50 + r * Math.cos(a), 50 + r * Math.sin(a)));
  }
  const s = step([...spiral], false, 'FILL');
  const replaced = fitStepArcs(s, TOL);
  assert.ok(replaced > 350, `spiral: ${replaced} segments in arcs`);
  checkAgainst(spiral, s);
  const wave: Pt[] = [];
  for (let i = 0; i <= 300; i++) wave.push(pt(i * 0.1, 5 * Math.sin(i * 0.02)));
  const w = step([...wave], false, 'FILL');
  assert.ok(fitStepArcs(w, TOL) > 250);
  checkAgainst(wave, w);
  // quarter circle of radius 10: length 5π
  assert.ok(Math.abs(arcLengthMm(10000, 0, 0, 10000, 0, 0, false) - 5 * Math.PI) < 1e-9);
  assert.ok(Math.abs(arcLengthMm(0, 10000, 10000, 0, 0, 0, true) - 5 * Math.PI) < 1e-9);
  assert.ok(Math.abs(arcLengthMm(10000, 0, 0, 10000, 0, 0, true) - 15 * Math.PI) < 1e-9, 'the long way round');
});

test('arc fitting is deterministic and only runs when asked', () => {
  const a = plan(step(circle(20, 20, 5, 100), true));
  const b = plan(step(circle(20, 20, 5, 100), true));
  fitPlanArcs(a, TOL);
  fitPlanArcs(b, TOL);
  assert.deepEqual(a, b);
  const s = step(circle(20, 20, 5, 100), true);
  fitStepArcs(s, TOL);
  assert.equal(fitStepArcs(s, TOL), 0, 'a fitted step is left alone');
});
