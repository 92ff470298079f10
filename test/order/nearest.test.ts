import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { nearestFirst, type PathSet, type Visit } from '#strata/order/nearest.js';

/** Paths of two entry points each, lines or (left where entered) loops. */
function pathSet(items: readonly Pt[][], lines: boolean): PathSet {
  return { count: items.length, entries: (i) => items[i], line: () => lines };
}

/** The plain nearest-first order: every entry left scanned from where the last path was left; ties: lower path, entry. */
function reference(items: readonly Pt[][], lines: boolean, from: Pt): Visit[] {
  const used = new Set<number>();
  const out: Visit[] = [];
  let at = from;
  while (used.size < items.length) {
    let best: Visit = [-1, -1];
    let bestD = Infinity;
    items.forEach((c, i) => {
      if (used.has(i)) return;
      c.forEach((p, k) => {
        const d = (p.x - at.x) ** 2 + (p.y - at.y) ** 2;
        if (d < bestD) [bestD, best] = [d, [i, k]];
      });
    });
    used.add(best[0]);
    out.push(best);
    at = items[best[0]][lines ? 1 - best[1] : best[1]];
  }
  return out;
}

/** Random items of two entry points on a coarse lattice, so that equal distances (ties) happen. */
function lattice(count: number, seed: number): { items: Pt[][]; from: Pt } {
  let s = seed;
  const rand = (n: number) => (s = (s * 1103515245 + 12345) % 2 ** 31) % n;
  const items: Pt[][] = [];
  for (let i = 0; i < count; i++)
    items.push([
      { x: rand(20) * 100, y: rand(20) * 100 },
      { x: rand(20) * 100, y: rand(20) * 100 },
    ]);
  return { items, from: { x: rand(20) * 100, y: rand(20) * 100 } };
}

// 400 and 1500: the grid is made again of the rest several times as it thins out
const COUNTS = [1, 2, 5, 11, 12, 13, 30, 80, 400, 1500];

test("'lowest' ties: the plain nearest-first order (ties: lower path, then entry), for few and many paths", () => {
  for (const count of COUNTS)
    for (const lines of [true, false]) {
      const { items, from } = lattice(count, 7 + count);
      assert.deepEqual(nearestFirst(pathSet(items, lines), from, 'lowest'), reference(items, lines, from), `${count}`);
    }
});

test("'grid' ties: every path is taken at an entry as near as any left, whatever tie the grid search settles on", () => {
  for (const count of COUNTS) {
    const { items, from } = lattice(count, 11 + count);
    const got = nearestFirst(pathSet(items, true), from, 'grid');
    assert.equal(new Set(got.map(([i]) => i)).size, count);
    let at = from;
    const used = new Set<number>();
    for (const [i, k] of got) {
      const d2 = (p: Pt) => (p.x - at.x) ** 2 + (p.y - at.y) ** 2;
      let nearest = Infinity;
      items.forEach((c, j) => {
        if (!used.has(j)) for (const p of c) nearest = Math.min(nearest, d2(p));
      });
      assert.equal(d2(items[i][k]), nearest);
      used.add(i);
      at = items[i][1 - k];
    }
  }
});

test("ties: 'lowest' takes the lower path, 'grid' the one the search comes to first (in a cell, the later path)", () => {
  // two lines from the same point: equally near from the start
  const items = [
    [
      { x: 0, y: 0 },
      { x: 5000, y: 0 },
    ],
    [
      { x: 0, y: 0 },
      { x: 0, y: 5000 },
    ],
  ];
  const from = { x: -1000, y: 0 };
  assert.deepEqual(nearestFirst(pathSet(items, true), from, 'lowest'), [
    [0, 0],
    [1, 0],
  ]);
  assert.deepEqual(nearestFirst(pathSet(items, true), from, 'grid'), [
    [1, 0],
    [0, 0],
  ]);
});

test('a path left elsewhere than its entry says where (`exit`), and the order goes on from there', () => {
  // a loop found by its entry (0, 0) but left at (10000, 0), next to the second path's entry
  const paths: PathSet = {
    count: 3,
    entries: (i) => [[{ x: 0, y: 0 }], [{ x: 10500, y: 0 }], [{ x: 2000, y: 0 }]][i],
    line: () => false,
    exit: (i, k) => (i === 0 ? { x: 10000, y: 0 } : paths.entries(i)[k]),
  };
  for (const ties of ['lowest', 'grid'] as const)
    assert.deepEqual(
      nearestFirst(paths, { x: -100, y: 0 }, ties).map(([i]) => i),
      [0, 1, 2],
    );
});

test('a start point far outside the paths still gives the nearest first', () => {
  const items: Pt[][] = [];
  for (let i = 0; i < 100; i++)
    items.push([
      { x: 100000 + i * 2000, y: 100000 },
      { x: 101000 + i * 2000, y: 100000 },
    ]);
  for (const ties of ['lowest', 'grid'] as const) {
    const got = nearestFirst(pathSet(items, true), { x: -1e9, y: -1e9 }, ties);
    assert.deepEqual(got[0], [0, 0]);
    assert.deepEqual(
      got.map(([i]) => i),
      items.map((_, i) => i),
    );
  }
});
