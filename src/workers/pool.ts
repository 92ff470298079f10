/**
 * A pool of layer workers (worker_threads in Node, Web Workers in browsers). The mesh is prepared for
 * slicing once, on the calling thread, and handed to every worker in shared memory where there is
 * some; jobs are layer ranges, results come back by range, so the output does not depend on how many
 * workers there are, nor on whether the calling thread computes some ranges itself.
 */
import { cancelled, StrataError } from '../errors.js';
import { isNode, soon } from '../runtime.js';
import type { PreparedMesh } from '../slice/index.js';
import type { RangeJob, ResultOf } from './layer-work.js';
import type { PrintSetup } from '../regions/objects.js';
import type { FromWorker } from './protocol.js';
import type { CustomInfillSpec } from '../infill/patterns/custom.js';
import { nodeWorkerPort, webWorkerPort, type Port, type WebWorkerCtor } from './ports.js';

/** Start one worker. */
export type Spawn = () => Port | Promise<Port>;

function defaultSpawn(): Port | Promise<Port> {
  const url = new URL('./layer-worker.js', import.meta.url);
  if (isNode) return nodeWorkerPort(url);
  const W = (globalThis as { Worker?: WebWorkerCtor }).Worker;
  if (!W) throw new Error('this environment has no Worker: slice with threads: 1');
  return webWorkerPort(W, url);
}

/** A copy of a typed array in a SharedArrayBuffer, or the array itself where there is none. */
function shared<T extends Float32Array | Float64Array | Int32Array | Uint32Array | Uint8Array>(a: T): T {
  if (typeof SharedArrayBuffer === 'undefined') return a;
  try {
    const C = a.constructor as new (b: SharedArrayBuffer) => T;
    const out = new C(new SharedArrayBuffer(a.byteLength));
    out.set(a as never);
    return out;
  } catch {
    return a;
  }
}

/** The prepared mesh with every array in shared memory (when available), so workers share one copy. */
export function sharePrepared(m: PreparedMesh): PreparedMesh {
  const e = m.edges;
  return {
    positions: shared(m.positions),
    indices: shared(m.indices),
    zq: shared(m.zq),
    triMode: shared(m.triMode),
    edges: { triEdge: shared(e.triEdge), edgeA: shared(e.edgeA), edgeB: shared(e.edgeB), edgeCount: e.edgeCount },
  };
}

export interface RunOptions<J extends RangeJob> {
  /**
   * Computes a job on the calling thread (at once, or stepping with pauses), which then takes jobs whenever it
   * is free (see `helpAboveMs`); without it only the workers do.
   */
  local?: (job: J) => ResultOf<J> | Promise<ResultOf<J>>;
  /**
   * The calling thread starts taking jobs only once the work not yet handed out would keep the workers
   * busy longer than this (ms, estimated from their last job, not counting each one's first): its first jobs are slow, and on a machine
   * without spare cores the compiler's work for them competes with the workers. 0 (default): at once.
   */
  helpAboveMs?: number;
  /**
   * Each result as it arrives (in any order), with where it was computed: the worker's index, or -1 on the
   * calling thread; an exception fails the run.
   */
  onResult?: (id: number, result: ResultOf<J>, where: number) => void;
  /**
   * Job i runs on worker `placement[i]` (a job that reads what an earlier job left on that worker); with it
   * there is no `local` work and no balancing between workers.
   */
  placement?: readonly number[];
  signal?: AbortSignal;
}

export interface LayerPool {
  /** Run jobs on the workers (and the calling thread, see `local`); resolves when all are done. */
  run<J extends RangeJob>(jobs: J[], options?: RunOptions<J>): Promise<void>;
  close(): Promise<void>;
}

/** Jobs each worker holds at once, so it never waits for the busy main thread to hand out the next. */
const IN_FLIGHT = 2;

/**
 * Start `size` workers now, so they load while the caller still prepares the model; hand them to
 * `createPool`, or to `releaseWorkers` if it turns out they are not needed.
 */
export function startWorkers(size: number, spawn: Spawn = defaultSpawn): Promise<Port[]> {
  const started = Promise.all(Array.from({ length: size }, () => spawn()));
  started.catch(() => {}); // failures surface where the ports are awaited
  return started;
}

export async function releaseWorkers(started: Promise<Port[]>): Promise<void> {
  const ports = await started.catch(() => []);
  await Promise.all(ports.map((p) => p.terminate()));
}

/**
 * Start `size` workers (or take them from `started`, ending any extra), then prepare the meshes (one per
 * object) on this thread while they load (`prepare`: best in shared memory, see `sharePrepared`) and send
 * them to the workers with the settings.
 */
export async function createPool(
  size: number,
  prepare: () => PreparedMesh[],
  setup: PrintSetup,
  custom?: CustomInfillSpec,
  started?: Promise<Port[]>,
  spawn: Spawn = defaultSpawn,
): Promise<LayerPool> {
  const ready = started ? await started : [];
  await Promise.all(ready.slice(size).map((p) => p.terminate()));
  const ports = [...ready.slice(0, size), ...(await startWorkers(Math.max(0, size - ready.length), spawn))];
  // The run in progress: one at a time, so the ports' listeners are installed once.
  let current: { onMessage(p: Port, m: FromWorker): void; fail(e: Error): void } | null = null;
  // A worker that failed between runs fails the next run at once: its jobs would never come back.
  let broken: Error | null = null;
  for (const p of ports) {
    p.listen(
      (m) => current?.onMessage(p, m),
      (e) => {
        broken ??= e;
        current?.fail(e);
      },
    );
  }
  try {
    const meshes = prepare();
    for (const p of ports) p.post({ type: 'init', meshes, setup, custom });
  } catch (e) {
    await Promise.all(ports.map((p) => p.terminate()));
    throw e;
  }
  return {
    run<J extends RangeJob>(jobs: J[], { local, onResult, signal, helpAboveMs = 0, placement }: RunOptions<J> = {}) {
      return new Promise<void>((resolve, reject) => {
        let next = 0;
        let done = 0;
        if (placement && (placement.length !== jobs.length || placement.some((w) => !(w >= 0 && w < ports.length)))) {
          return reject(new Error('a placed job names no worker of this pool'));
        }
        // with a placement, each worker's own jobs, in order
        const queues = placement
          ? ports.map((_, w) => jobs.map((_, id) => id).filter((id) => placement[id] === w))
          : null;
        if (placement) local = undefined;
        let finished = false;
        let helping = !!local && helpAboveMs <= 0;
        // layers not yet handed out, and the workers' time per layer on their last job
        let unassigned = jobs.reduce((n, j) => n + j.to - j.from, 0);
        let msPerLayer = 0;
        const answered = new Set<Port>();
        const take = () => {
          const id = next++;
          unassigned -= jobs[id].to - jobs[id].from;
          return id;
        };
        const finish = (e: Error | null) => {
          if (finished) return;
          finished = true;
          current = null;
          if (e) reject(e);
          else resolve();
        };
        const complete = (id: number, r: ResultOf<J>, where: number) => {
          try {
            onResult?.(id, r, where);
          } catch (e) {
            return finish(e as Error);
          }
          if (++done === jobs.length) finish(null);
        };
        const feed = (p: Port) => {
          if (finished) return;
          const queue = queues?.[ports.indexOf(p)];
          if (queue ? queue.length === 0 : next >= jobs.length) return;
          const id = queue ? queue.shift()! : take();
          try {
            p.post({ type: 'range', id, job: jobs[id] });
          } catch (e) {
            finish(e as Error);
          }
        };
        // the calling thread takes a job whenever it is free, between handling worker messages
        const work = () => {
          if (!local || finished || next >= jobs.length) return;
          const id = take();
          let r: ResultOf<J> | Promise<ResultOf<J>>;
          try {
            r = local(jobs[id]);
          } catch (e) {
            return finish(e as Error);
          }
          if (r instanceof Promise) {
            r.then(
              (v) => {
                if (finished) return;
                complete(id, v, -1);
                soon(work);
              },
              (e: unknown) => finish(e as Error),
            );
            return;
          }
          complete(id, r, -1);
          soon(work);
        };
        if (signal?.aborted) return finish(cancelled(signal));
        signal?.addEventListener('abort', () => finish(cancelled(signal)), { once: true });
        if (broken) return finish(broken);
        if (jobs.length === 0) return finish(null);
        current = {
          fail: (e) => finish(e),
          onMessage: (p, m) => {
            if (finished) return;
            if (m.type === 'error') {
              return finish(m.code === 'INTERNAL' ? new Error(m.message) : new StrataError(m.code as never, m.message));
            }
            // a worker's first job runs cold code: only later ones tell its pace
            const warm = answered.has(p);
            answered.add(p);
            if (warm) msPerLayer = m.ms / Math.max(1, jobs[m.id].to - jobs[m.id].from);
            // the answer to job m.id, of its kind
            complete(m.id, m.result as ResultOf<J>, ports.indexOf(p));
            feed(p);
            if (local && !helping && warm && (unassigned * msPerLayer) / ports.length > helpAboveMs) {
              helping = true;
              soon(work);
            }
          },
        };
        for (let k = 0; k < IN_FLIGHT; k++) for (const p of ports) feed(p);
        if (helping) soon(work);
      });
    },
    async close() {
      await Promise.all(ports.splice(0).map((p) => p.terminate()));
    },
  };
}
