import { test } from 'node:test';
import assert from 'node:assert/strict';
import { classicWalls } from '#strata/regions/walls.js';
import type { IslandWalls } from '#strata/regions/walls.js';
import { area, ringArea } from '#strata/geometry/clip.js';
import type { ExPolygon } from '#strata/geometry/types.js';
import { square } from '../geometry/test-shapes.js';

/** The classic wall loops by index (gap loops left out). */
const loops = (w: IslandWalls) => w.walls.filter((s) => s.role === 'wall').map((s) => s.paths);

test('a 20 mm square gets two walls at 0.2 and 0.6 mm inside, and an inner area 0.8 mm in', () => {
  const [w] = classicWalls([square(0, 0, 20000)], 2, 400);
  assert.equal(loops(w).length, 2);
  assert.equal(Math.round(Math.abs(ringArea(loops(w)[0][0]))), 19600 * 19600);
  assert.equal(Math.round(Math.abs(ringArea(loops(w)[1][0]))), 18800 * 18800);
  assert.equal(Math.round(area(w.inner)), 18400 * 18400);
});

test('a hole gets its own wall loop in each wall', () => {
  const island: ExPolygon = {
    ...square(0, 0, 20000),
    holes: [
      [
        { x: 5000, y: 5000 },
        { x: 5000, y: 15000 },
        { x: 15000, y: 15000 },
        { x: 15000, y: 5000 },
      ],
    ],
  };
  const [w] = classicWalls([island], 2, 400);
  assert.equal(loops(w)[0].length, 2);
  assert.equal(loops(w)[1].length, 2);
});

test('a 1 mm strip gets the outer wall only: no inner wall that would overlap it', () => {
  const strip: ExPolygon = {
    outer: [
      { x: 0, y: 0 },
      { x: 20000, y: 0 },
      { x: 20000, y: 1000 },
      { x: 0, y: 1000 },
    ],
    holes: [],
  };
  const [w] = classicWalls([strip], 3, 400);
  assert.equal(loops(w).length, 1);
  assert.equal(w.inner.length, 0);
});

test('a strip thinner than one line width gets nothing rather than a crossing wall', () => {
  const strip: ExPolygon = {
    outer: [
      { x: 0, y: 0 },
      { x: 20000, y: 0 },
      { x: 20000, y: 300 },
      { x: 0, y: 300 },
    ],
    holes: [],
  };
  const [w] = classicWalls([strip], 2, 400);
  assert.equal(loops(w).flat().length, 0);
});
