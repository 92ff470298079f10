import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  extrudeOnlyRatio,
  KlipperPlanner,
  klipperJunctionV2,
  klipperMoveSeconds,
  type KlipperLimits,
} from '#strata/plan/klipper-planner.js';

const L: KlipperLimits = {
  maxVelocity: 300,
  maxAccel: 3000,
  minCruiseRatio: 0,
  squareCornerVelocity: 5,
  maxZVelocity: 15,
  maxZAccel: 300,
  maxExtrudeOnlyVelocity: 300 * extrudeOnlyRatio(0.4, 1.75),
  maxExtrudeOnlyAccel: 3000 * extrudeOnlyRatio(0.4, 1.75),
  instantCornerVelocity: 1,
};

const close = (a: number, b: number, eps = 1e-9, what = '') =>
  assert.ok(Math.abs(a - b) <= eps * Math.max(1, Math.abs(b)), `${what} ${a} ≠ ${b}`);

function total(p: KlipperPlanner): number {
  p.flush();
  return p.seconds.reduce((a, b) => a + (b ?? 0), 0);
}

test('a 90° corner between long moves allows exactly the square-corner velocity', () => {
  // cos θ = −(u_prev · u) = 0 at 90°
  close(klipperJunctionV2(0, 100, 3000, 100, 3000, 5, 3000), 25);
  // a lower acceleration (M204 below max_accel) lowers it in proportion, as junction_deviation is fixed
  close(klipperJunctionV2(0, 100, 1500, 100, 1500, 5, 3000), 12.5);
});

test('junctions: a reversal stops; straight on is unlimited by the corner rules; short moves limit by the centripetal rule', () => {
  assert.equal(klipperJunctionV2(1, 10, 3000, 10, 3000, 5, 3000), 0);
  assert.ok(klipperJunctionV2(-1, 10, 3000, 10, 3000, 5, 3000) > 1e6);
  // 90°, 0.2 mm moves: ½ · 0.2 · tan 45° · 3000 = 300 mm²/s² (the deviation rule's 25 is lower); 0.01 mm: 15
  close(klipperJunctionV2(0, 0.2, 3000, 0.2, 3000, 5, 3000), 25);
  close(klipperJunctionV2(0, 0.01, 3000, 0.01, 3000, 5, 3000), 15);
});

test('trapezoid: a triangle, a full trapezoid and cruising only', () => {
  // 100 mm at 100 mm/s, 3000 mm/s²: 2 · 100/3000 + (100 − 100²/3000)/100
  close(klipperMoveSeconds(100, 3000, 0, 100 * 100, 0), 2 / 30 + (100 - 10000 / 3000) / 100);
  close(klipperMoveSeconds(10, 3000, 100 * 100, 100 * 100, 100 * 100), 0.1);
  // up to 10 mm/s over 1/60 mm and down again: a triangle
  close(klipperMoveSeconds(1 / 30, 3000, 0, 100, 0), 2 * (10 / 3000));
});

test('planner: one move from rest to rest is a trapezoid at its feed rate, capped at max_velocity', () => {
  const p = new KlipperPlanner(L);
  p.move(100, 0, 0, 0, 100);
  close(total(p), klipperMoveSeconds(100, 3000, 0, 10000, 0));
  const q = new KlipperPlanner(L);
  q.move(300, 0, 0, 0, 1000);
  close(total(q), klipperMoveSeconds(300, 3000, 0, 300 * 300, 0));
});

test('planner: two sides of a square pass their corner at the square-corner velocity', () => {
  const p = new KlipperPlanner(L);
  p.move(100, 0, 0, 0, 50);
  p.move(0, 100, 0, 0, 50);
  const first = klipperMoveSeconds(100, 3000, 0, 2500, 25);
  close(total(p), first + klipperMoveSeconds(100, 3000, 25, 2500, 0), 1e-9, 'square');
});

test('planner: minimum_cruise_ratio lowers the peak of a short move that only accelerates and decelerates', () => {
  const plain = new KlipperPlanner(L);
  plain.move(2, 0, 0, 0, 200);
  const smoothed = new KlipperPlanner({ ...L, minCruiseRatio: 0.5 });
  smoothed.move(2, 0, 0, 0, 200);
  // without: a triangle to √(3000 · 2) mm/s; with: cruise at the speed the pseudo-acceleration 1500 reaches at mid-move
  close(total(plain), (2 * Math.sqrt(6000)) / 3000);
  const peak2 = 1500 * 2; // (0 + 2 · 2 · 1500) / 2
  close(total(smoothed), klipperMoveSeconds(2, 3000, 0, peak2, 0));
  assert.ok(total(smoothed) > total(plain));
});

test('planner: retractions use the extrude-only limits and stop the head; Z moves the Z limits', () => {
  const p = new KlipperPlanner(L);
  p.move(10, 0, 0, 0.3, 50);
  p.move(0, 0, 0, -5, 45);
  p.move(10, 0, 0, 0.3, 50);
  const a = L.maxExtrudeOnlyAccel; // ≈ 798 mm/s²
  const expected = 2 * klipperMoveSeconds(10, 3000, 0, 2500, 0) + klipperMoveSeconds(5, a, 0, 45 * 45, 0);
  close(total(p), expected);
  const z = new KlipperPlanner(L);
  z.move(0, 0, 2, 0, 50);
  close(total(z), klipperMoveSeconds(2, 300, 0, 15 * 15, 0));
});

test('planner: the extruder corner velocity limits a junction where the extrusion per mm changes', () => {
  // travel (E 0) straight into an extrusion of 0.0333 mm/mm: (1 / 0.0333)² ≈ 900 mm²/s², so 30 mm/s, not full speed
  const p = new KlipperPlanner(L);
  p.move(50, 0, 0, 0, 100);
  p.move(50, 0, 0, 50 / 30, 100);
  const v2 = 900;
  const expected = klipperMoveSeconds(50, 3000, 0, 10000, v2) + klipperMoveSeconds(50, 3000, v2, 10000, 0);
  close(total(p), expected, 1e-6);
});

test('planner: times go to the bucket current when each move was added', () => {
  const p = new KlipperPlanner(L);
  p.tag = 0;
  p.move(10, 0, 0, 0, 50);
  p.tag = 2;
  p.move(10, 0, 0, 0, 50);
  p.flush();
  assert.equal(p.seconds.length, 3);
  assert.ok(p.seconds[0]! > 0 && p.seconds[2]! > 0);
  assert.equal(p.seconds[1] ?? 0, 0);
});
