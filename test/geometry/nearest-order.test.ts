import { test } from 'node:test';
import assert from 'node:assert/strict';
import { orderLoops, orderNearest, orderPolylines } from '#strata/geometry/nearest-order.js';
import type { Polyline, Pt } from '#strata/geometry/types.js';

test('nearest-first ordering visits every line once and reverses lines entered at their far end', () => {
  const lines: Polyline[] = [];
  for (let i = 0; i < 50; i++)
    lines.push([
      { x: 0, y: i * 1000 },
      { x: 10000, y: i * 1000 },
    ]);
  const shuffled = lines
    .map((l, i) => ({ l, k: (i * 37) % 50 }))
    .sort((a, b) => a.k - b.k)
    .map((x) => x.l);
  const out = orderPolylines(shuffled, { x: 0, y: -1000 });
  assert.equal(out.length, 50);
  // a zig-zag: consecutive lines start where the previous ended (same side)
  let travel = 0;
  for (let i = 1; i < out.length; i++) {
    const e = out[i - 1][1],
      s = out[i][0];
    travel += Math.hypot(e.x - s.x, e.y - s.y);
  }
  assert.equal(travel, 49 * 1000);
  assert.equal(new Set(out.map((l) => l[0].y)).size, 50);
});

test('a start point far outside the paths still orders quickly and correctly', () => {
  const lines: Polyline[] = [
    [
      { x: 100000, y: 100000 },
      { x: 101000, y: 100000 },
    ],
    [
      { x: 105000, y: 100000 },
      { x: 106000, y: 100000 },
    ],
  ];
  const out = orderPolylines(lines, { x: -1e9, y: -1e9 });
  assert.equal(out[0][0].x, 100000);
});

test('loops are entered at their nearest vertex and rotated to start there', () => {
  const sq = (x: number) => [
    { x, y: 0 },
    { x: x + 1000, y: 0 },
    { x: x + 1000, y: 1000 },
    { x, y: 1000 },
  ];
  const { loops, end } = orderLoops([sq(10000), sq(0)], { x: 900, y: 1100 });
  assert.deepEqual(loops[0][0], { x: 1000, y: 1000 });
  assert.equal(loops[1][0].x >= 10000, true);
  assert.deepEqual(end, loops[1][0]);
});

test('the order is the plain nearest-first order (ties: lower item, then lower candidate), for few and many items', () => {
  // a reference: scan every remaining candidate from where the last item ended
  const reference = (items: Pt[][], from: Pt): Array<[number, number]> => {
    const used = new Set<number>();
    const out: Array<[number, number]> = [];
    let at = from;
    while (used.size < items.length) {
      let best: [number, number] = [-1, -1];
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
      at = items[best[0]][items[best[0]].length - 1 - best[1]];
    }
    return out;
  };
  let seed = 7;
  const rand = (n: number) => (seed = (seed * 1103515245 + 12345) % 2 ** 31) % n;
  // 400 and 1500: the grid is made again of the rest several times as it thins out
  for (const count of [1, 2, 5, 11, 12, 13, 30, 80, 400, 1500]) {
    // coarse coordinates, so equal distances (ties) happen
    const items: Pt[][] = [];
    for (let i = 0; i < count; i++)
      items.push([
        { x: rand(20) * 100, y: rand(20) * 100 },
        { x: rand(20) * 100, y: rand(20) * 100 },
      ]);
    const from = { x: rand(20) * 100, y: rand(20) * 100 };
    const got = orderNearest(
      count,
      (i) => items[i],
      (i, k) => items[i][items[i].length - 1 - k],
      from,
    );
    assert.deepEqual(got, reference(items, from), `${count} items`);
  }
});
