/**
 * `sendToPrinter` (the browser entry's): upload G-code to OctoPrint or Moonraker from a page, over
 * XMLHttpRequest (fetch cannot report upload progress), and start it on request.
 *
 *   import { Slicer, sendToPrinter } from 'strata-slicer';
 *   const { gcode } = await new Slicer({ printer: 'Ender3' }).slice(stl);
 *   await sendToPrinter(gcode, { to: 'moonraker', url: 'http://voron.local', print: true, name: 'part.gcode' });
 *
 * The browser's rules apply: the host must allow the page's origin (CORS), and a page served over https://
 * cannot call an http:// host. A request the browser refuses to make, or whose answer it hides, ends with no
 * reason given; the error then names those causes and a host that is off or a wrong address.
 */
import { cancelled } from '../errors.js';
import { sendGcode, type SendOptions, type SendResult } from './hosts.js';
import { Unreachable, type HttpReply, type Transport } from './transport.js';

export type { HostKind, SendOptions, SendResult } from './hosts.js';
export { HOST_KINDS } from './hosts.js';

const BLOCKED =
  "no answer the page may read: the host is off or the address is wrong, or it does not allow this page's origin (CORS: OctoPrint needs Settings › API › Allow Cross Origin Resource Sharing; Moonraker an [authorization] cors_domains entry for this page), or it is http:// and this page https:// (mixed content)";

function xhr(
  method: string,
  url: string,
  headers: Record<string, string>,
  body: XMLHttpRequestBodyInit | null,
  onProgress?: (sent: number, total: number) => void,
  signal?: AbortSignal,
): Promise<HttpReply> {
  return new Promise((resolve, reject) => {
    if (signal?.aborted) return reject(cancelled(signal));
    const r = new XMLHttpRequest();
    r.open(method, url);
    for (const [k, v] of Object.entries(headers)) r.setRequestHeader(k, v);
    if (onProgress) r.upload.onprogress = (e) => onProgress(e.loaded, e.lengthComputable ? e.total : e.loaded);
    const onAbort = () => r.abort();
    signal?.addEventListener('abort', onAbort, { once: true });
    r.onload = () => {
      signal?.removeEventListener('abort', onAbort);
      resolve({ status: r.status, statusText: r.statusText, body: r.responseText });
    };
    r.onerror = () => {
      signal?.removeEventListener('abort', onAbort);
      reject(new Unreachable(BLOCKED));
    };
    r.ontimeout = () => reject(new Unreachable('no answer (timed out)'));
    r.onabort = () => reject(cancelled(signal));
    r.send(body);
  });
}

const xhrTransport: Transport = {
  request: (method, url, headers, body, signal) => xhr(method, url, headers, body ?? null, undefined, signal),
  upload(url, headers, fields, file, onProgress, signal) {
    const form = new FormData();
    for (const [k, v] of Object.entries(fields)) form.append(k, v);
    form.append(file.field, new Blob([file.bytes as Uint8Array<ArrayBuffer>], { type: file.type }), file.name);
    return xhr('POST', url, headers, form, onProgress, signal);
  },
};

/** Upload `gcode` (text or bytes) as `name` (default `strata.gcode`) to the host, printing it if `print`. */
export function sendToPrinter(gcode: string | Uint8Array, opts: SendOptions & { name?: string }): Promise<SendResult> {
  const bytes = typeof gcode === 'string' ? new TextEncoder().encode(gcode) : gcode;
  return sendGcode({ name: opts.name ?? 'strata.gcode', bytes }, opts, xhrTransport);
}
