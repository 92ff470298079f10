import { test } from 'node:test';
import assert from 'node:assert/strict';
import { SCARF_CLEARANCE_MM, scarfRuns, type ScarfLoop, type ScarfRun } from '#strata/plan/scarf.js';
import type { ScarfStyle } from '#strata/paths/roles.js';
import type { Pt } from '#strata/geometry/types.js';

const H = 0.2;
const W = 0.4;
const STYLE: ScarfStyle = { length: 20, startHeight: 0.1, steps: 10, conditional: false };

/** A counter-clockwise square `side` mm wide from (0, 0), corners only, optionally starting mid-way along its first side. */
function square(side: number, midStart = false): Pt[] {
  const s = side * 1000;
  const corners = [
    { x: 0, y: 0 },
    { x: s, y: 0 },
    { x: s, y: s },
    { x: 0, y: s },
  ];
  return midStart ? [{ x: s / 2, y: 0 }, corners[1], corners[2], corners[3], corners[0]] : corners;
}

const loopOf = (points: Pt[], extra: Partial<ScarfLoop> = {}): ScarfLoop => ({
  points,
  width: W,
  widths: null,
  z: null,
  flags: null,
  ...extra,
});

/** Length of a run's path, mm. */
function runLength(run: ScarfRun): number {
  let l = 0;
  for (let i = 1; i < run.points.length; i++)
    l += Math.hypot(run.points[i].x - run.points[i - 1].x, run.points[i].y - run.points[i - 1].y);
  return l / 1000;
}
/** Distance of each point from the run's start along it, mm. */
function along(run: ScarfRun): number[] {
  const d = [0];
  for (let i = 1; i < run.points.length; i++)
    d.push(d[i - 1] + Math.hypot(run.points[i].x - run.points[i - 1].x, run.points[i].y - run.points[i - 1].y) / 1000);
  return d;
}

test('a loop starts on a ramp of the scarf length: Z and flow rise together from the start height, in at least `steps` moves', () => {
  const runs = scarfRuns(loopOf(square(40, true)), STYLE, H)!;
  assert.equal(runs.length, 3);
  const [ramp, rest, wipe] = runs;
  assert.ok(Math.abs(runLength(ramp) - 20) < 0.01, `ramp ${runLength(ramp)} mm`);
  assert.ok(ramp.points.length - 1 >= STYLE.steps);
  const z = ramp.z!,
    w = ramp.widths!;
  assert.ok(Math.abs(z[0] - -(1 - 0.1) * H) < 1e-9, `starts 10 % of the layer above the layer below: ${z[0]}`);
  assert.equal(z[z.length - 1], 0, "ends at the layer's Z");
  const d = along(ramp);
  for (let j = 0; j < z.length; j++) {
    const share = 0.1 + (0.9 * d[j]) / 20;
    assert.ok(Math.abs(z[j] - -(1 - share) * H) < 1e-4, `Z linear along the ramp at ${d[j]} mm`);
    assert.ok(Math.abs(w[j] - W * share) < 1e-4, 'the flow follows the height under the nozzle');
    if (j > 0) assert.ok(z[j] > z[j - 1] && w[j] > w[j - 1], 'rising');
  }
  // the rest of the loop back to the seam, at the layer's Z, then over the ramp again
  assert.equal(rest.z, null);
  assert.deepEqual(rest.points[0], ramp.points[ramp.points.length - 1]);
  assert.deepEqual(rest.points[rest.points.length - 1], ramp.points[0]);
  assert.ok(Math.abs(runLength(ramp) + runLength(rest) - 160) < 0.01, 'ramp and rest are the loop');
  assert.equal(wipe.z, null, "the end runs over the ramp at the layer's Z");
  assert.deepEqual(wipe.points, ramp.points);
  for (let j = 0; j < w.length; j++)
    assert.ok(Math.abs(w[j] + wipe.widths![j] - W) < 1e-9, 'ramp and end lay one bead between them');
  assert.equal(wipe.widths![wipe.widths!.length - 1], 0, 'the flow shrinks to nothing');
});

test('the nozzle stays clear of the layer below: a start height of 0 starts at the clearance', () => {
  const [ramp] = scarfRuns(loopOf(square(40)), { ...STYLE, startHeight: 0 }, H)!;
  assert.ok(Math.abs(ramp.z![0] - (SCARF_CLEARANCE_MM - H)) < 1e-9);
  for (const z of ramp.z!) assert.ok(z >= SCARF_CLEARANCE_MM - H - 1e-12);
  // a layer too thin to ramp keeps its plain seam
  assert.equal(scarfRuns(loopOf(square(40)), STYLE, SCARF_CLEARANCE_MM), null);
});

test('a ramp keeps the corners it passes, and one ending on a corner leaves the rest from that corner', () => {
  // a 10 mm square: the ramp of 15 mm turns its first corner at 10 mm
  const runs = scarfRuns(loopOf(square(10)), { ...STYLE, length: 15, steps: 3 }, H)!;
  const [ramp, rest] = runs;
  assert.deepEqual(
    ramp.points.map((p) => [p.x, p.y]),
    [
      [0, 0],
      [5000, 0],
      [10000, 0],
      [10000, 5000],
    ],
  );
  assert.deepEqual(
    rest.points.map((p) => [p.x, p.y]),
    [
      [10000, 5000],
      [10000, 10000],
      [0, 10000],
      [0, 0],
    ],
  );
  const ends = scarfRuns(loopOf(square(10)), { ...STYLE, length: 20, steps: 2 }, H)!;
  assert.deepEqual(
    ends[0].points.map((p) => [p.x, p.y]),
    [
      [0, 0],
      [10000, 0],
      [10000, 10000],
    ],
  );
  assert.deepEqual(
    ends[1].points.map((p) => [p.x, p.y]),
    [
      [10000, 10000],
      [0, 10000],
      [0, 0],
    ],
  );
  // a ramp as long as the loop: the ramp and the end only
  const whole = scarfRuns(loopOf(square(10)), { ...STYLE, length: 40, steps: 4 }, H)!;
  assert.equal(whole.length, 2);
  assert.deepEqual(whole[0].points[whole[0].points.length - 1], { x: 0, y: 0 });
});

test('a loop shorter than the ramp keeps a plain seam', () => {
  assert.equal(scarfRuns(loopOf(square(4)), STYLE, H), null);
  assert.notEqual(scarfRuns(loopOf(square(5)), STYLE, H), null);
});

test('conditional: no scarf where the seam is in a sharp corner, a scarf where it is on a straight side', () => {
  const conditional = { ...STYLE, conditional: true };
  assert.equal(scarfRuns(loopOf(square(40)), conditional, H), null);
  assert.notEqual(scarfRuns(loopOf(square(40, true)), conditional, H), null);
  // a 64-gon turns 5.6° a corner: smooth
  const circle = Array.from({ length: 64 }, (_, i) => ({
    x: Math.round(10000 * Math.cos((i * Math.PI) / 32)),
    y: Math.round(10000 * Math.sin((i * Math.PI) / 32)),
  }));
  assert.notEqual(scarfRuns(loopOf(circle), conditional, H), null);
});

test('widths and over-air flags of the loop carry over to the ramp, the rest and the end', () => {
  const points = square(10, true); // 5 points, edges: 5, 10, 10, 10, 5 mm
  const widths = Float64Array.from([0.4, 0.6, 0.6, 0.4, 0.4]);
  const flags = Uint8Array.from([0, 1, 0, 0, 0]);
  const [ramp, rest, wipe] = scarfRuns(loopOf(points, { widths, flags }), { ...STYLE, length: 10, steps: 2 }, H)!;
  // ramp: (5,0) → (10,0) corner → (10,5) end, the first segment on edge 0, the second on edge 1 (over air)
  assert.deepEqual(
    ramp.points.map((p) => [p.x, p.y]),
    [
      [5000, 0],
      [10000, 0],
      [10000, 5000],
    ],
  );
  assert.deepEqual([...ramp.flags!], [0, 1]);
  assert.deepEqual([...wipe.flags!], [0, 1]);
  assert.ok(Math.abs(ramp.widths![1] - 0.6 * (0.1 + 0.9 * 0.5)) < 1e-9, 'the corner: its own width times the share');
  assert.ok(Math.abs(ramp.widths![2] - 0.6) < 1e-9, 'half-way along edge 1, whose ends are both 0.6 wide');
  assert.deepEqual(
    rest.points.map((p) => [p.x, p.y]),
    [
      [10000, 5000],
      [10000, 10000],
      [0, 10000],
      [0, 0],
      [5000, 0],
    ],
  );
  assert.deepEqual([...rest.widths!], [0.6, 0.6, 0.4, 0.4, 0.4]);
  assert.deepEqual([...rest.flags!], [1, 0, 0, 0]);
});

test('a loop with a Z of its own is left as it is', () => {
  const points = square(40);
  assert.equal(scarfRuns(loopOf(points, { z: new Float64Array(points.length) }), STYLE, H), null);
});
