/**
 * Cooperative pacing for work on the calling thread: between steps, `pause()` gives the event loop a turn
 * once a time slice has passed (so progress shows, messages from workers are handled, a page stays
 * responsive) and acts on an abort at once, rejecting with a CANCELLED error that carries `signal.reason`.
 *
 * Work written as `Steps` (a generator that yields `undefined` where it may pause and a promise where it
 * must wait, and gets the promise's value back) runs either way: `drive` paces it, awaiting what it waits
 * for; `driveSync` runs it to its end at once, for callers that cannot await (a synchronous `slice()`).
 */
import { cancelled, StrataError } from '../errors.js';
import { soon } from '../runtime.js';

/** One step of paced work: a pause point (undefined), or a promise to wait for, whose value is sent back in. */
export type Step = undefined | Promise<unknown>;
/** Paced work returning T. */
export type Steps<T> = Generator<Step, T, unknown>;

/** Wait for a promise inside `Steps`: `const v = yield* wait(p)`. */
export function* wait<T>(p: Promise<T>): Steps<T> {
  return (yield p) as T;
}

/** Plain steps (a generator yielding between pieces of work) as paced `Steps`, `onStep` after each. */
export function* paced<T>(steps: Generator<unknown, T>, onStep?: () => void): Steps<T> {
  for (;;) {
    const s = steps.next();
    if (s.done) return s.value;
    onStep?.();
    yield;
  }
}

/** Longest the calling thread computes without giving the event loop a turn, ms. */
export const TIME_SLICE_MS = 12;

export class Pacer {
  readonly #signal?: AbortSignal;
  #since = performance.now();

  constructor(signal?: AbortSignal) {
    this.#signal = signal;
  }

  /** Throw if the slice has been aborted. */
  check(): void {
    if (this.#signal?.aborted) throw cancelled(this.#signal);
  }

  /** Let the event loop run if this thread has computed for a time slice; then check for an abort. */
  async pause(): Promise<void> {
    this.check();
    if (performance.now() - this.#since < TIME_SLICE_MS) return;
    await new Promise<void>((resolve) => soon(resolve));
    this.#since = performance.now();
    this.check();
  }

  /** Run a generator of steps to its end, pausing between steps (`onStep` after each). */
  async run<T>(steps: Generator<unknown, T>, onStep?: () => void): Promise<T> {
    for (;;) {
      const s = steps.next();
      if (s.done) return s.value;
      onStep?.();
      await this.pause();
    }
  }

  /**
   * Run paced work to its end: pause at its pause points, wait for its promises and send their values back
   * in; a rejection, or an abort at a pause, is thrown into it where it stands (its `finally` blocks run).
   */
  async drive<T>(steps: Steps<T>): Promise<T> {
    let next = steps.next();
    for (;;) {
      if (next.done) return next.value;
      let value: unknown;
      try {
        if (next.value === undefined) await this.pause();
        else value = await next.value;
      } catch (e) {
        next = steps.throw(e);
        continue;
      }
      next = steps.next(value);
    }
  }

  /**
   * Run paced work to its end at once, on this thread (an abort already signalled is thrown into it at its
   * next pause point). Work that must wait for something is an error: it cannot be done synchronously.
   */
  driveSync<T>(steps: Steps<T>): T {
    let next = steps.next();
    for (;;) {
      if (next.done) return next.value;
      if (next.value !== undefined) {
        // the promise is not awaited here: keep its rejection from being reported as unhandled
        next.value.catch(() => {});
        next = steps.throw(
          new StrataError(
            'BAD_SETTING',
            'this slice needs to wait for something (a module to load, workers to start) and cannot run synchronously: use the async slice()',
          ),
        );
        continue;
      }
      try {
        this.check();
      } catch (e) {
        next = steps.throw(e);
        continue;
      }
      next = steps.next();
    }
  }
}
