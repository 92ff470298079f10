/**
 * Cooperative pacing for work on the calling thread: between steps, `pause()` gives the event loop a turn
 * once a time slice has passed (so progress shows, messages from workers are handled, a page stays
 * responsive) and acts on an abort at once, rejecting with a CANCELLED error that carries `signal.reason`.
 */
import { cancelled } from '../errors.js';
import { soon } from '../runtime.js';

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
}
