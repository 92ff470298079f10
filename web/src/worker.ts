/**
 * The page's module worker entry: it listens at once and loads the slicer behind a dynamic import
 * (slice-work.ts), keeping what arrives meanwhile (see listen-first.ts).
 */
import { listenFirst } from '../../src/workers/listen-first.js';
import type { ToWorker } from './protocol.js';

listenFirst(
  globalThis as unknown as { onmessage: ((e: { data: ToWorker }) => void) | null },
  async () => (await import('./slice-work.js')).onMessage,
);
