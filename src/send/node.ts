/**
 * `sendToPrinter` (the Node entry's): upload G-code to OctoPrint or Moonraker and start it on request.
 *
 *   import { Slicer, sendToPrinter } from 'strata-slicer';
 *   const { gcode } = await new Slicer({ printer: 'Ender3' }).slice(stl);
 *   await sendToPrinter(gcode, { to: 'octoprint', url: 'http://octopi.local', apiKey, print: true, name: 'part.gcode' });
 */
import { nodeTransport } from './node-transport.js';
import { sendGcode, type SendOptions, type SendResult } from './hosts.js';

export type { HostKind, SendOptions, SendResult } from './hosts.js';
export { HOST_KINDS } from './hosts.js';

/** Upload `gcode` (text or bytes) as `name` (default `strata.gcode`) to the host, printing it if `print`. */
export function sendToPrinter(gcode: string | Uint8Array, opts: SendOptions & { name?: string }): Promise<SendResult> {
  const bytes = typeof gcode === 'string' ? new TextEncoder().encode(gcode) : gcode;
  return sendGcode({ name: opts.name ?? 'strata.gcode', bytes }, opts, nodeTransport);
}
