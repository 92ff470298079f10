/**
 * A pool of layer workers (worker_threads in Node, Web Workers in browsers). The mesh is copied once
 * into shared memory and handed to every worker; jobs are layer ranges, results come back by range,
 * so the output does not depend on how many workers there are.
 */
import { StrataError } from '../errors.js';
import { isNode, nodeBuiltin } from '../runtime.js';
import type { Mesh } from '../mesh/types.js';
import type { RangeJob, RangeResult } from '../pipeline/layer-work.js';
import type { Config } from '../settings/resolve.js';
import type { FromWorker, ToWorker } from './protocol.js';
import type { CustomInfillSpec } from '../pipeline/custom-infill.js';

interface Port {
  post(msg: ToWorker): void;
  onMessage(fn: (msg: FromWorker) => void): void;
  onError(fn: (err: Error) => void): void;
  terminate(): Promise<unknown> | void;
}


async function spawn(): Promise<Port> {
  const url = new URL('./layer-worker.js', import.meta.url);
  if (isNode) {
    const { Worker } = await nodeBuiltin<typeof import('node:worker_threads')>('worker_threads');
    const w = new Worker(url);
    w.unref();
    return {
      post: (m) => w.postMessage(m),
      onMessage: (fn) => w.on('message', fn),
      onError: (fn) => w.on('error', fn),
      terminate: () => w.terminate(),
    };
  }
  const W = (globalThis as unknown as { Worker: new (u: URL, o: { type: 'module' }) => { postMessage(m: unknown): void; onmessage: ((e: { data: FromWorker }) => void) | null; onerror: ((e: { message?: string }) => void) | null; terminate(): void } }).Worker;
  const w = new W(url, { type: 'module' });
  return {
    post: (m) => w.postMessage(m),
    onMessage: (fn) => (w.onmessage = (e) => fn(e.data)),
    onError: (fn) => (w.onerror = (e) => fn(new Error(e.message ?? 'worker error'))),
    terminate: () => w.terminate(),
  };
}

/** Copy typed arrays into SharedArrayBuffers (when available) so workers share one mesh. */
function shareMesh(mesh: Mesh): Mesh {
  if (typeof SharedArrayBuffer === 'undefined') return mesh;
  try {
    const p = new Float32Array(new SharedArrayBuffer(mesh.positions.byteLength));
    p.set(mesh.positions);
    const i = new Uint32Array(new SharedArrayBuffer(mesh.indices.byteLength));
    i.set(mesh.indices);
    return { positions: p, indices: i };
  } catch {
    return mesh;
  }
}

export interface LayerPool {
  /**
   * Run jobs on the workers and, through `local`, on the calling thread too. Results are returned in
   * job order, so they do not depend on who computed what.
   */
  run(jobs: RangeJob[], local: (job: RangeJob) => RangeResult, onDone?: (job: RangeJob) => void, signal?: AbortSignal): Promise<RangeResult[]>;
  close(): Promise<void>;
}

/** Jobs each worker holds at once, so it never waits for the busy main thread to hand out the next. */
const IN_FLIGHT = 2;

export async function createPool(size: number, mesh: Mesh, cfg: Config, custom?: CustomInfillSpec): Promise<LayerPool> {
  const shared = shareMesh(mesh);
  const ports = await Promise.all(Array.from({ length: size }, () => spawn()));
  // The run in progress: one at a time, so the ports' listeners are installed once.
  let current: { onMessage(p: Port, m: FromWorker): void; fail(e: Error): void } | null = null;
  for (const p of ports) {
    p.post({ type: 'init', mesh: shared, cfg, custom });
    p.onMessage((m) => current?.onMessage(p, m));
    p.onError((e) => current?.fail(e));
  }
  return {
    run(jobs, local, onDone, signal) {
      return new Promise<RangeResult[]>((resolve, reject) => {
        const results: RangeResult[] = new Array(jobs.length);
        let next = 0;
        let done = 0;
        let finished = false;
        const finish = (e: Error | null) => {
          if (finished) return;
          finished = true;
          current = null;
          if (e) reject(e);
          else resolve(results);
        };
        const complete = (id: number, r: RangeResult) => {
          results[id] = r;
          onDone?.(jobs[id]);
          if (++done === jobs.length) finish(null);
        };
        const feed = (p: Port) => {
          if (finished || next >= jobs.length) return;
          const id = next++;
          p.post({ type: 'range', id, job: jobs[id] });
        };
        // the calling thread takes a job whenever it is free, between handling worker messages
        const work = () => {
          if (finished || next >= jobs.length) return;
          const id = next++;
          try {
            complete(id, local(jobs[id]));
          } catch (e) {
            return finish(e as Error);
          }
          setTimeout(work, 0);
        };
        if (signal?.aborted) return finish(new StrataError('CANCELLED', 'slicing was cancelled'));
        signal?.addEventListener('abort', () => finish(new StrataError('CANCELLED', 'slicing was cancelled')), { once: true });
        if (jobs.length === 0) return finish(null);
        current = {
          fail: (e) => finish(e),
          onMessage: (p, m) => {
            if (finished) return;
            if (m.type === 'error') {
              return finish(m.code === 'INTERNAL' ? new Error(m.message) : new StrataError(m.code as never, m.message));
            }
            complete(m.id, m.result);
            feed(p);
          },
        };
        for (let k = 0; k < IN_FLIGHT; k++) for (const p of ports) feed(p);
        setTimeout(work, 0);
      });
    },
    async close() {
      await Promise.all(ports.map((p) => p.terminate()));
    },
  };
}
