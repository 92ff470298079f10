import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { Z_SPEED_MM_S } from '#strata/plan/moves.js';
import { estimatePlan, pointToPointSeconds, segmentSeconds, type EstimateSettings } from '#strata/plan/estimate.js';
import { MINIMUM_PLANNER_SPEED, trapezoidSeconds } from '#strata/plan/marlin-planner.js';
import type { ExtrudeStep, LayerPlan, PlanStep, PrintPlan, TravelStep } from '#strata/plan/types.js';

const S: EstimateSettings = {
  maxSpeed: 300,
  filamentDiameter: 1.75,
  flowRate: 100,
  retractionEnabled: true,
  retractionDistance: 5,
  retractionSpeed: 45,
  retractionExtraPrime: 0,
  travelSpeed: 150,
  firstLayerTravelSpeed: 100,
  acceleration: 500,
  cornerVelocity: 8,
  filamentDensity: 1.24,
  firmwareRetraction: false,
  machineLimits: 'estimate',
  maxSpeedX: null,
  maxSpeedY: null,
  maxSpeedZ: null,
  maxSpeedE: null,
  maxAccelerationX: null,
  maxAccelerationY: null,
  maxAccelerationZ: null,
  maxAccelerationE: null,
  travelAcceleration: null,
  retractAcceleration: null,
  gcodeFlavor: 'marlin',
  minimumCruiseRatio: 0.5,
  nozzleDiameter: 0.4,
  zHopSpeed: null,
  wipeDistance: 0,
  retractBeforeWipe: 0,
  coastingVolume: 0,
  coastingMinVolume: 0.8,
  jerkX: null,
  jerkY: null,
  jerkZ: null,
  jerkE: null,
  junctionDeviation: null,
  startGcode: '',
};

const pt = (xMm: number, yMm: number): Pt => ({ x: Math.round(xMm * 1000), y: Math.round(yMm * 1000) });
const line = (points: Pt[], speed: number, closed = false): ExtrudeStep => ({
  kind: 'extrude',
  feature: 'FILL',
  points,
  closed,
  width: 0.4,
  height: 0.2,
  speed,
  flow: 1,
});
const move = (points: Pt[], retract: boolean, zHop = 0, speed = 150): TravelStep => ({
  kind: 'travel',
  points,
  retract,
  zHop,
  speed,
});
const layer = (index: number, steps: PlanStep[], z = 0.2 * (index + 1)): LayerPlan => ({
  index,
  z,
  height: 0.2,
  fan: 0,
  steps,
});
const plan = (...layers: LayerPlan[]): PrintPlan => ({
  layers,
  objects: [],
  bounds: { minX: 0, minY: 0, minZ: 0, maxX: 100, maxY: 100, maxZ: 1 },
});
const close = (actual: number, expected: number, tolerance: number, what: string): void =>
  assert.ok(Math.abs(actual - expected) <= tolerance, `${what}: ${actual} vs ${expected}`);

/** Closed form of one trapezoid that reaches its cruise speed v: L/v + (v−v0)²/2av + (v−v1)²/2av. */
const trapezoid = (L: number, v: number, v0: number, v1: number, a: number): number =>
  L / v + (v - v0) ** 2 / (2 * a * v) + (v - v1) ** 2 / (2 * a * v);

/** Marlin's planner starts and ends every chain at its minimum planner speed. */
const m = MINIMUM_PLANNER_SPEED;

test("a long straight move takes L/v + v/a (from and to Marlin's minimum planner speed)", () => {
  const e = estimatePlan(plan(layer(0, [line([pt(0, 0), pt(100, 0)], 50)])), S);
  close(e.printTimeSeconds, trapezoid(100, 50, m, m, 500), 1e-9, 'straight');
  close(e.printTimeSeconds, 100 / 50 + 50 / 500, 1e-3, 'about L/v + v/a');
  assert.deepEqual(e.layerSeconds.length, 1);
});

test('a short move that never reaches its speed takes 2·√(L/a)', () => {
  const e = estimatePlan(plan(layer(0, [line([pt(0, 0), pt(1, 0)], 50)])), S);
  const peak = Math.sqrt(500 * 1 + m * m);
  close(e.printTimeSeconds, (2 * peak - 2 * m) / 500, 1e-9, 'triangle');
  close(pointToPointSeconds(1, 50, 500), 2 * Math.sqrt(1 / 500), 1e-12, 'p2p');
});

test('collinear pieces cost the same as one straight move (no slow-down at straight junctions)', () => {
  const pts: Pt[] = [];
  for (let i = 0; i <= 200; i++) pts.push(pt(i * 0.5, 0));
  const e = estimatePlan(plan(layer(0, [line(pts, 50)])), S);
  close(e.printTimeSeconds, trapezoid(100, 50, m, m, 500), 1e-6, 'split straight');
});

test('a 90° corner is taken at cornerVelocity (the junction deviation it maps to)', () => {
  const e = estimatePlan(plan(layer(0, [line([pt(0, 0), pt(100, 0), pt(100, 100)], 50)])), S);
  // Marlin's junction vectors carry E when the extruder moves: k mm of filament a mm opens the corner a little
  const k = (0.4 * 0.2) / (Math.PI * 0.875 ** 2);
  const cos = -(k * k) / (1 + k * k);
  const sinHalf = Math.sqrt(0.5 * (1 - cos));
  const jd = (8 * 8 * (Math.SQRT2 - 1)) / 500;
  const vc = Math.sqrt((500 * jd * sinHalf) / (1 - sinHalf));
  assert.ok(vc > 8 && vc < 8.01);
  const expected = trapezoid(100, 50, m, vc, 500) + trapezoid(100, 50, vc, m, 500);
  close(e.printTimeSeconds, expected, 1e-9, 'corner');
  // a travel (no E): exactly cornerVelocity
  const t = estimatePlan(plan(layer(0, [move([pt(0, 0)], false), move([pt(100, 0), pt(100, 100)], false, 0, 50)])), S);
  close(t.printTimeSeconds, trapezoid(100, 50, m, 8, 500) + trapezoid(100, 50, 8, m, 500), 1e-9, 'travel corner');
  // A reversal all but stops the head (E going on both ways keeps it from being an exact one in Marlin:
  // cos θ = (1 − k²) / (1 + k²), under a mm/s); a travel's is exact: it stops
  const back = estimatePlan(plan(layer(0, [line([pt(0, 0), pt(100, 0), pt(0, 0)], 50)])), S);
  const sinBack = Math.sqrt(0.5 * (1 - (1 - k * k) / (1 + k * k)));
  const vr = Math.sqrt((500 * jd * sinBack) / (1 - sinBack));
  assert.ok(vr < 1);
  close(back.printTimeSeconds, trapezoid(100, 50, m, vr, 500) + trapezoid(100, 50, vr, m, 500), 1e-9, 'reversal');
  const travelBack = estimatePlan(
    plan(layer(0, [move([pt(0, 0)], false), move([pt(100, 0), pt(0, 0)], false, 0, 50)])),
    S,
  );
  close(travelBack.printTimeSeconds, 2 * trapezoid(100, 50, m, m, 500), 1e-9, 'travel reversal');
});

test('a zig-zag of short segments is slower than the straight line of the same length', () => {
  const pts: Pt[] = [];
  for (let i = 0; i <= 100; i++) pts.push(pt(i, i % 2 === 0 ? 0 : 1));
  const pathLength = 100 * Math.SQRT2;
  const zig = estimatePlan(plan(layer(0, [line(pts, 60)])), S).printTimeSeconds;
  const straight = pathLength / 60 + 60 / 500;
  assert.ok(zig > straight * 1.5, `zig-zag ${zig} vs straight ${straight}`);
});

test('a finely divided circle runs near its centripetal speed √(a·r)', () => {
  const r = 10;
  const pts: Pt[] = [];
  for (let i = 0; i < 100; i++)
    pts.push(pt(50 + r * Math.cos((i / 100) * 2 * Math.PI), 50 + r * Math.sin((i / 100) * 2 * Math.PI)));
  const e = estimatePlan(plan(layer(0, [line(pts, 200, true)])), S);
  const v = Math.sqrt(500 * r);
  const expected = (2 * Math.PI * r) / v + v / 500; // cruise at v, start and end at rest
  close(e.printTimeSeconds, expected, 0.05 * expected, 'circle');
});

test('speeds are capped at maxSpeed', () => {
  const e = estimatePlan(plan(layer(0, [line([pt(0, 0), pt(200, 0)], 1000)])), { ...S, maxSpeed: 100 });
  close(e.printTimeSeconds, trapezoid(200, 100, m, m, 500), 1e-9, 'capped');
});

test('retraction, Z hop and prime are blocks like any other: 90° junctions at min(cornerVelocity, both speeds)', () => {
  const s = { ...S, retractionExtraPrime: 0.5 };
  const p = plan(layer(0, [move([pt(0, 0)], false), move([pt(30, 0)], true, 0.4)]));
  const e = estimatePlan(p, s);
  // E then Z then X then Z then E: every junction 90°, so min(8, the two blocks' speeds) = 5 (Z's speed)
  const z = Z_SPEED_MM_S;
  const expected =
    trapezoidSeconds(5, m, 45, z, 500) + // retract
    2 * (0.4 / z) + // lift and lower, cruising at 5 mm/s throughout
    trapezoidSeconds(30, z, 150, z, 500) + // the travel at its own speed
    trapezoidSeconds(5.5, z, 45, m, 500); // prime with the extra
  close(e.printTimeSeconds, expected, 1e-9, 'retracted travel');
  close(e.filamentMm, 0.5, 1e-12, 'extra prime is filament used');
  const off = estimatePlan(p, { ...s, retractionEnabled: false });
  close(off.printTimeSeconds, trapezoidSeconds(30, m, 150, m, 500), 1e-9, 'no retraction (and so no Z hop)');
});

test('per-layer seconds add up; a layer change is a Z block between the layers', () => {
  const p = plan(layer(0, [line([pt(0, 0), pt(100, 0)], 50)]), layer(1, [line([pt(100, 0), pt(0, 0)], 50)]));
  const e = estimatePlan(p, S);
  assert.equal(e.layerSeconds.length, 2);
  const z = Z_SPEED_MM_S;
  close(e.layerSeconds[0]!, trapezoid(100, 50, m, z, 500), 1e-9, 'layer 0');
  close(e.layerSeconds[1]!, 0.2 / z + trapezoid(100, 50, z, m, 500), 1e-9, 'layer 1');
  close(e.printTimeSeconds, e.layerSeconds[0]! + e.layerSeconds[1]!, 1e-12, 'total');
});

test('filament length from width × height × length over the cross-section; grams from density', () => {
  const p = plan(layer(0, [line([pt(0, 0), pt(100, 0), pt(100, 50)], 50)]));
  const area = Math.PI * 0.875 ** 2;
  const e = estimatePlan(p, { ...S, flowRate: 110 });
  const expectedMm = ((0.4 * 0.2 * 150) / area) * 1.1;
  close(e.filamentMm, expectedMm, 1e-9, 'length');
  close(e.filamentGrams, (expectedMm * area * 1.24) / 1000, 1e-12, 'grams');
});

test('segmentSeconds handles triangles between unequal entry and exit speeds', () => {
  // Enter at 10, leave at 20 over 1 mm with a = 500: peak² = aL + (100 + 400)/2 = 750.
  const peak = Math.sqrt(750);
  close(segmentSeconds(1, 10, 100, 20, 500), (peak - 10) / 500 + (peak - 20) / 500, 1e-12, 'triangle');
});

test('machine limits: per-axis speed and acceleration caps, travel and retract acceleration, and "ignore"', () => {
  const long = plan(layer(0, [line([pt(0, 0), pt(100, 0)], 100)]));
  const capped = estimatePlan(long, { ...S, maxSpeedX: 50 });
  close(capped.printTimeSeconds, trapezoid(100, 50, m, m, 500), 1e-9, 'X capped at 50 mm/s');
  close(
    estimatePlan(long, { ...S, maxSpeedX: 50, machineLimits: 'ignore' }).printTimeSeconds,
    trapezoid(100, 100, m, m, 500),
    1e-9,
    'ignored',
  );
  close(
    estimatePlan(long, { ...S, maxSpeedY: 50 }).printTimeSeconds,
    trapezoid(100, 100, m, m, 500),
    1e-9,
    'a Y limit does not slow an X move',
  );
  // a 45° move may go 50/cos 45° when each axis is limited to 50
  const diagonal = plan(layer(0, [line([pt(0, 0), pt(100, 100)], 200)]));
  const v = 50 / Math.SQRT1_2;
  close(
    estimatePlan(diagonal, { ...S, maxSpeedX: 50, maxSpeedY: 50 }).printTimeSeconds,
    trapezoid(100 * Math.SQRT2, v, m, m, 500),
    1e-9,
    'diagonal',
  );
  // per-axis acceleration: X at 250 mm/s² halves the acceleration of an X move
  close(
    estimatePlan(long, { ...S, maxAccelerationX: 250 }).printTimeSeconds,
    trapezoid(100, 100, m, m, 250),
    1e-9,
    'X acceleration',
  );
  // travels accelerate at travelAcceleration
  const hop = plan(layer(0, [move([pt(0, 0)], false), move([pt(100, 0)], false, 0, 100)]));
  close(
    estimatePlan(hop, { ...S, travelAcceleration: 5000 }).printTimeSeconds,
    trapezoid(100, 100, m, m, 5000),
    1e-9,
    'travel acceleration',
  );
  // retractions are capped at maxSpeedE and use retractAcceleration; the 90° junctions E→X→E at the junction
  // deviation's speed with each entering block's acceleration: 8 mm/s into the travel (500), 8√2 into the prime (1000)
  const retract = plan(layer(0, [move([pt(0, 0)], false), move([pt(10, 0)], true)]));
  const r1 = estimatePlan(retract, { ...S, maxSpeedE: 20, retractAcceleration: 1000 }).printTimeSeconds;
  const v2 = 8 * Math.SQRT2;
  close(
    r1,
    trapezoidSeconds(5, m, 20, 8, 1000) + trapezoidSeconds(10, 8, 150, v2, 500) + trapezoidSeconds(5, v2, 20, m, 1000),
    1e-9,
    'retract and prime',
  );
});

test("an arc is timed like the firmware runs it: 1 mm chords, taken at the circle's own speed", () => {
  const r = 20;
  const quarter: ExtrudeStep = {
    ...line([pt(r, 0), pt(0, r)], 50),
    arcs: [undefined, { cx: 0, cy: 0, clockwise: false }],
  };
  const e = estimatePlan(plan(layer(0, [quarter])), S);
  const length = (Math.PI * r) / 2;
  // a gentle curve: nearly L/v plus the start and stop
  close(e.printTimeSeconds, length / 50 + 50 / 500, 0.02, 'quarter circle');
  close(e.filamentMm, length * ((0.4 * 0.2) / (Math.PI * 0.875 ** 2)), 1e-9, 'filament along the arc');
});
