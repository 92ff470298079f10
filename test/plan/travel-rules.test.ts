import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { ExPolygon, Pt } from '#strata/geometry/types.js';
import { printedIsland, RetractionWindow, routeOverIslands } from '#strata/plan/travel-rules.js';

const pt = (x: number, y: number): Pt => ({ x: x * 1000, y: y * 1000 });
const square = (x0: number, y0: number, side: number, holes: Pt[][] = []): ExPolygon => ({
  outer: [pt(x0, y0), pt(x0 + side, y0), pt(x0 + side, y0 + side), pt(x0, y0 + side)],
  holes,
});

test('a route is over a printed island when it crosses it or ends in it, not when it passes by or through a hole', () => {
  const a = square(0, 0, 10);
  const b = square(20, 0, 10);
  const ring = square(40, 0, 20, [[pt(45, 5), pt(45, 15), pt(55, 15), pt(55, 5)]]);
  const islands = [a, b, ring].map(printedIsland);
  // from a, over b, to the right: over b
  assert.equal(routeOverIslands(pt(5, 5), [pt(35, 5)], islands, a), true);
  // from a to the left: a is the one it leaves
  assert.equal(routeOverIslands(pt(5, 5), [pt(-10, 5)], islands, a), false);
  // above everything
  assert.equal(routeOverIslands(pt(5, 15), [pt(35, 15)], islands, a), false);
  // into the ring's hole without crossing the ring's band: not over
  assert.equal(routeOverIslands(pt(48, 8), [pt(52, 12)], islands, null), false);
  // across the ring's band from its hole: over
  assert.equal(routeOverIslands(pt(50, 10), [pt(50, 30)], islands, null), true);
  // a combed route: the second leg goes over b
  assert.equal(routeOverIslands(pt(5, 15), [pt(25, 15), pt(25, 5)], islands, a), true);
});

test('retraction window: at most countMax retractions within window mm of filament', () => {
  const w = new RetractionWindow(2, 10);
  assert.equal(w.full(), false);
  w.add();
  w.extruded += 3;
  w.add();
  // two within 3 mm of filament
  assert.equal(w.full(), true);
  w.extruded += 6.9;
  assert.equal(w.full(), true);
  w.extruded += 0.2;
  // the first is 10.1 mm back: out of the window
  assert.equal(w.full(), false);
  w.add();
  assert.equal(w.full(), true);
  // 0 = no limit
  const none = new RetractionWindow(0, 10);
  none.add();
  none.add();
  assert.equal(none.full(), false);
});
