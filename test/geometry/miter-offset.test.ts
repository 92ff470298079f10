import { test } from 'node:test';
import assert from 'node:assert/strict';
import { rawMiterOffset } from '#strata/geometry/miter-offset.js';
import { area, offset, pointInArea } from '#strata/geometry/clip.js';
import type { ExPolygon, Polygon, Pt } from '#strata/geometry/types.js';

const regular = (n: number, r: number): Polygon =>
  Array.from({ length: n }, (_, i) => ({
    x: Math.round(r * Math.cos((2 * Math.PI * i) / n)),
    y: Math.round(r * Math.sin((2 * Math.PI * i) / n)),
  }));

/** A star with `n` spikes: radii alternate between r and r/2 (concave corners on every other vertex). */
const star = (n: number, r: number): Polygon =>
  Array.from({ length: 2 * n }, (_, i) => {
    const rad = i % 2 === 0 ? r : r / 2;
    const a = (Math.PI * i) / n;
    return { x: Math.round(rad * Math.cos(a)), y: Math.round(rad * Math.sin(a)) };
  });

function distToRing(p: Pt, ring: Polygon): number {
  let best = Infinity;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    const a = ring[j],
      b = ring[i];
    const dx = b.x - a.x,
      dy = b.y - a.y;
    const t = Math.max(0, Math.min(1, ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy)));
    best = Math.min(best, Math.hypot(a.x + t * dx - p.x, a.y + t * dy - p.y));
  }
  return best;
}

test('shrinking a regular polygon gives the regular polygon with its apothem reduced by the offset', () => {
  const n = 64,
    r = 20000,
    d = 400;
  const out = offset([{ outer: regular(n, r), holes: [] }], -d);
  const apothem = r * Math.cos(Math.PI / n) - d;
  const expected = n * apothem * apothem * Math.tan(Math.PI / n);
  assert.equal(out.length, 1);
  assert.ok(Math.abs(area(out) - expected) / expected < 1e-4, `${area(out)} vs ${expected}`);
});

test('shrunk and grown stars keep every vertex at the offset distance from the outline', () => {
  const s: ExPolygon = { outer: star(12, 10000), holes: [] };
  for (const d of [-150, -400, 300]) {
    const out = offset([s], d);
    assert.ok(out.length >= 1);
    for (const island of out) {
      for (const p of island.outer) {
        assert.ok(distToRing(p, s.outer) >= Math.abs(d) - 2, `vertex ${p.x},${p.y} too close for ${d}`);
        assert.equal(pointInArea(p, s), d < 0);
      }
    }
  }
});

test('a shrink that eats thin parts splits or removes them like a full union', () => {
  // a dumbbell: two 4 mm squares joined by a 0.5 mm neck
  const ring: Polygon = [
    { x: 0, y: 0 },
    { x: 4000, y: 0 },
    { x: 4000, y: 1750 },
    { x: 6000, y: 1750 },
    { x: 6000, y: 0 },
    { x: 10000, y: 0 },
    { x: 10000, y: 4000 },
    { x: 6000, y: 4000 },
    { x: 6000, y: 2250 },
    { x: 4000, y: 2250 },
    { x: 4000, y: 4000 },
    { x: 0, y: 4000 },
  ];
  const out = offset([{ outer: ring, holes: [] }], -400);
  assert.equal(out.length, 2);
  assert.equal(area(out), 2 * 3200 * 3200);
});

test('a corner past the mitre limit is squared off at the offset distance from the vertex', () => {
  const sharp: Polygon = [
    { x: 0, y: 0 },
    { x: 10000, y: 0 },
    { x: 0, y: 2000 },
  ];
  const [raw] = rawMiterOffset([sharp], 200, 3)?.rings ?? [];
  assert.equal(raw.length, 4);
  // two points at the sharp tip, on the cut 200 µm beyond it, instead of one far mitre point
  const tip = raw.slice(1, 3);
  for (const p of tip)
    assert.ok(Math.hypot(p.x - 10000, p.y) > 199 && Math.hypot(p.x - 10000, p.y) < 600, `${p.x},${p.y}`);
  assert.ok(Math.abs(tip[0].y - tip[1].y) > 100);
  const out = offset([{ outer: sharp, holes: [] }], 200);
  assert.equal(out.length, 1);
  assert.ok(out[0].outer.every((p) => distToRing(p, sharp) >= 198 && distToRing(p, sharp) <= 3 * 200 + 2));
});

test('a spike is squared off 200 µm beyond its tip', () => {
  const spike: Polygon = [
    { x: 0, y: 0 },
    { x: 10000, y: 0 },
    { x: 0, y: 200 },
  ];
  const [raw] = rawMiterOffset([spike], 200, 3)?.rings ?? [];
  assert.equal(raw.length, 4);
  for (const p of raw.slice(1, 3)) assert.ok(p.x >= 10195 && p.x <= 10205, `${p.x}`);
  const out = offset([{ outer: spike, holes: [] }], 200);
  assert.ok(out[0].outer.every((p) => distToRing(p, spike) >= 198));
  assert.deepEqual(offset([{ outer: spike, holes: [] }], -200), []);
});

test('repeated points and clockwise outers are left to the general offsetter', () => {
  const spike: Polygon = [
    { x: 0, y: 0 },
    { x: 10000, y: 0 },
    { x: 0, y: 200 },
  ];
  const sq = regular(4, 5000);
  assert.equal(rawMiterOffset([[...sq].reverse()], -200, 3), null);
  assert.equal(rawMiterOffset([[sq[0], sq[0], sq[1], sq[2]]], -200, 3), null);
  assert.notEqual(rawMiterOffset([sq], -200, 3), null);
  // the facade still offsets them
  assert.ok(area(offset([{ outer: spike, holes: [] }], 200)) > 0);
});

test('edges used up between concave corners are dropped, not left to the union as loops', () => {
  // a 20 mm circle whose edges alternate long and short (126 µm), shrunk by 5 mm: the short
  // offset edges are used up by their two corners
  const r = 20000,
    d = 5000;
  const ring: Polygon = [];
  let a = 0;
  for (let i = 0; i < 200; i++) {
    ring.push({ x: Math.round(r * Math.cos(a)), y: Math.round(r * Math.sin(a)) });
    a += ((i % 2 === 0 ? 1.8 : 0.2) * Math.PI) / 100;
  }
  const raw = rawMiterOffset([ring], -d, 3);
  assert.ok(raw);
  assert.equal(raw.loops, false);
  assert.equal(raw.rings[0].length, 100);
  const out = offset([{ outer: ring, holes: [] }], -d);
  assert.equal(out.length, 1);
  for (const p of out[0].outer) {
    assert.ok(distToRing(p, ring) >= d - 2, `${p.x},${p.y}`);
    assert.ok(Math.hypot(p.x, p.y) < r - d + 50, `${p.x},${p.y}`);
  }
  const inner = r * Math.cos((0.9 * Math.PI) / 100) - d;
  assert.ok(area(out) > Math.PI * inner * inner && area(out) < Math.PI * (r - d) * (r - d));
});
