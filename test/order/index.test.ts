import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Polyline, Pt } from '#strata/geometry/types.js';
import { exitPoint, orderLines, orderLoops, orderPaths, shortenOrder, type PathSet } from '#strata/order/index.js';

/** Travel of polylines printed in the order given: start → first path, each path's end → the next's start, µm. */
function travelLength(lines: readonly Pt[][], start: Pt): number {
  let cur = start;
  let t = 0;
  for (const l of lines) {
    t += Math.hypot(l[0].x - cur.x, l[0].y - cur.y);
    cur = l[l.length - 1];
  }
  return t;
}

/** Travel of a visit order of a path set, from `from` and on to `to` when given, µm. */
function tourLength(paths: PathSet, visits: ReadonlyArray<readonly [number, number]>, from: Pt, to: Pt | null): number {
  let at = from,
    sum = 0;
  for (const [i, c] of visits) {
    const a = paths.entries(i)[c];
    sum += Math.hypot(a.x - at.x, a.y - at.y);
    at = exitPoint(paths, [i, c]);
  }
  return to ? sum + Math.hypot(to.x - at.x, to.y - at.y) : sum;
}

test('lines nearest-first: every line once, turned round when entered at its far end', () => {
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
  const out = orderLines(shuffled, { x: 0, y: -1000 });
  assert.equal(out.length, 50);
  // a zig-zag: consecutive lines start where the previous ended (same side)
  assert.equal(travelLength(out, { x: 0, y: 0 }), 49 * 1000);
  assert.equal(new Set(out.map((l) => l[0].y)).size, 50);
});

/** `n` short lines at random places and angles, µm. */
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

test('ordering lines keeps every line once (possibly reversed) and cuts travel', () => {
  const lines = shuffled(2_000, 7);
  const start = { x: 0, y: 0 };
  const out = orderLines(lines, start);
  assert.equal(out.length, lines.length);
  const key = (l: Pt[]) => {
    const a = `${l[0].x},${l[0].y}`,
      b = `${l[l.length - 1].x},${l[l.length - 1].y}`;
    return a < b ? a + '|' + b : b + '|' + a;
  };
  assert.deepEqual(out.map(key).sort(), lines.map(key).sort());
  assert.ok(travelLength(out, start) < 0.1 * travelLength(lines, start));
});

test('ordering is about linear: 16× the lines cost well under 64× the time', () => {
  const time = (n: number) => {
    const lines = shuffled(n, 3);
    const t = performance.now();
    orderLines(lines, { x: 0, y: 0 });
    return performance.now() - t;
  };
  time(2_000);
  const small = Math.max(0.5, time(2_000)),
    big = time(32_000);
  assert.ok(big < 64 * small, `${big} ms vs ${small} ms`);
});

test('loops are entered at their nearest vertex and started there; the end is where the last one starts', () => {
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
  assert.deepEqual(orderLoops([], { x: 5, y: 5 }), { loops: [], end: { x: 5, y: 5 } });
  // one loop: started at the vertex nearest the nozzle
  assert.deepEqual(orderLoops([sq(0)], { x: 1100, y: 1100 }).loops[0][0], { x: 1000, y: 1000 });
});

test('a shortened order visits every path once and never travels further than the nearest-first one', () => {
  let seed = 3;
  const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
  for (let trial = 0; trial < 50; trial++) {
    const n = 1 + Math.floor(rnd() * 300);
    const ends: Pt[][] = [];
    const line: boolean[] = [];
    for (let i = 0; i < n; i++) {
      const a = { x: Math.round(rnd() * 1e5), y: Math.round(rnd() * 1e5) };
      line.push(rnd() < 0.7);
      ends.push(line[i] ? [a, { x: a.x + Math.round((rnd() - 0.5) * 2e4), y: a.y }] : [a]);
    }
    const paths: PathSet = { count: n, entries: (i) => ends[i], line: (i) => line[i] };
    const from = { x: rnd() * 1e5, y: rnd() * 1e5 };
    const to = rnd() < 0.5 ? { x: rnd() * 1e5, y: rnd() * 1e5 } : null;
    const nearest = orderPaths(paths, { from });
    const short = orderPaths(paths, { from, to, shorten: true });
    assert.deepEqual(short, shortenOrder(paths, nearest, from, to));
    assert.deepEqual(
      short.map(([i]) => i).sort((a, b) => a - b),
      ends.map((_, i) => i),
    );
    for (const [i, c] of short) assert.ok(c < ends[i].length);
    assert.ok(tourLength(paths, short, from, to) <= tourLength(paths, nearest, from, to) + 1e-6);
  }
});

test('with an end point the shortened order ends near it; a line turned round is entered at its other end', () => {
  // a line 1 mm above the start, 10 mm long; a loop's entry under its far end; the end point 2 mm above the start
  const ends = [
    [
      { x: 0, y: 1000 },
      { x: 10000, y: 1000 },
    ],
    [{ x: 10000, y: 0 }],
  ];
  const paths: PathSet = { count: 2, entries: (i) => ends[i], line: (i) => i === 0 };
  const from = { x: 0, y: 0 },
    to = { x: 0, y: 2000 };
  assert.deepEqual(orderPaths(paths, { from }), [
    [0, 0],
    [1, 0],
  ]);
  // out to the loop first, then back along the line, entered at its far end
  const short = orderPaths(paths, { from, to, shorten: true });
  assert.deepEqual(short, [
    [1, 0],
    [0, 1],
  ]);
  assert.equal(tourLength(paths, short, from, to), 12000);
});
