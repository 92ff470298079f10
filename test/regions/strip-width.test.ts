import { test } from 'node:test';
import assert from 'node:assert/strict';
import { stripWidthUm } from '#strata/regions/strip-width.js';

const rect = (w: number, l: number) => ({
  outer: [
    { x: 0, y: 0 },
    { x: l, y: 0 },
    { x: l, y: w },
    { x: 0, y: w },
  ],
  holes: [],
});

test('strip width is exact for rectangles, where the mean width 2A/P falls short', () => {
  for (const [w, l] of [
    [500, 10_000],
    [300, 1_000],
    [1_000, 1_000],
  ]) {
    assert.ok(Math.abs(stripWidthUm(rect(w, l)) - w) < 1e-6, `${w} × ${l}`);
    assert.ok((2 * w * l) / (2 * (w + l)) < w);
  }
  const wedge = {
    outer: [
      { x: 0, y: 0 },
      { x: 10_000, y: 0 },
      { x: 0, y: 400 },
    ],
    holes: [],
  };
  const d = stripWidthUm(wedge);
  assert.ok(d > 150 && d < 250, `wedge ${d}`);
});
