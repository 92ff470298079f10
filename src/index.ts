/**
 * Strata: a fast FFF slicer for Node and the browser.
 *
 *   import { Slicer } from 'strata-slicer';
 *   const { gcode, stats } = await new Slicer({ layerHeight: 0.2 }).slice(stlBytes);
 */
export * from './exports.js';
// sending G-code to OctoPrint or Moonraker (node:http; the page has its own transport)
export { sendToPrinter, HOST_KINDS } from './send/node.js';
export type { HostKind, SendOptions, SendResult } from './send/node.js';

// In Node the shader compiler loads with the library, so `setCustomInfill` reports a broken shader at once.
import * as customInfill from './infill/patterns/custom.js';
import { provideCustomInfill } from './infill/registry.js';
provideCustomInfill(customInfill);
