import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cleanPaths } from '#strata/infill/cleanup.js';

test('a segment printed twice is kept once; the later path is split around it', () => {
  const a = [
    { x: 0, y: 0 },
    { x: 10, y: 0 },
    { x: 10, y: 10 },
  ];
  const b = [
    { x: 10, y: 10 },
    { x: 10, y: 0 },
    { x: 20, y: 0 },
  ];
  assert.deepEqual(cleanPaths([a, b], [], 0), {
    lines: [
      a,
      [
        { x: 10, y: 0 },
        { x: 20, y: 0 },
      ],
    ],
    loops: [],
  });
});

test('a loop sharing a segment with a line opens there; repeats and short paths go', () => {
  const loop = [
    { x: 0, y: 0 },
    { x: 10, y: 0 },
    { x: 10, y: 10 },
    { x: 0, y: 10 },
  ];
  const r = cleanPaths(
    [
      [
        { x: 10, y: 0 },
        { x: 0, y: 0 },
      ],
    ],
    [loop],
    0,
  );
  assert.deepEqual(r.loops, []);
  assert.deepEqual(r.lines[1], [
    { x: 10, y: 0 },
    { x: 10, y: 10 },
    { x: 0, y: 10 },
    { x: 0, y: 0 },
  ]);
  const s = cleanPaths(
    [
      [
        { x: 0, y: 0 },
        { x: 0, y: 0 },
        { x: 5, y: 0 },
      ],
      [
        { x: 1, y: 1 },
        { x: 1, y: 1 },
      ],
    ],
    [],
    3,
  );
  assert.deepEqual(s.lines, [
    [
      { x: 0, y: 0 },
      { x: 5, y: 0 },
    ],
  ]);
});
