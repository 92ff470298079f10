import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  busyThreshold,
  foreignShare,
  loadWarnings,
  overallForeignShare,
  startLoadWarning,
  type BlockLoad,
  type LoadMark,
  type LoadReport,
} from './load.js';

const mark = (atMs: number, busy: number, own: number): LoadMark => ({
  at: atMs,
  machine: { busy, total: busy + 1000 },
  self: { utime: own, stime: 0, cutime: 0, cstime: 0 },
});

test('the load average before the start: busy above 0.35 per core (0.7 on two cores)', () => {
  assert.equal(busyThreshold(2), 0.7);
  assert.equal(startLoadWarning(0.69, 2), null);
  assert.equal(startLoadWarning(0.7, 2), null);
  const w = startLoadWarning(0.71, 2);
  assert.match(w!, /1-minute load average 0\.71 before the start, above 0\.70 for 2 cores/);
  assert.match(w!, /ratios flatter Strata/);
  assert.equal(startLoadWarning(1.3, 4), null, 'four cores allow 1.4');
});

test('foreignShare: machine busy ticks minus our own, over time × cores', () => {
  // 10 s on 2 cores at 100 ticks/s = 2000 tick-slots; machine busy 1500, we (and our children) 1300 → 200 others = 10 %
  assert.equal(foreignShare(mark(0, 0, 0), mark(10_000, 1500, 1300), 2, 100), 0.1);
  assert.equal(foreignShare(mark(0, 0, 0), mark(10_000, 1000, 1300), 2, 100), 0, 'clamped at 0 (tick rounding)');
  assert.equal(foreignShare(mark(0, 0, 0), mark(10_000, 9000, 0), 2, 100), 1, 'clamped at 1');
  assert.equal(foreignShare({ at: 0, machine: null, self: null }, mark(10_000, 1, 1), 2, 100), null, 'no /proc');
  assert.equal(foreignShare(mark(0, 0, 0), mark(0, 10, 0), 2, 100), null, 'no time elapsed');
});

const block = (label: string, foreignShare: number | null, loadAverage = 1.5, seconds = 10): BlockLoad => ({
  label,
  seconds,
  loadAverage,
  foreignShare,
});
const report = (before: number, blocks: BlockLoad[]): LoadReport => ({ cpus: 2, busyAbove: 0.7, before, blocks });

test('loadWarnings: quiet machine, busy start, disturbed blocks, no /proc', () => {
  // our own slicers keep the load average near 2 on an idle 2-core machine: that alone is no warning
  assert.deepEqual(loadWarnings(report(0.2, [block('a', 0.02, 2.1), block('b', 0.1, 2.4)])), []);
  const busyStart = loadWarnings(report(2.5, [block('a', 0.01)]));
  assert.equal(busyStart.length, 1);
  assert.match(busyStart[0]!, /load average 2\.50 before the start/);
  const disturbed = loadWarnings(report(0.1, [block('cube', 0.05), block('spot', 0.4), block('bunny', 0.2)]));
  assert.equal(disturbed.length, 1);
  assert.match(
    disturbed[0]!,
    /other processes used more than 10 % of the CPU while measuring \(spot 40 %, bunny 20 %; worst spot\)/,
  );
  assert.doesNotMatch(disturbed[0]!, /cube/);
  // without /proc, the load average decides: above cores + threshold
  assert.deepEqual(loadWarnings(report(0.1, [block('a', null, 2.6)])), []);
  assert.match(loadWarnings(report(0.1, [block('a', null, 2.8)]))[0]!, /load average rose to 2\.80/);
});

test('overallForeignShare weights blocks by their time', () => {
  assert.ok(
    Math.abs(overallForeignShare([block('a', 0.1, 1, 30), block('b', 0.5, 1, 10), block('c', null)])! - 0.2) < 1e-12,
  );
  assert.equal(overallForeignShare([block('a', null)]), null);
});
