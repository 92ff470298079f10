import { test } from 'node:test';
import assert from 'node:assert/strict';
import { interleaveOrder, runInterleaved, type Job } from './interleave.js';
import type { Measurement } from './measure.js';
import { notRun } from './report.js';

test('interleaveOrder: warm-up rounds first, then A B C A B C …', () => {
  const order = interleaveOrder(['a', 'b', 'c'], 2, 1);
  assert.deepEqual(
    order.map((r) => `${r.round}${r.key}${r.counted ? '' : '*'}`),
    ['1a*', '1b*', '1c*', '2a', '2b', '2c', '3a', '3b', '3c'],
  );
  assert.deepEqual(
    interleaveOrder(['x'], 3, 0).map((r) => r.counted),
    [true, true, true],
  );
  assert.deepEqual(interleaveOrder([], 5, 1), []);
});

const job = (label: string): Job => ({ label, command: 'slicer', args: [label] });
const measurement = (wallSeconds: number, exitCode = 0): Measurement => ({
  exitCode,
  signal: null,
  timedOut: false,
  spawnError: null,
  wallSeconds,
  cpuSeconds: wallSeconds * 2,
  peakMiB: 50,
  stderrTail: exitCode === 0 ? '' : 'boom\n',
});

test('runInterleaved: runs in interleaved order, leaves the warm-up out of the figures, keeps round order', async () => {
  const calls: string[] = [];
  let t = 0;
  const result = await runInterleaved(
    { strata: job('S'), cura: job('C'), prusa: notRun('missing') },
    {
      repeat: 3,
      warmup: 1,
      measure: async (j) => {
        calls.push(j.label);
        t += 1;
        return measurement(j.label === 'S' ? t : 100 + t);
      },
    },
  );
  assert.deepEqual(calls, ['S', 'C', 'S', 'C', 'S', 'C', 'S', 'C']);
  assert.deepEqual(
    result.strata.runs.map((r) => r.wallSeconds),
    [3, 5, 7],
    'warm-up (t = 1) not counted',
  );
  assert.deepEqual(
    result.cura.runs.map((r) => r.wallSeconds),
    [104, 106, 108],
  );
  assert.equal(result.strata.wallSeconds, 5);
  assert.equal(result.strata.cpuSeconds, 10);
  assert.equal(result.prusa.status, 'missing', 'a non-job is passed through');
});

test('runInterleaved: a failing job is dropped from later rounds and reported failed; the others go on', async () => {
  const calls: string[] = [];
  const result = await runInterleaved(
    { a: job('A'), b: job('B') },
    {
      repeat: 3,
      warmup: 1,
      measure: async (j) => {
        calls.push(j.label);
        return measurement(1, j.label === 'B' && calls.length > 2 ? 1 : 0);
      },
    },
  );
  assert.deepEqual(calls, ['A', 'B', 'A', 'B', 'A', 'A']);
  assert.equal(result.a.status, 'ok');
  assert.equal(result.a.runs.length, 3);
  assert.equal(result.b.status, 'failed');
  assert.match(result.b.message!, /exit code 1: boom/);
});

test('runInterleaved: a failure in the warm-up counts as a failure', async () => {
  const result = await runInterleaved(
    { a: job('A') },
    { repeat: 2, warmup: 1, measure: async () => measurement(1, 3) },
  );
  assert.equal(result.a.status, 'failed');
});

test('runInterleaved: an abort stops before the next run', async () => {
  const abort = new AbortController();
  const calls: string[] = [];
  const result = await runInterleaved(
    { a: job('A'), b: job('B') },
    {
      repeat: 5,
      warmup: 0,
      signal: abort.signal,
      measure: async (j) => {
        calls.push(j.label);
        if (calls.length === 3) abort.abort();
        return measurement(1);
      },
    },
  );
  assert.deepEqual(calls, ['A', 'B', 'A']);
  assert.equal(result.a.runs.length, 2);
  assert.equal(result.b.runs.length, 1);
});
