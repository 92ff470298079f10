import { test } from 'node:test';
import assert from 'node:assert/strict';
import { shortenTour, type TourStop } from '#strata/order/shorten.js';
import type { Pt } from '#strata/geometry/types.js';

/** Travel of stops in the order given, from `from` and on to `to` (µm). */
function travel(
  stops: readonly TourStop[],
  order: ArrayLike<number>,
  reversed: ArrayLike<number>,
  from: Pt,
  to: Pt | null,
) {
  let at = from,
    sum = 0;
  for (let k = 0; k < order.length; k++) {
    const s = stops[order[k]];
    const a = reversed[k] ? s.out : s.in;
    sum += Math.hypot(a.x - at.x, a.y - at.y);
    at = reversed[k] ? s.in : s.out;
  }
  return to ? sum + Math.hypot(to.x - at.x, to.y - at.y) : sum;
}

test('a shortened tour visits every stop once and never travels further than the order it was given', () => {
  let seed = 7;
  const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
  for (let trial = 0; trial < 200; trial++) {
    const n = 1 + Math.floor(rnd() * 240);
    const stops: TourStop[] = [];
    for (let i = 0; i < n; i++) {
      const a = { x: Math.round(rnd() * 1e5), y: Math.round(rnd() * 1e5) };
      // loops (entered where they are left) and lines
      const b =
        rnd() < 0.3 ? a : { x: a.x + Math.round((rnd() - 0.5) * 2e4), y: a.y + Math.round((rnd() - 0.5) * 2e4) };
      stops.push({ in: a, out: b });
    }
    const from = { x: rnd() * 1e5, y: rnd() * 1e5 };
    const to = rnd() < 0.5 ? { x: rnd() * 1e5, y: rnd() * 1e5 } : null;
    const given = travel(stops, Int32Array.from(stops.keys()), new Uint8Array(n), from, to);
    const t = shortenTour(stops, from, to);
    assert.equal(new Set(t.order).size, n);
    assert.ok(travel(stops, t.order, t.reversed, from, to) <= given + 1e-6);
  }
});

test('two rows of lines visited alternately become one row out and the other back', () => {
  // lines 10 mm long along x, in two rows 5 mm apart; given alternating between the rows
  const row = (y: number, i: number): TourStop => ({ in: { x: i * 11000, y }, out: { x: i * 11000 + 10000, y } });
  const stops: TourStop[] = [];
  for (let i = 0; i < 8; i++) stops.push(row(0, i), row(5000, i));
  const from = { x: 0, y: 0 };
  const t = shortenTour(stops, from, null);
  // 1 mm between the lines of a row, 5 mm across to the other at the far end
  assert.ok(travel(stops, t.order, t.reversed, from, null) <= 14 * 1000 + 5000 + 1);
});

test('with an end point the tour ends near it', () => {
  const stops: TourStop[] = [0, 1, 2, 3].map((i) => ({ in: { x: i * 10000, y: 0 }, out: { x: i * 10000, y: 0 } }));
  const from = { x: 15000, y: 0 },
    to = { x: 0, y: 0 };
  const t = shortenTour(stops, from, to);
  // out to the far stop first, then back along the others
  assert.equal(travel(stops, t.order, t.reversed, from, to), 45000);
  assert.equal(t.order[3], 0);
});
