import { test } from 'node:test';
import assert from 'node:assert/strict';
import { area } from '#strata/geometry/clip.js';
import { rect, square } from '../geometry/test-shapes.js';
import { overhangOf } from '#strata/regions/overhang.js';

const S = { supportThreshold: 50, supportMinArea: 0.5 };

test('a layer reaching out past the one below further than the overhang angle allows needs support there', () => {
  // 20 mm square over a 10 mm square: everything beyond 0.2·tan 50° = 0.238 mm from the lower square
  const o = overhangOf([square(0, 0, 20_000)], [square(5_000, 5_000, 10_000)], 0.2, S);
  const reach = 200 * Math.tan((50 * Math.PI) / 180);
  const held = (10_000 + 2 * reach) ** 2; // the grown square (mitred corners)
  const expected = 20_000 ** 2 - held;
  assert.ok(Math.abs(area(o) - expected) / expected < 0.005, `overhang ${area(o)} µm², expected ${expected}`);
});

test('no overhang within the angle, on the first layer, or for specks below supportMinArea', () => {
  // a 45° slope: each layer reaches 0.2 mm out, less than 0.238 mm
  assert.deepEqual(overhangOf([square(-200, -200, 10_400)], [square(0, 0, 10_000)], 0.2, S), []);
  assert.deepEqual(overhangOf([square(0, 0, 20_000)], [], 0.2, S, true), []);
  // a 0.6 × 0.6 mm speck (0.36 mm²) beside the part
  assert.deepEqual(
    overhangOf([square(0, 0, 10_000), rect(12_000, 0, 12_600, 600)], [square(0, 0, 10_000)], 0.2, S),
    [],
  );
  // …but a larger one is kept, and a steeper threshold keeps the 45° slope out too
  assert.equal(
    overhangOf([square(0, 0, 10_000), rect(12_000, 0, 13_000, 1_000)], [square(0, 0, 10_000)], 0.2, S).length,
    1,
  );
  assert.ok(
    overhangOf([square(-200, -200, 10_400)], [square(0, 0, 10_000)], 0.2, {
      ...S,
      supportThreshold: 30,
      supportMinArea: 0,
    }).length > 0,
  );
});

test('a floating part (nothing below) is all overhang', () => {
  const o = overhangOf([square(0, 0, 5_000)], [], 0.2, S);
  assert.equal(Math.round(area(o)), 25_000_000);
});
