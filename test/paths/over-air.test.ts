import { test } from 'node:test';
import assert from 'node:assert/strict';
import { rect } from '../geometry/test-shapes.js';
import { flagLevels, flagOverAir, indexArea } from '#strata/paths/over-air.js';

const air = indexArea([rect(10_000, -5_000, 20_000, 5_000)]);

test('a line across an area over air is split exactly at its edges, the middle run flagged', () => {
  const f = flagOverAir(
    [
      { x: 0, y: 0 },
      { x: 30_000, y: 0 },
    ],
    false,
    air,
  )!;
  assert.deepEqual(f.points, [
    { x: 0, y: 0 },
    { x: 10_000, y: 0 },
    { x: 20_000, y: 0 },
    { x: 30_000, y: 0 },
  ]);
  assert.deepEqual([...f.flags], [0, 1, 0]);
});

test('a loop keeps its shape: flags per edge, the closing edge included', () => {
  // a square loop whose right side runs through the area
  const loop = [
    { x: 15_000, y: -2_000 },
    { x: 15_000, y: 2_000 },
    { x: 0, y: 2_000 },
    { x: 0, y: -2_000 },
  ];
  const f = flagOverAir(loop, true, air)!;
  assert.equal(f.flags.length, f.points.length, 'one flag per edge of a closed path');
  // edge 0 (inside), then the top edge leaves the area at x = 10 mm, the left side is outside, the bottom comes back in
  assert.deepEqual(f.points, [
    { x: 15_000, y: -2_000 },
    { x: 15_000, y: 2_000 },
    { x: 10_000, y: 2_000 },
    { x: 0, y: 2_000 },
    { x: 0, y: -2_000 },
    { x: 10_000, y: -2_000 },
  ]);
  assert.deepEqual([...f.flags], [1, 1, 0, 0, 0, 1]);
});

test('paths clear of the area are left alone', () => {
  assert.equal(
    flagOverAir(
      [
        { x: 0, y: 10_000 },
        { x: 30_000, y: 10_000 },
      ],
      false,
      air,
    ),
    null,
  );
  assert.equal(
    flagOverAir(
      [
        { x: 0, y: 0 },
        { x: 5_000, y: 0 },
      ],
      false,
      air,
    ),
    null,
  );
  assert.equal(
    flagOverAir(
      [
        { x: 0, y: 0 },
        { x: 5_000, y: 0 },
      ],
      false,
      indexArea([]),
    ),
    null,
  );
});

test('levels: a line across nested areas is cut at each edge and flagged with the highest level holding each piece (areas in a grid or not)', () => {
  for (const grid of [false, true]) {
    // levels 1 to 4 as nested bands, as overhang levels are: each further out from the layer below
    const levels = [10_000, 12_000, 14_000, 16_000].map((x0) => indexArea([rect(x0, -5_000, 30_000, 5_000)], grid));
    const f = flagLevels(
      [
        { x: 0, y: 0 },
        { x: 20_000, y: 0 },
      ],
      false,
      levels,
    )!;
    assert.deepEqual(
      f.points.map((p) => p.x),
      [0, 10_000, 12_000, 14_000, 16_000, 20_000],
    );
    assert.deepEqual([...f.flags], [0, 1, 2, 3, 4]);
    // a level with nothing in it: its pieces take the level below
    const gap = flagLevels(
      [
        { x: 0, y: 0 },
        { x: 20_000, y: 0 },
      ],
      false,
      [levels[0], indexArea([], grid), levels[2], levels[3]],
    )!;
    assert.deepEqual([...gap.flags], [0, 1, 3, 4]);
    // a loop round a hole's corner: in and out of the band
    const ring = flagLevels(
      [
        { x: 8_000, y: -1_000 },
        { x: 11_000, y: -1_000 },
        { x: 11_000, y: 1_000 },
        { x: 8_000, y: 1_000 },
      ],
      true,
      levels,
    )!;
    assert.deepEqual(
      [ring.points.map((p) => p.x), [...ring.flags]],
      [
        [8_000, 10_000, 11_000, 11_000, 10_000, 8_000],
        [0, 1, 1, 1, 0, 0],
      ],
    );
  }
});

test("levels: pieces of one edge on one level are one edge again, the path's own points kept; widths follow", () => {
  // two level-1 areas side by side (a seam of the clipper's output): no cut between them
  const twin = [
    indexArea([rect(5_000, -5_000, 10_000, 5_000), rect(10_000, -5_000, 15_000, 5_000)]),
    indexArea([]),
    indexArea([]),
    indexArea([]),
  ];
  const line = [
    { x: 0, y: 0 },
    { x: 8_000, y: 0 },
    { x: 20_000, y: 0 },
  ];
  const f = flagLevels(line, false, twin, Float64Array.from([0.4, 0.5, 0.6]))!;
  assert.deepEqual(
    f.points.map((p) => p.x),
    [0, 5_000, 8_000, 15_000, 20_000],
    'the cut at x = 10 mm is gone, the vertex at 8 mm stays',
  );
  assert.deepEqual([...f.flags], [0, 1, 1, 0]);
  assert.deepEqual(
    [...f.widths!].map((w) => Math.round(w * 1000) / 1000),
    [0.4, 0.463, 0.5, 0.558, 0.6],
  );
  // a loop round the areas' corner: one flag per edge
  const loop = flagLevels(
    [
      { x: 12_000, y: 0 },
      { x: 0, y: 0 },
      { x: 0, y: 3_000 },
      { x: 12_000, y: 3_000 },
    ],
    true,
    twin,
  )!;
  assert.equal(loop.flags.length, loop.points.length);
  assert.equal(
    flagLevels(
      [
        { x: 0, y: 20_000 },
        { x: 9_000, y: 20_000 },
      ],
      false,
      twin,
    ),
    null,
    'clear of every level',
  );
});
