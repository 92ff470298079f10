import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  MarlinPlanner,
  MINIMUM_PLANNER_SPEED as m,
  trapezoidSeconds,
  type MarlinLimits,
} from '#strata/plan/marlin-planner.js';
import { marlinLimits, startGcodeLimits, type EstimateSettings } from '#strata/plan/estimate.js';

const close = (actual: number, expected: number, tolerance: number, what: string): void =>
  assert.ok(Math.abs(actual - expected) <= tolerance, `${what}: ${actual} vs ${expected}`);

const NONE = [Infinity, Infinity, Infinity, Infinity] as const;
const JD: MarlinLimits = {
  maxFeedrate: NONE,
  maxAccel: NONE,
  printAccel: 1000,
  travelAccel: 1000,
  retractAccel: 1000,
  jerk: null,
  junctionDeviation: 0.02,
};
const JERK: MarlinLimits = { ...JD, jerk: [10, 10, 0.4, 1.5] };

function run(limits: MarlinLimits, moves: Array<[number, number, number, number, number]>): number {
  const p = new MarlinPlanner(limits);
  for (const [dx, dy, dz, de, v] of moves) p.move(dx, dy, dz, de, v);
  p.flush();
  return p.seconds.reduce((a, b) => a + b, 0);
}

test('trapezoids: cruise, and triangles between unequal speeds', () => {
  // 0 → 100 → 0 over 200 mm at 1000 mm/s²: 5 mm each way, 190 mm cruising
  close(trapezoidSeconds(200, 0, 100, 0, 1000), 0.1 + 0.1 + 1.9, 1e-12, 'cruise');
  // 10 → ? → 20 over 1 mm at 500: peak² = 500 + (100 + 400) / 2 = 750
  const peak = Math.sqrt(750);
  close(trapezoidSeconds(1, 10, 100, 20, 500), (2 * peak - 30) / 500, 1e-12, 'triangle');
});

test('a long straight move: from and to the minimum planner speed, L/v + v/a', () => {
  const t = run(JD, [[200, 0, 0, 0, 100]]);
  const ramp = (100 * 100 - m * m) / 2000; // mm each way
  close(t, 2 * ((100 - m) / 1000) + (200 - 2 * ramp) / 100, 1e-12, 'straight');
  close(t, 200 / 100 + 100 / 1000, 1e-4, 'about L/v + v/a');
  // split into 1 mm pieces: the same (straight junctions do not slow)
  close(
    run(
      JD,
      Array.from({ length: 200 }, () => [1, 0, 0, 0, 100] as [number, number, number, number, number]),
    ),
    t,
    1e-9,
    'pieces',
  );
});

test('classic jerk: a 20 mm square at 100 mm/s, 1000 mm/s², jerk 10 mm/s: every corner at 10 mm/s', () => {
  const t = run(JERK, [
    [20, 0, 0, 0, 100],
    [0, 20, 0, 0, 100],
    [-20, 0, 0, 0, 100],
    [0, -20, 0, 0, 100],
  ]);
  // start: no axis faster than its jerk from rest, so 10 mm/s; each 90° corner: X drops 100 → 0 and Y
  // rises 0 → 100, a change of 100 against a jerk of 10: 10 mm/s. A side: 10 → 100 in 4.95 mm, cruise
  // 10.1 mm, 100 → 10 in 4.95 mm: 0.09 + 0.101 + 0.09 = 0.281 s; the last brakes to 0.05 mm/s
  const side = 0.281;
  const last = 0.09 + (20 - 4.95 - (100 * 100 - m * m) / 2000) / 100 + (100 - m) / 1000;
  close(t, 3 * side + last, 1e-12, 'square');
  close(t, 1.1334500125, 1e-9, 'by hand');
});

test('junction deviation: the same square, 90° corners at √(a · jd · (√2 + 1))', () => {
  const t = run(JD, [
    [20, 0, 0, 0, 100],
    [0, 20, 0, 0, 100],
    [-20, 0, 0, 0, 100],
    [0, -20, 0, 0, 100],
  ]);
  const v = Math.sqrt(1000 * 0.02 * (Math.SQRT2 + 1)); // 6.95 mm/s
  const up = (100 - v) / 1000,
    upD = (100 * 100 - v * v) / 2000;
  const first = (100 - m) / 1000 + (20 - (100 * 100 - m * m) / 2000 - upD) / 100 + up;
  const middle = 2 * up + (20 - 2 * upD) / 100;
  const last = up + (20 - upD - (100 * 100 - m * m) / 2000) / 100 + (100 - m) / 1000;
  close(t, first + 2 * middle + last, 1e-12, 'square');
});

test('a zig-zag of √2 mm legs never reaches its speed: triangles between the corner speeds', () => {
  const legs: Array<[number, number, number, number, number]> = [];
  for (let i = 0; i < 6; i++) legs.push([1, i % 2 ? -1 : 1, 0, 0, 100]);
  const L = Math.SQRT2;
  const tri = (v0: number, v1: number) => (2 * Math.sqrt(1000 * L + (v0 * v0 + v1 * v1) / 2) - v0 - v1) / 1000;
  // junction deviation: 90° corners at √(1000 · 0.02 · (√2 + 1))
  const vjd = Math.sqrt(1000 * 0.02 * (Math.SQRT2 + 1));
  close(run(JD, legs), tri(m, vjd) + 4 * tri(vjd, vjd) + tri(vjd, m), 1e-12, 'junction deviation');
  // classic jerk: Y reverses 70.7 → −70.7 at each corner, X goes on: the junction at 100 × 10 / 141.4;
  // the first leg starts at 100 × 10 / 70.7 (each axis 70.7 from rest)
  const vj = (100 * 10) / (2 * 100 * Math.SQRT1_2);
  close(run(JERK, legs), tri(10 * Math.SQRT2, vj) + 4 * tri(vj, vj) + tri(vj, m), 1e-12, 'classic jerk');
});

test('per-axis limits: feed rate and acceleration of the axes, the extruder included; retract acceleration', () => {
  const lim: MarlinLimits = { ...JD, maxFeedrate: [50, 50, 5, 20], maxAccel: [250, 1000, 100, 5000] };
  // along X: 50 mm/s at 250 mm/s²
  close(run(lim, [[100, 0, 0, 0, 100]]), trapezoidSeconds(100, m, 50, m, 250), 1e-12, 'X');
  // a retraction: E only, 20 mm/s (M203 E) at the retract acceleration
  close(run(lim, [[0, 0, 0, -5, 45]]), trapezoidSeconds(5, m, 20, m, 1000), 1e-12, 'retraction');
  // classic jerk: a retraction starts at the E jerk
  close(
    run({ ...JERK, retractAccel: 1000 }, [[0, 0, 0, -5, 45]]),
    trapezoidSeconds(5, 1.5, 45, m, 1000),
    1e-12,
    'E jerk',
  );
});

const SETTINGS = {
  acceleration: 500,
  cornerVelocity: 8,
  gcodeFlavor: 'marlin',
  machineLimits: 'estimate',
  maxSpeedX: 200,
  maxSpeedY: null,
  maxSpeedZ: null,
  maxSpeedE: null,
  maxAccelerationX: null,
  maxAccelerationY: null,
  maxAccelerationZ: null,
  maxAccelerationE: null,
  travelAcceleration: null,
  retractAcceleration: null,
  jerkX: null,
  jerkY: null,
  jerkZ: null,
  jerkE: null,
  junctionDeviation: null,
  startGcode: '',
} as unknown as EstimateSettings;

test('limits: junction deviation from cornerVelocity, or given; classic jerk when jerk is given', () => {
  const jd = marlinLimits(SETTINGS);
  assert.equal(jd.jerk, null);
  close(jd.junctionDeviation, (64 * (Math.SQRT2 - 1)) / 500, 1e-15, 'from cornerVelocity');
  assert.deepEqual(jd.maxFeedrate, [200, Infinity, Infinity, Infinity]);
  assert.equal(marlinLimits({ ...SETTINGS, junctionDeviation: 0.013 }).junctionDeviation, 0.013);
  assert.deepEqual(marlinLimits({ ...SETTINGS, jerkX: 8 }).jerk, [8, 8, 0.3, 5]);
  assert.deepEqual(marlinLimits({ ...SETTINGS, jerkX: 8, jerkY: 9, jerkZ: 0.4, jerkE: 2.5 }).jerk, [8, 9, 0.4, 2.5]);
  // any jerk given means classic jerk: X and Y from cornerVelocity when not given
  assert.deepEqual(marlinLimits({ ...SETTINGS, jerkE: 2.5 }).jerk, [8, 8, 0.3, 2.5]);
  assert.equal(marlinLimits({ ...SETTINGS, jerkX: 8, machineLimits: 'ignore' }).jerk, null);
  assert.deepEqual(marlinLimits({ ...SETTINGS, machineLimits: 'ignore' }).maxFeedrate, [
    Infinity,
    Infinity,
    Infinity,
    Infinity,
  ]);
});

test("limits: the start G-code's M201/M203/M204/M205, then what Strata writes after it", () => {
  const start =
    'G28\nM201 X1000 Y1000 Z200 E5000 ; accelerations\nM203 X200 Y200 Z12 E120\nM204 P1250 R1250 T1500\nM205 X8.00 Y8.00 Z0.40 E4.50\nM201 X{machine_max_acceleration_x}\n';
  const g = startGcodeLimits(start);
  assert.deepEqual(g.M201, { X: 1000, Y: 1000, Z: 200, E: 5000 });
  assert.deepEqual(g.M204, { P: 1250, R: 1250, T: 1500 });
  const l = marlinLimits({ ...SETTINGS, startGcode: start });
  assert.deepEqual(l.maxAccel, [1000, 1000, 200, 5000]);
  assert.deepEqual(l.maxFeedrate, [200, 200, 12, 120]);
  assert.deepEqual([l.printAccel, l.travelAccel, l.retractAccel], [1250, 1500, 1250]);
  assert.deepEqual(l.jerk, [8, 8, 0.4, 4.5]);
  // an acceleration set away from its default is written after the start G-code (M204 P T)
  const a = marlinLimits({ ...SETTINGS, startGcode: start, acceleration: 2000 });
  assert.deepEqual([a.printAccel, a.travelAccel, a.retractAccel], [2000, 2000, 1250]);
  // machineLimits = write: the settings' limits, written after it, win where given
  const w = marlinLimits({ ...SETTINGS, startGcode: start, machineLimits: 'write', maxAccelerationX: 3000 });
  assert.deepEqual(w.maxAccel, [3000, 1000, 200, 5000]);
  assert.deepEqual(w.jerk, [8, 8, 0.4, 4.5]);
  assert.deepEqual(
    marlinLimits({ ...SETTINGS, startGcode: start, machineLimits: 'write', jerkX: 10 }).jerk,
    [10, 10, 0.4, 4.5],
  );
  // written with no jerk set (M205 X Y = cornerVelocity): still junction deviation
  assert.equal(marlinLimits({ ...SETTINGS, machineLimits: 'write' }).jerk, null);
  // M205 J: junction deviation; RepRap: M203 and M566 in mm/min
  assert.equal(marlinLimits({ ...SETTINGS, startGcode: 'M205 J0.02' }).junctionDeviation, 0.02);
  const rrf = marlinLimits({ ...SETTINGS, gcodeFlavor: 'reprap', startGcode: 'M203 X12000\nM566 X600 Y600' });
  assert.equal(rrf.maxFeedrate[0], 200);
  assert.deepEqual(rrf.jerk, [10, 10, 0.3, 5]);
});
