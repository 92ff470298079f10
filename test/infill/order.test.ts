import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { orderPaths, travelLength } from '#strata/infill/order.js';

function shuffled(n: number, seed: number): Pt[][] {
  let s = seed;
  const rnd = () => (s = (s * 1103515245 + 12345) % 2147483648) / 2147483648;
  const out: Pt[][] = [];
  for (let i = 0; i < n; i++) {
    const x = Math.round(rnd() * 200_000),
      y = Math.round(rnd() * 200_000);
    out.push([
      { x, y },
      { x: x + Math.round((rnd() - 0.5) * 3_000), y: y + Math.round((rnd() - 0.5) * 3_000) },
    ]);
  }
  return out;
}

test('ordering keeps every path once (possibly reversed) and cuts travel', () => {
  const lines = shuffled(2_000, 7);
  const start = { x: 0, y: 0 };
  const { lines: out } = orderPaths(lines, [], start);
  assert.equal(out.length, lines.length);
  const key = (l: Pt[]) => {
    const a = `${l[0].x},${l[0].y}`,
      b = `${l[l.length - 1].x},${l[l.length - 1].y}`;
    return a < b ? a + '|' + b : b + '|' + a;
  };
  assert.deepEqual(out.map(key).sort(), lines.map(key).sort());
  assert.ok(travelLength(out, start) < 0.1 * travelLength(lines, start));
});

test('ordering is about linear: 16× the paths cost well under 64× the time', () => {
  const time = (n: number) => {
    const lines = shuffled(n, 3);
    const t = performance.now();
    orderPaths(lines, [], { x: 0, y: 0 });
    return performance.now() - t;
  };
  time(2_000);
  const small = Math.max(0.5, time(2_000)),
    big = time(32_000);
  assert.ok(big < 64 * small, `${big} ms vs ${small} ms`);
});

test('loops are rotated to start nearest to where the nozzle is', () => {
  const loop = [
    { x: 0, y: 0 },
    { x: 10, y: 0 },
    { x: 10, y: 10 },
    { x: 0, y: 10 },
  ];
  const { loops } = orderPaths([], [loop], { x: 11, y: 11 });
  assert.deepEqual(loops[0][0], { x: 10, y: 10 });
});
