/**
 * The point index against plain polygon tests: containment (whichever way its ray goes), meeting an area,
 * and crossing a segment, on random islands with holes and random queries.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pointInArea } from '#strata/geometry/clip.js';
import { segmentsMeet } from '#strata/geometry/contain.js';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import { AreaIndex } from '#strata/geometry/area-index.js';
import { rect } from './test-shapes.js';

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => (s = (s * 1664525 + 1013904223) >>> 0) / 2 ** 32;
}

/** A star-shaped ring round (cx, cy) with radii in [r/2, r], counter-clockwise (or clockwise for a hole). */
function star(cx: number, cy: number, r: number, n: number, rand: () => number, hole = false): Pt[] {
  const out: Pt[] = [];
  for (let k = 0; k < n; k++) {
    const a = (2 * Math.PI * k) / n;
    const rr = r * (0.5 + 0.5 * rand());
    out.push({ x: Math.round(cx + rr * Math.cos(a)), y: Math.round(cy + rr * Math.sin(a)) });
  }
  return hole ? out.reverse() : out;
}

/** Islands spread over a wide strip (so rays along x and y walk different numbers of cells). */
function islands(rand: () => number): ExPolygon[] {
  const out: ExPolygon[] = [];
  for (let k = 0; k < 6; k++) {
    const cx = 20_000 + k * 30_000,
      cy = 15_000;
    out.push({ outer: star(cx, cy, 12_000, 40, rand), holes: [star(cx, cy, 4_000, 12, rand, true)] });
  }
  return out;
}

const distToSegment = (p: Pt, a: Pt, b: Pt) => {
  const dx = b.x - a.x,
    dy = b.y - a.y;
  const u = Math.max(0, Math.min(1, ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy)));
  return Math.hypot(a.x + u * dx - p.x, a.y + u * dy - p.y);
};

const nearBoundary = (p: Pt, areas: readonly ExPolygon[], d: number) =>
  areas.some((a) =>
    [a.outer, ...a.holes].some((r) => r.some((q, i) => distToSegment(p, q, r[(i + 1) % r.length]) < d)),
  );

test('contains agrees with the polygon test away from the boundary, wherever the point is', () => {
  const rand = rng(11);
  const areas = islands(rand);
  const index = new AreaIndex(areas);
  let inside = 0,
    checked = 0;
  for (let k = 0; k < 4000; k++) {
    const p = { x: Math.round(-5_000 + 190_000 * rand()), y: Math.round(-5_000 + 40_000 * rand()) };
    if (nearBoundary(p, areas, 1)) continue;
    const want = areas.some((a) => pointInArea(p, a));
    assert.equal(index.contains(p.x, p.y), want, `(${p.x}, ${p.y})`);
    checked++;
    if (want) inside++;
  }
  // the queries cover both answers
  assert.ok(inside > 500 && checked - inside > 500, `${inside} of ${checked} inside`);
});

test('meets agrees with a plain test of vertices and edges', () => {
  const rand = rng(5);
  const areas = islands(rand);
  const index = new AreaIndex(areas);
  const edges = (a: ExPolygon) =>
    [a.outer, ...a.holes].flatMap((r) => r.map((p, i) => [p, r[(i + 1) % r.length]] as const));
  let hits = 0;
  for (let k = 0; k < 400; k++) {
    const c = { x: Math.round(190_000 * rand()), y: Math.round(30_000 * rand()) };
    const probe: ExPolygon = { outer: star(c.x, c.y, 500 + 6_000 * rand(), 10, rand), holes: [] };
    const want =
      probe.outer.some((p) => areas.some((a) => pointInArea(p, a))) ||
      areas.some((a) => pointInArea(a.outer[0], probe) || a.holes.some((h) => pointInArea(h[0], probe))) ||
      edges(probe).some(([p, q]) =>
        areas.some((a) => edges(a).some(([r, s]) => segmentsMeet(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y))),
      );
    assert.equal(index.meets(probe), want, `probe at (${c.x}, ${c.y})`);
    if (want) hits++;
  }
  assert.ok(hits > 50 && hits < 350, `${hits} of 400 meet`);
});

test('nearestOutside finds the way out when the nearest edge leads into another area a few µm away', () => {
  // two squares 3 µm apart: out through the right edge of the first lands in the second
  const ix = new AreaIndex([rect(0, 0, 1000, 1000), rect(1003, 0, 2000, 1000)]);
  const p = { x: 990, y: 500 };
  assert.ok(ix.contains(p.x, p.y));
  const q = ix.nearestOutside(p.x, p.y, 600);
  assert.ok(q !== null, 'a way out within 600 µm (the top edge, 500 µm off)');
  assert.ok(!ix.contains(q.x, q.y), `${q.x}, ${q.y} lies outside`);
  assert.ok(Math.hypot(q.x - p.x, q.y - p.y) <= 600, `${q.x}, ${q.y} within reach`);
  // nothing within 400 µm: none
  assert.equal(ix.nearestOutside(500, 500, 400), null);
});
