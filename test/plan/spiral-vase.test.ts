import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Pt } from '#strata/geometry/types.js';
import { finishingTurn, nearestOnLoop, openLoopNear, spiralTurn, type VaseRun } from '#strata/plan/spiral-vase.js';

/** A 10 mm square loop, counter-clockwise, µm. */
const SQUARE: Pt[] = [
  { x: 0, y: 0 },
  { x: 10000, y: 0 },
  { x: 10000, y: 10000 },
  { x: 0, y: 10000 },
];
const loop = (extra: Partial<VaseRun> = {}): VaseRun => ({
  points: SQUARE,
  closed: true,
  width: 0.4,
  widths: null,
  z: null,
  flags: null,
  ...extra,
});

function lengths(points: readonly Pt[]): number[] {
  const d = [0];
  for (let k = 1; k < points.length; k++)
    d.push(d[k - 1] + Math.hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y));
  return d;
}

test('the nearest point of a loop: inside an edge, or the corner within a few µm', () => {
  assert.deepEqual(nearestOnLoop(SQUARE, { x: 4000, y: -300 }), { edge: 0, at: { x: 4000, y: 0 }, t: 0.4 });
  assert.deepEqual(nearestOnLoop(SQUARE, { x: 10300, y: 6000 }).at, { x: 10000, y: 6000 });
  assert.deepEqual(nearestOnLoop(SQUARE, { x: 10002, y: 10003 }), { edge: 2, at: { x: 10000, y: 10000 }, t: 0 });
});

test('a loop opened near a point goes once round from the nearest point back to it, its channels turned with it', () => {
  const flags = Uint8Array.from([1, 0, 0, 2]);
  const widths = Float64Array.from([0.4, 0.5, 0.4, 0.3]);
  const o = openLoopNear(loop({ flags, widths }), { x: 2500, y: 100 });
  assert.deepEqual(o.points, [{ x: 2500, y: 0 }, SQUARE[1], SQUARE[2], SQUARE[3], SQUARE[0], { x: 2500, y: 0 }]);
  assert.deepEqual([...o.flags!], [1, 0, 0, 2, 1], 'the start edge is split: its flag on both ends');
  assert.deepEqual(
    [...o.widths!].map((w) => +w.toFixed(3)),
    [0.425, 0.5, 0.4, 0.3, 0.4, 0.425],
  );
  assert.equal(o.closed, false);
  const corner = openLoopNear(loop(), { x: 9997, y: 10004 }); // 3 µm along edge 2 from its corner: the corner
  assert.deepEqual(corner.points, [SQUARE[2], SQUARE[3], SQUARE[0], SQUARE[1], SQUARE[2]]);
});

test('a turn rises linearly in its length from the layer below to the layer, strictly, and ends at the layer', () => {
  const opened = openLoopNear(loop(), { x: 2500, y: 0 });
  const from = { x: 2480, y: -30 }; // the previous turn's end, a little off the new outline
  const turn = spiralTurn(opened, from, -0.2, false);
  assert.deepEqual(turn.points[0], from, 'the previous end leads in: no travel');
  assert.equal(turn.points.length, opened.points.length + 1);
  const z = turn.z!;
  const d = lengths(turn.points);
  assert.equal(z[0], -0.2);
  assert.equal(z[z.length - 1], 0);
  for (let k = 1; k < z.length; k++) {
    assert.ok(z[k] > z[k - 1], `Z rises at every point (${k})`);
    assert.ok(Math.abs(z[k] - (-0.2 + (0.2 * d[k]) / d[d.length - 1])) < 1e-12, 'linear in the length');
  }
  assert.equal(turn.widths, null, 'full flow: the loop keeps its width');
  // starting on the new outline: no lead-in point
  assert.deepEqual(spiralTurn(opened, opened.points[0], -0.2, false).points, opened.points);
});

test('a first turn grows its flow from nothing; the finishing turn shrinks it to nothing, flat', () => {
  const opened = openLoopNear(loop(), { x: 0, y: 5000 });
  const first = spiralTurn(opened, null, -0.2, true);
  const d = lengths(first.points);
  const total = d[d.length - 1];
  first.widths!.forEach((w, k) => assert.ok(Math.abs(w - (0.4 * d[k]) / total) < 1e-12));
  assert.equal(first.widths![0], 0);
  const finish = finishingTurn(opened);
  assert.equal(finish.z, null);
  assert.deepEqual(finish.points, opened.points);
  finish.widths!.forEach((w, k) => assert.ok(Math.abs(w - 0.4 * (1 - d[k] / total)) < 1e-12));
  // together a bead of one width everywhere: the rising turn's share and the finishing turn's add to one
  for (let k = 0; k < d.length; k++) assert.ok(Math.abs(first.widths![k] + finish.widths![k] - 0.4) < 1e-12);
});
