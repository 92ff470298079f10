/**
 * The page's module worker entry. It listens at once and loads the slicer behind a dynamic import: the
 * library waits for its clipping engine (WebAssembly) while it loads, and messages that came in before a
 * listener existed would be lost.
 */
import type { ToWorker } from './protocol.js';

const scope = globalThis as unknown as { onmessage: ((e: MessageEvent<ToWorker>) => void) | null };
const early: ToWorker[] = [];
let handle: ((msg: ToWorker) => void) | null = null;
scope.onmessage = (e) => (handle ? handle(e.data) : early.push(e.data));
void import('./slice-work.js').then((m) => {
  handle = m.onMessage;
  for (const msg of early.splice(0)) handle(msg);
});
