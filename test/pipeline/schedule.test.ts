/**
 * The pipeline's schedule, pinned: which steps run, in which order, where (the pool of workers, the workers
 * only, the calling thread), with how many workers and ranges, for the setups that change it. The schedule is
 * a pure function of a few flags, and run.ts carries out its steps as listed, so nothing is sliced here: the
 * flags come from a plate's settings (passes.ts decides which whole-model passes it needs) or are given.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Mesh } from '#strata/mesh/types.js';
import { plateSetup } from '#strata/pipeline/print-setup.js';
import { scheduleInput } from '#strata/pipeline/run.js';
import { schedule, type PassNeed, type Schedule, type ScheduleInput } from '#strata/pipeline/schedule.js';
import { sliceSetup } from '#strata/pipeline/slice-setup.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import type { SliceOptions } from '#strata/settings/schema.js';

/** A box, mm. */
function box(size: number, height: number): Mesh {
  const p: number[] = [];
  for (const [x, y, z] of [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [1, 1, 1],
    [0, 1, 1],
  ])
    p.push(100 + x * size, 100 + y * size, z * height);
  return {
    positions: new Float32Array(p),
    indices: new Uint32Array([
      0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
    ]),
  };
}

/** The schedule's flags for a 20 mm box (100 layers of 0.2 mm) with these settings. */
function flagsOf(
  settings: SliceOptions,
  opts: { threads: number; custom?: 'shader' | 'js density'; customInWorkers?: boolean },
): ScheduleInput {
  const cfg = resolveConfig(settings);
  const plate = plateSetup([{ name: 'box', mesh: box(20, 20) }], settings, cfg);
  const custom =
    opts.custom === 'shader'
      ? { name: 'stripes', shader: 'vec4 cellular(vec3 p) { return vec4(0.0); }' }
      : opts.custom === 'js density'
        ? { name: 'stripes', shader: 'vec4 cellular(vec3 p) { return vec4(0.0); }', density: () => 20 }
        : undefined;
  const s = { ...sliceSetup(plate), custom: !!custom };
  return scheduleInput(s, { threads: opts.threads, sink: () => {}, custom, customInWorkers: opts.customInWorkers });
}

/** The steps as text: stage (what a regions step keeps; the passes) @ where. */
function stepsOf(s: Schedule): string[] {
  return s.steps.map((st) => {
    const what = st.stage === 'regions' ? ` (${st.keep})` : st.stage === 'passes' ? ` (${st.passes.join(', ')})` : '';
    return `${st.stage}${what} @ ${st.on}`;
  });
}

const FINISH = 'finish @ calling thread';

test('no whole-model pass: each range makes its regions and paths at once on the pool, planned here as they arrive', () => {
  const flags = flagsOf({}, { threads: 4 });
  assert.equal(flags.layers, 100);
  assert.deepEqual(flags.passes, []);
  const s = schedule(flags);
  assert.deepEqual(stepsOf(s), ['layers @ pool', FINISH]);
  assert.equal(s.workers, 3, 'the calling thread counts as one of the threads');
  assert.equal(s.ranges.length, 16, 'four ranges a thread, for balance');
  assert.deepEqual(s.ranges[0], [0, 6]);
  assert.deepEqual(s.ranges.at(-1), [93, 100]);
  assert.ok(s.ranges.every(([a, b], k) => b > a && (k === 0 ? a === 0 : a === s.ranges[k - 1][1])));
});

test('threads = 1: no workers, one range, everything on the calling thread, whatever the passes', () => {
  assert.deepEqual(schedule(flagsOf({}, { threads: 1 })), {
    ranges: [[0, 100]],
    workers: 0,
    steps: [
      { stage: 'layers', on: 'calling thread' },
      { stage: 'finish', on: 'calling thread' },
    ],
  });
  const support = schedule(flagsOf({ supportEnabled: true }, { threads: 1 }));
  assert.equal(support.workers, 0);
  assert.deepEqual(stepsOf(support), [
    // no workers to hold the regions: the model paths are made with them, only the outlines kept
    'regions (outlines, model paths made) @ calling thread',
    'passes (support) @ calling thread',
    'shared @ calling thread',
    FINISH,
  ]);
  const lightning = schedule(flagsOf({ infillPattern: 'lightning' }, { threads: 1 }));
  assert.deepEqual(stepsOf(lightning), [
    'regions (regions) @ calling thread',
    'passes (lightning) @ calling thread',
    'paths @ calling thread',
    FINISH,
  ]);
});

test('support: the workers hold their regions and make the model paths while the calling thread runs the support pass', () => {
  const flags = flagsOf({ supportEnabled: true }, { threads: 4 });
  assert.deepEqual(flags.passes, [{ name: 'support', modelPathsWait: false, long: true }]);
  const s = schedule(flags);
  assert.equal(s.workers, 3);
  assert.deepEqual(stepsOf(s), [
    'regions (outlines, regions held) @ pool',
    'held @ workers',
    'passes (support) @ calling thread',
    'held @ calling thread',
    'shared @ calling thread',
    FINISH,
  ]);
});

test('support with no top Z gap: skin resting on support reads it, so every layer’s paths wait for the pass', () => {
  const flags = flagsOf({ supportEnabled: true, supportZGap: 0 }, { threads: 4 });
  assert.deepEqual(flags.passes, [{ name: 'support', modelPathsWait: true, long: true }]);
  assert.deepEqual(stepsOf(schedule(flags)), [
    'regions (regions) @ pool',
    'passes (support) @ calling thread',
    'paths @ pool',
    FINISH,
  ]);
});

test('lightning: its trees are read by the infill, so the paths are made after the pass, on the pool', () => {
  const flags = flagsOf({ infillPattern: 'lightning' }, { threads: 4 });
  assert.deepEqual(
    flags.passes.map((p) => p.name),
    ['lightning'],
  );
  assert.deepEqual(stepsOf(schedule(flags)), [
    'regions (regions) @ pool',
    'passes (lightning) @ calling thread',
    'paths @ pool',
    FINISH,
  ]);
  // no infill, no trees
  assert.deepEqual(flagsOf({ infillPattern: 'lightning', infillDensity: 0 }, { threads: 4 }).passes, []);
  // a custom infill fills every region instead: no lightning pass
  assert.deepEqual(flagsOf({ infillPattern: 'lightning' }, { threads: 4, custom: 'shader' }).passes, []);
});

test('raft: a short pass, the model paths are made with the regions; its layers are planned before the model', () => {
  const raft = schedule(flagsOf({ adhesionType: 'raft' }, { threads: 4 }));
  assert.deepEqual(stepsOf(raft), [
    'regions (outlines, model paths made) @ pool',
    'passes (raft) @ calling thread',
    'raft @ calling thread',
    'shared @ calling thread',
    FINISH,
  ]);
  const all = schedule(
    flagsOf({ adhesionType: 'raft', supportEnabled: true, infillPattern: 'lightning' }, { threads: 4 }),
  );
  assert.deepEqual(stepsOf(all), [
    'regions (regions) @ pool',
    'passes (support, lightning, raft) @ calling thread',
    'raft @ calling thread',
    'paths @ pool',
    FINISH,
  ]);
  const supportRaft = schedule(flagsOf({ adhesionType: 'raft', supportEnabled: true }, { threads: 4 }));
  assert.deepEqual(stepsOf(supportRaft), [
    'regions (outlines, regions held) @ pool',
    'held @ workers',
    'passes (support, raft) @ calling thread',
    'held @ calling thread',
    'raft @ calling thread',
    'shared @ calling thread',
    FINISH,
  ]);
});

test('custom infill in workers: as many workers as threads, the calling thread only plans', () => {
  const s = schedule(flagsOf({}, { threads: 4, custom: 'shader', customInWorkers: true }));
  assert.equal(s.workers, 4);
  assert.equal(s.ranges.length, 16);
  assert.deepEqual(stepsOf(s), ['layers @ workers', FINISH]);
  // one thread still gets a worker, and the ranges of two threads, so that progress shows
  const one = schedule(flagsOf({}, { threads: 1, custom: 'shader', customInWorkers: true }));
  assert.equal(one.workers, 1);
  assert.equal(one.ranges.length, 8);
  assert.deepEqual(stepsOf(one), ['layers @ workers', FINISH]);
  // with support the workers hold the regions; the calling thread made none, and only waits for theirs
  const support = schedule(flagsOf({ supportEnabled: true }, { threads: 2, custom: 'shader', customInWorkers: true }));
  assert.deepEqual(stepsOf(support), [
    'regions (outlines, regions held) @ workers',
    'held @ workers',
    'passes (support) @ calling thread',
    'held @ calling thread',
    'shared @ calling thread',
    FINISH,
  ]);
  // without customInWorkers (a synchronous slice) the custom infill is computed as any other
  assert.deepEqual(stepsOf(schedule(flagsOf({}, { threads: 4, custom: 'shader' }))), ['layers @ pool', FINISH]);
});

test('a custom density given as a JS function cannot travel to a worker: everything on the calling thread', () => {
  const s = schedule(flagsOf({ supportEnabled: true }, { threads: 4, custom: 'js density', customInWorkers: true }));
  assert.equal(s.workers, 0);
  assert.deepEqual(stepsOf(s), [
    'regions (outlines, model paths made) @ calling thread',
    'passes (support) @ calling thread',
    'shared @ calling thread',
    FINISH,
  ]);
});

test('few layers: no more workers than ranges, and none for a single range', () => {
  const none: PassNeed[] = [];
  const base = { custom: 'none', customInWorkers: false, passes: none } as const;
  assert.deepEqual(schedule({ ...base, layers: 2, threads: 8 }), {
    ranges: [
      [0, 1],
      [1, 2],
    ],
    workers: 1,
    steps: [
      { stage: 'layers', on: 'pool' },
      { stage: 'finish', on: 'calling thread' },
    ],
  });
  const single = schedule({ ...base, layers: 1, threads: 8 });
  assert.equal(single.workers, 0);
  assert.deepEqual(stepsOf(single), ['layers @ calling thread', FINISH]);
});
