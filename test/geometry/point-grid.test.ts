import { test } from 'node:test';
import assert from 'node:assert/strict';
import { FixedPointGrid, PointGrid } from '#strata/geometry/point-grid.js';

/** A fixed pseudo-random sequence in [0, 1). */
function random(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

function brute(xs: ArrayLike<number>, ys: ArrayLike<number>, x: number, y: number, d: number): number[] {
  const out: number[] = [];
  for (let i = 0; i < xs.length; i++) if ((xs[i] - x) ** 2 + (ys[i] - y) ** 2 <= d * d) out.push(i);
  return out;
}

const sorted = (ids: number[], n: number) => ids.slice(0, n).sort((a, b) => a - b);

test('both grids find exactly the points within the distance, whatever the cell size', () => {
  const next = random(7);
  for (const cell of [1, 250, 1000, 4000, 100000]) {
    const n = 300;
    const xs = new Float64Array(n),
      ys = new Float64Array(n);
    const grid = new PointGrid(cell);
    for (let i = 0; i < n; i++) {
      // clustered and negative coordinates too, and some points repeated
      xs[i] = i % 17 === 0 ? xs[i - 1] || 0 : Math.round((next() - 0.3) * 20000);
      ys[i] = i % 17 === 0 ? ys[i - 1] || 0 : Math.round((next() - 0.6) * 8000);
      assert.equal(grid.add(xs[i], ys[i]), i);
    }
    const fixed = new FixedPointGrid(xs, ys, cell);
    // one array for every query: entries past the count are stale and must not matter
    const out: number[] = [];
    for (let q = 0; q < 200; q++) {
      const x = Math.round((next() - 0.4) * 30000),
        y = Math.round((next() - 0.6) * 12000);
      const d = q % 10 === 0 ? 0 : Math.round(next() * 6000);
      const want = brute(xs, ys, x, y, d);
      assert.deepEqual(sorted(out, grid.near(x, y, d, out)), want, `PointGrid cell ${cell} query ${q}`);
      assert.deepEqual(sorted(out, fixed.near(x, y, d, out)), want, `FixedPointGrid cell ${cell} query ${q}`);
    }
  }
});

test('a point exactly at the distance is found; queries far outside the points find none', () => {
  const xs = Float64Array.from([0, 3000, -3000]),
    ys = Float64Array.from([0, 4000, 0]);
  const fixed = new FixedPointGrid(xs, ys, 1000);
  const out: number[] = [];
  assert.deepEqual(sorted(out, fixed.near(0, 0, 5000, out)), [0, 1, 2]);
  assert.deepEqual(sorted(out, fixed.near(0, 0, 4999, out)), [0, 2]);
  assert.equal(fixed.near(1e7, -1e7, 1000, out), 0);
  assert.equal(new FixedPointGrid(new Float64Array(0), new Float64Array(0), 1000).near(0, 0, 1e6, out), 0);
});

test('nearest takes the closest point, the lowest id on a tie, and -1 when none is in range', () => {
  const grid = new PointGrid(500);
  grid.add(1000, 0);
  grid.add(0, 1000);
  grid.add(-1000, 0);
  grid.add(5000, 5000);
  assert.equal(grid.nearest(0, 0, 2000), 0);
  assert.equal(grid.nearest(-900, 0, 2000), 2);
  assert.equal(grid.nearest(3000, 3000, 100), -1);
});
