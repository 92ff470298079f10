import { test } from 'node:test';
import assert from 'node:assert/strict';
import { combRoute, makeCombArea } from '#strata/plan/comb.js';
import { pointInArea } from '#strata/geometry/clip.js';
import type { ExPolygon, Polygon, Pt } from '#strata/geometry/types.js';

const sq = (x0: number, y0: number, x1: number, y1: number): Polygon => [
  { x: x0, y: y0 },
  { x: x1, y: y0 },
  { x: x1, y: y1 },
  { x: x0, y: y1 },
];

function segmentsInside(a: Pt, way: Pt[], area: ExPolygon): boolean {
  // sample every path segment densely
  let p = a;
  for (const q of way) {
    for (let k = 1; k < 20; k++) {
      const s = { x: p.x + ((q.x - p.x) * k) / 20, y: p.y + ((q.y - p.y) * k) / 20 };
      if (!pointInArea(s, area)) return false;
    }
    p = q;
  }
  return true;
}

test('a travel across a hole goes around it and stays inside the island', () => {
  const hole = sq(8000, 8000, 12000, 12000).reverse();
  const outline: ExPolygon = { outer: sq(0, 0, 20000, 20000), holes: [hole] };
  // boundary to walk along: rings half a line width inside the material
  const boundary = [sq(200, 200, 19800, 19800), sq(7800, 7800, 12200, 12200).reverse()];
  const area = makeCombArea(outline, boundary);
  const a = { x: 2000, y: 10000 },
    b = { x: 18000, y: 10000 };
  const way = combRoute(a, b, area);
  assert.ok(way && way.length > 1, 'detoured');
  assert.deepEqual(way[way.length - 1], b);
  assert.ok(segmentsInside(a, way, outline));
});

test('a travel that stays inside needs no waypoints', () => {
  const outline: ExPolygon = { outer: sq(0, 0, 20000, 20000), holes: [] };
  const area = makeCombArea(outline, [sq(200, 200, 19800, 19800)]);
  assert.deepEqual(combRoute({ x: 1000, y: 1000 }, { x: 15000, y: 12000 }, area), [{ x: 15000, y: 12000 }]);
});

test('a travel across the notch of a U shape follows the outline instead of crossing air', () => {
  const u: Polygon = [
    { x: 0, y: 0 },
    { x: 30000, y: 0 },
    { x: 30000, y: 20000 },
    { x: 20000, y: 20000 },
    { x: 20000, y: 5000 },
    { x: 10000, y: 5000 },
    { x: 10000, y: 20000 },
    { x: 0, y: 20000 },
  ];
  const outline: ExPolygon = { outer: u, holes: [] };
  const inner: Polygon = [
    { x: 200, y: 200 },
    { x: 29800, y: 200 },
    { x: 29800, y: 19800 },
    { x: 20200, y: 19800 },
    { x: 20200, y: 4800 },
    { x: 9800, y: 4800 },
    { x: 9800, y: 19800 },
    { x: 200, y: 19800 },
  ];
  const area = makeCombArea(outline, [inner]);
  const a = { x: 5000, y: 15000 },
    b = { x: 25000, y: 15000 };
  const way = combRoute(a, b, area);
  assert.ok(way);
  assert.ok(segmentsInside(a, way, outline));
});
