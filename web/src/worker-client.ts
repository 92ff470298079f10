/** Requests to a slicing worker as promises; ending the worker (Cancel) rejects what is pending. */
import type { FromWorker, ToWorker } from './protocol.js';

type Reply = Exclude<FromWorker, { type: 'progress' } | { type: 'error' }>;
type Request = ToWorker extends infer T ? (T extends { id: number } ? Omit<T, 'id'> : never) : never;

export class Cancelled extends Error {
  constructor() {
    super('cancelled');
  }
}

export class WorkerClient {
  #worker: Worker | null = null;
  #nextId = 1;
  #pending = new Map<
    number,
    { resolve(r: Reply): void; reject(e: Error): void; progress?: (stage: string, fraction: number) => void }
  >();

  #spawn(): Worker {
    const w = new Worker(new URL('./slice-worker.js', import.meta.url), { type: 'module', name: 'strata' });
    w.onmessage = (e: MessageEvent<FromWorker>) => {
      const m = e.data;
      const p = this.#pending.get(m.id);
      if (!p) return;
      if (m.type === 'progress') {
        p.progress?.(m.stage, m.fraction);
        return;
      }
      this.#pending.delete(m.id);
      if (m.type === 'error') p.reject(new Error(m.message));
      else p.resolve(m);
    };
    w.onerror = (e) => {
      e.preventDefault();
      this.#fail(new Error(`the slicing worker failed: ${e.message || 'its script did not load'}`));
    };
    return w;
  }

  #fail(e: Error): void {
    const pending = [...this.#pending.values()];
    this.#pending.clear();
    this.#worker?.terminate();
    this.#worker = null;
    for (const p of pending) p.reject(e);
  }

  request<T extends Reply['type']>(
    msg: Request,
    transfer: Transferable[] = [],
    progress?: (stage: string, fraction: number) => void,
  ): Promise<Extract<Reply, { type: T }>> {
    this.#worker ??= this.#spawn();
    const id = this.#nextId++;
    return new Promise((resolve, reject) => {
      this.#pending.set(id, { resolve: resolve as (r: Reply) => void, reject, progress });
      this.#worker!.postMessage({ ...msg, id } as ToWorker, transfer);
    });
  }

  /** End the worker now (whatever it is doing); pending requests reject with Cancelled. */
  cancel(): void {
    this.#fail(new Cancelled());
  }

  get busy(): boolean {
    return this.#pending.size > 0;
  }
}
