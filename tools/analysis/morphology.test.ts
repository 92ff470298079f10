import { test } from 'node:test';
import assert from 'node:assert/strict';
import { close, dilate, dropSmallComponents, erode, grownClosings, squaredDistance } from './morphology.js';

const count = (b: Uint8Array) => b.reduce((n, v) => n + (v !== 0 ? 1 : 0), 0);

/** A cols × rows bitmap with the cells of rectangle [i0, i1) × [j0, j1) set. */
function rect(cols: number, rows: number, ...boxes: [number, number, number, number][]): Uint8Array {
  const b = new Uint8Array(cols * rows);
  for (const [i0, j0, i1, j1] of boxes) for (let j = j0; j < j1; j++) for (let i = i0; i < i1; i++) b[j * cols + i] = 1;
  return b;
}

test('squared distances equal a brute-force search', () => {
  const cols = 37,
    rows = 23;
  const b = new Uint8Array(cols * rows);
  let seed = 7;
  for (let k = 0; k < b.length; k++) {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    b[k] = seed % 29 === 0 ? 1 : 0;
  }
  const d = squaredDistance(b, cols, rows, 1);
  for (let k = 0; k < b.length; k++) {
    let best = Infinity;
    for (let q = 0; q < b.length; q++) {
      if (b[q] === 0) continue;
      const di = (k % cols) - (q % cols),
        dj = Math.floor(k / cols) - Math.floor(q / cols);
      best = Math.min(best, di * di + dj * dj);
    }
    assert.equal(d[k], best, `cell ${k}`);
  }
});

test('dilation by a disc, erosion, and closing of gaps', () => {
  const one = new Uint8Array(21 * 21);
  one[10 * 21 + 10] = 1;
  // Lattice points within 3 of a point: 29.
  assert.equal(count(dilate(one, 21, 21, 3)), 29);
  const square = rect(31, 31, [5, 5, 26, 26]);
  assert.equal(count(erode(square, 31, 31, 3, false)), 15 * 15);
  // Beyond the window counts as set unless told otherwise.
  const full = new Uint8Array(10 * 10).fill(1);
  assert.equal(count(erode(full, 10, 10, 2)), 100);
  assert.equal(count(erode(full, 10, 10, 2, false)), 36);
  // Two blocks 4 cells apart close up with r = 3 (but for the row at each end of the gap, where a disc of radius 3
  // still dips 0.76 cells into a gap 4 wide); 8 cells apart they do not.
  const near = rect(40, 20, [5, 5, 15, 15], [19, 5, 29, 15]);
  assert.equal(count(close(near, 40, 20, 3)), 24 * 10 - 2 * 4);
  const far = rect(40, 20, [5, 5, 15, 15], [23, 5, 33, 15]);
  assert.equal(count(close(far, 40, 20, 3)), 200);
  // Grown closings: growing by 0 is the closing, growing by r the dilation, of a convex block.
  const within = grownClosings(far, 40, 20, 3);
  const grown = (g: number) => count(Uint8Array.from({ length: 800 }, (_, k) => (within(k, g) ? 1 : 0)));
  assert.equal(grown(0), 200);
  assert.equal(grown(3), count(dilate(far, 40, 20, 3)));
});

test('components smaller than the limit are dropped, diagonal neighbours join', () => {
  const b = rect(20, 20, [1, 1, 4, 4], [10, 10, 16, 16]);
  b[4 * 20 + 4] = 1; // touches the small block at a corner: 10 cells together
  dropSmallComponents(b, 20, 20, 10);
  assert.equal(count(b), 10 + 36);
  dropSmallComponents(b, 20, 20, 11);
  assert.equal(count(b), 36);
});
