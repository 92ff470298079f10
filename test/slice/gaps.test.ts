import { test } from 'node:test';
import assert from 'node:assert/strict';
import { closeOpenChains } from '#strata/slice/gaps.js';

/** Slots for the points (µm) and one chain through them in order. */
function chainOf(points: [number, number][]): { chain: Int32Array; x: Float64Array; y: Float64Array } {
  return {
    chain: Int32Array.from(points, (_, i) => i),
    x: Float64Array.from(points, (p) => p[0]),
    y: Float64Array.from(points, (p) => p[1]),
  };
}

const GAP_UM = 2_000;

test('an open run that encloses solid (a part with a wall missing) is closed on itself', () => {
  // three sides of a 10 mm square, counter-clockwise: the fourth side is a 10 mm gap
  const { chain, x, y } = chainOf([
    [10_000, 0],
    [10_000, 10_000],
    [0, 10_000],
    [0, 0],
  ]);
  assert.equal(closeOpenChains([chain], x, y, GAP_UM).length, 1);
});

test("an open run that would close into a hole across a wide gap is left out (a flap of a scan's open base)", () => {
  // a V, clockwise when closed: closing it would cut a triangular cavity into the solid around it
  const { chain, x, y } = chainOf([
    [10_000, 0],
    [5_000, -8_000],
    [0, 0],
  ]);
  assert.equal(closeOpenChains([chain], x, y, GAP_UM).length, 0);
});

test('a hole whose wall has a small gap next to its length is still closed', () => {
  // a clockwise ring round a 10 mm hole with 3 mm of its 40 mm wall missing
  const { chain, x, y } = chainOf([
    [3_000, 0],
    [0, 0],
    [0, 10_000],
    [10_000, 10_000],
    [10_000, 0],
    [6_000, 0],
  ]);
  assert.equal(closeOpenChains([chain], x, y, GAP_UM).length, 1);
});

test('open runs whose ends meet within the gap are joined into one ring', () => {
  const a = [
    [0, 0],
    [10_000, 0],
    [10_000, 10_000],
  ] as [number, number][];
  const b = [
    [10_000, 10_500],
    [0, 10_000],
    [0, 500],
  ] as [number, number][];
  const { x, y } = chainOf([...a, ...b]);
  const rings = closeOpenChains([Int32Array.of(0, 1, 2), Int32Array.of(3, 4, 5)], x, y, GAP_UM);
  assert.equal(rings.length, 1);
  assert.equal(rings[0].length, 6);
});
