/**
 * The page's module worker entry: it listens at once and loads the slicer behind a dynamic import
 * (slice-work.ts), keeping what arrives meanwhile (the library's `listenFirst`).
 */
import { listenFirst } from 'strata-slicer/worker';
import type { ToWorker } from './protocol.js';

listenFirst(
  globalThis as unknown as { onmessage: ((e: { data: ToWorker }) => void) | null },
  async () => (await import('./slice-work.js')).onMessage,
);
