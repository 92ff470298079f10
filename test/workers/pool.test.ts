/**
 * The pool driven through the browser host (`webWorkerPort`) by a fake Web Worker that runs the real
 * worker handler in this thread: results match the calling thread's, and a worker that cannot answer
 * (script not loaded, uncaught error, unreadable message, unclonable job) fails the run instead of
 * leaving it waiting.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { prepareModel } from '#strata/api/slicer.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { plainSetup } from '#strata/regions/objects.js';
import { planLayers, prepareMesh } from '#strata/slice/index.js';
import {
  computeRange,
  type HeldJob,
  type LayersJob,
  type LayerWork,
  type OutlinesJob,
  type OutlinesResult,
  type PathsResult,
  type RangeJob,
  type ResultOf,
} from '#strata/workers/layer-work.js';
import { makeHandler } from '#strata/workers/handler.js';
import { createPool, startWorkers } from '#strata/workers/pool.js';
import { webWorkerPort, type WebWorkerEvent, type WebWorkerLike } from '#strata/workers/ports.js';
import type { ToWorker } from '#strata/workers/protocol.js';

type Mode = 'ok' | 'no-script' | 'throws' | 'messageerror' | 'unclonable';

/**
 * A Web Worker stand-in: messages cross by structured clone, one task later, as in a browser. Tasks are
 * immediates, queued in order with the pool's own (`soon`): with timers, a job finishing after a timer's
 * due time let Node run the timers queued meanwhile in the same pass, so the stand-in could answer every
 * job before the calling thread's turn came, which no real worker (computing in parallel) does.
 * `msPerLayer` replaces the time a job reports (for the calling thread's decision to help).
 */
function fakeWorker(mode: Mode, msPerLayer?: number) {
  return class FakeWorker implements WebWorkerLike {
    #listeners = new Map<string, Array<(e: WebWorkerEvent) => void>>();
    #posted = 0;
    #layers = new Map<number, number>();
    #handle = makeHandler((m) => {
      if (m.type === 'result' && msPerLayer !== undefined) m.ms = msPerLayer * (this.#layers.get(m.id) ?? 0);
      this.#emit('message', { data: structuredClone(m) });
    });
    constructor(
      readonly url: URL,
      readonly options: { type: 'module' },
    ) {
      if (mode === 'no-script') setTimeout(() => this.#emit('error', { preventDefault() {} }), 0);
    }
    #emit(type: string, e: WebWorkerEvent) {
      setImmediate(() => {
        for (const fn of this.#listeners.get(type) ?? []) fn(e);
      });
    }
    addEventListener(type: string, fn: (e: WebWorkerEvent) => void) {
      this.#listeners.set(type, [...(this.#listeners.get(type) ?? []), fn]);
    }
    postMessage(m: unknown) {
      const msg = structuredClone(m) as ToWorker;
      if (mode === 'no-script') return;
      if (msg.type === 'range' && ++this.#posted > 1) {
        if (mode === 'throws')
          return this.#emit('error', { message: 'Uncaught RangeError: boom', filename: 'layer-worker.js', lineno: 3 });
        if (mode === 'messageerror') return this.#emit('messageerror', {});
        if (mode === 'unclonable') throw new DOMException('could not be cloned', 'DataCloneError');
      }
      if (msg.type === 'range') this.#layers.set(msg.id, msg.job.to - msg.job.from);
      setImmediate(() => this.#handle(msg));
    }
    terminate() {}
  };
}

const root = fileURLToPath(new URL('../../../', import.meta.url));
const cfg = resolveConfig({});
const model = prepareModel(readFileSync(root + 'examples/calibration-cube.stl'), cfg);
const layers = planLayers(20, cfg.firstLayerHeight, cfg.layerHeight);
const params = {
  density: 0.2,
  lineWidthUm: 400,
  nozzleDiameterUm: 400,
  angle: 45,
  centering: 'object' as const,
  origin: { x: 0, y: 0 },
  connect: false,
};
const jobs: LayersJob[] = [0, 1, 2, 3, 4, 5].map((k) => ({
  kind: 'layers',
  layers,
  from: Math.floor((k * layers.length) / 6),
  to: Math.floor(((k + 1) * layers.length) / 6),
  infillParams: [params],
  zOffset: 0,
  adhesion: true,
}));
const prepared = [prepareMesh(model.mesh)];
/** The calling thread's work (a fresh one per call: held regions are kept per thread). */
const here = (): LayerWork => ({ meshes: () => prepared, setup: plainSetup(cfg), held: new Map() });
const local = <J extends RangeJob>(j: J): ResultOf<J> => computeRange(here(), j);
const url = new URL('../../../dist/workers/layer-worker.js', import.meta.url);
const pool = (mode: Mode, workers = 1, msPerLayer?: number) =>
  createPool(
    workers,
    () => prepared,
    plainSetup(cfg),
    undefined,
    undefined,
    () => webWorkerPort(fakeWorker(mode, msPerLayer), url),
  );
const tick = () => new Promise((r) => setTimeout(r, 5));

test('through Web Workers, results come back in job order and equal the calling thread’s', {
  timeout: 20_000,
}, async () => {
  const p = await pool('ok', 2);
  let locally = 0;
  const results: PathsResult[] = [];
  await p.run(jobs, { local: (j) => (locally++, local(j)), onResult: (id, r) => (results[id] = r) });
  assert.ok(locally < jobs.length, 'the workers took some jobs');
  assert.deepEqual(results, jobs.map(local));
  // and without the calling thread
  const byWorkers: PathsResult[] = [];
  await p.run(jobs, { onResult: (id, r) => (byWorkers[id] = r) });
  await p.close();
  assert.deepEqual(byWorkers, results);
});

test('a worker whose script does not load fails the next run with a clear message, not a stall', {
  timeout: 20_000,
}, async () => {
  const p = await pool('no-script');
  await tick(); // the error arrives between runs (as between the two passes of lightning infill)
  await assert.rejects(
    p.run(jobs, { local }),
    /layer-worker\.js could not be started: the script did not load as a module worker/,
  );
  await p.close();
});

test('a worker started early that fails before the pool listens still fails the run', { timeout: 20_000 }, async () => {
  const started = startWorkers(1, () => webWorkerPort(fakeWorker('no-script'), url));
  await tick();
  const p = await createPool(1, () => prepared, plainSetup(cfg), undefined, started);
  await assert.rejects(p.run(jobs, { local }), /could not be started/);
  await p.close();
});

test('an uncaught error in a worker, an unreadable message or an unclonable job fails the run', {
  timeout: 20_000,
}, async () => {
  const cases: Array<[Mode, RegExp]> = [
    ['throws', /layer worker failed: Uncaught RangeError: boom \(layer-worker\.js:3\)/],
    ['messageerror', /could not be read/],
    ['unclonable', /could not be cloned/],
  ];
  for (const [mode, message] of cases) {
    const p = await pool(mode);
    await assert.rejects(p.run(jobs, { local }), message, mode);
    await p.close();
  }
});

test('the calling thread computes ranges only while the work left would keep the workers busy long enough', {
  timeout: 20_000,
}, async () => {
  // 6 jobs of ~3-4 layers; the worker holds 2 at once and its first job does not count
  const run = async (msPerLayer: number, helpAboveMs: number) => {
    const p = await pool('ok', 1, msPerLayer);
    const byCaller: number[] = [];
    const results: PathsResult[] = [];
    await p.run(jobs, {
      local: (j) => (byCaller.push(jobs.indexOf(j)), local(j)),
      onResult: (id, r) => (results[id] = r),
      helpAboveMs,
    });
    await p.close();
    assert.deepEqual(results, jobs.map(local));
    return byCaller;
  };
  assert.deepEqual(await run(1, 1000), [], 'little work left: the workers do it all');
  assert.deepEqual(await run(1, Infinity), []);
  const helped = await run(1000, 1000);
  // after the worker's second result (jobs 0-2 handed out), 3 jobs ≈ 10 layers ≈ 10 s are left
  assert.ok(helped.length > 0 && Math.min(...helped) >= 3, `the calling thread helped with ${helped}`);
  assert.ok((await run(0, 0)).length > 0, 'helpAboveMs 0: from the start');
});

test('regions held where they were made: the held jobs placed on those workers give the model paths the calling thread makes in one go', {
  timeout: 20_000,
}, async () => {
  const modelPaths = { infillParams: [params], zOffset: 0, adhesion: false };
  const regionJobs: OutlinesJob[] = jobs.map((j) => ({
    kind: 'outlines',
    layers,
    from: j.from,
    to: j.to,
    hold: true,
  }));
  const p = await pool('ok', 2);
  const where: number[] = [];
  const outlines: OutlinesResult[] = [];
  await p.run(regionJobs, { onResult: (id, r, w) => ((where[id] = w), (outlines[id] = r)) });
  assert.deepEqual(new Set(where), new Set([0, 1]), 'both workers made some ranges');
  const held: HeldJob[] = jobs.map((j) => ({ kind: 'held', layers, from: j.from, to: j.to, modelPaths }));
  const paths: PathsResult[] = [];
  await p.run(held, { placement: where, onResult: (id, r, w) => ((paths[id] = r), assert.equal(w, where[id])) });
  // what an outlines job that makes the model paths gives on the calling thread
  const inOneGo = jobs.map((j) =>
    local<OutlinesJob>({ kind: 'outlines', layers, from: j.from, to: j.to, hold: false, modelPaths }),
  );
  assert.deepEqual(
    paths.map((r) => r.paths),
    inOneGo.map((r) => r.paths),
  );
  assert.deepEqual(
    outlines.map((r) => r.outlines),
    inOneGo.map((r) => r.outlines),
  );
  assert.ok(inOneGo.every((r) => r.paths.length === r.outlines.length && r.paths.length > 0));
  assert.ok(
    outlines.every((r) => r.paths.length === 0 && r.outlines.every((l) => l.islands.every((i) => !('walls' in i)))),
    'held: only the outlines come back',
  );
  // held regions are used once: asked again, or on the other worker, there are none
  await assert.rejects(
    p.run(held.slice(0, 1), { placement: [where[0]] }),
    new RegExp(`no regions held for layers ${jobs[0].from}-${jobs[0].to}`),
  );
  await assert.rejects(p.run(held.slice(0, 1), { placement: [2] }), /names no worker/);
  await p.close();
});
