/**
 * Strata for browsers and bundlers (the package's `browser` export): the same API as the Node entry,
 * but the IceSL shader compiler loads only when a custom infill is used, so it stays out of the core
 * bundle. `await loadCustomInfill()` first if `setCustomInfill` should report shader errors at once.
 *
 * A bundle must emit `workers/layer-worker.js` as its own entry beside the code that creates the
 * worker pool: it is loaded as `new URL('./layer-worker.js', import.meta.url)`, a module worker.
 */
export * from './exports.js';
// sending G-code to OctoPrint or Moonraker (XMLHttpRequest; the Node entry's uses node:http)
export { sendToPrinter, HOST_KINDS } from './send/browser.js';
export type { HostKind, SendOptions, SendResult } from './send/browser.js';
