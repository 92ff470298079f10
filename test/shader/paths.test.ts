import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Polyline } from '#strata/geometry/types.js';
import { chainPaths } from '#strata/shader/paths.js';

const line = (...xs: number[]): Polyline => xs.map((x) => ({ x, y: 0 }));

test('chained custom infill paths: nearest first, turned round where entered at their end, touching ends joined', () => {
  // entered from the right: the far line first, turned round, then the near one, which touches it (3 µm)
  const out = chainPaths([line(0, 1000), line(1003, 2000), line(10000, 11000)], { x: 12000, y: 0 });
  assert.deepEqual(out, [line(11000, 10000), line(2000, 1003, 1000, 0)]);
  // lines meeting at one point are joined without repeating it
  assert.deepEqual(chainPaths([line(0, 1000), line(1000, 2000)], { x: 0, y: 0 }), [line(0, 1000, 2000)]);
  // shorter than two points: dropped
  assert.deepEqual(chainPaths([line(5), []], { x: 0, y: 0 }), []);
});

test('a closed path is found by its first point and started at its vertex nearest the nozzle, never joined', () => {
  const square: Polyline = [
    { x: 0, y: 0 },
    { x: 1000, y: 0 },
    { x: 1000, y: 1000 },
    { x: 0, y: 1000 },
    { x: 0, y: 0 },
  ];
  // a line ending at the square's far corner: the square follows, started there and closed again there
  const out = chainPaths(
    [
      square,
      [
        { x: 3000, y: 1000 },
        { x: 1000, y: 1000 },
      ],
    ],
    { x: 3000, y: 1000 },
  );
  assert.deepEqual(out, [
    [
      { x: 3000, y: 1000 },
      { x: 1000, y: 1000 },
    ],
    [
      { x: 1000, y: 1000 },
      { x: 0, y: 1000 },
      { x: 0, y: 0 },
      { x: 1000, y: 0 },
      { x: 1000, y: 1000 },
    ],
  ]);
});
