/**
 * The print-host transport of the page: XMLHttpRequest (fetch cannot report upload progress). A request the
 * browser refuses to make, or whose answer it hides, ends with status 0 and no reason: the host is down, the
 * address is wrong, or the host does not allow this page's origin (CORS); the error says all three.
 */
import { cancelled } from '../../src/errors.js';
import { Unreachable, type HttpReply, type Transport } from '../../src/send/transport.js';

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

export const xhrTransport: Transport = {
  request: (method, url, headers, body, signal) => xhr(method, url, headers, body ?? null, undefined, signal),
  upload(url, headers, fields, file, onProgress, signal) {
    const form = new FormData();
    for (const [k, v] of Object.entries(fields)) form.append(k, v);
    form.append(file.field, new Blob([file.bytes as Uint8Array<ArrayBuffer>], { type: file.type }), file.name);
    return xhr('POST', url, headers, form, onProgress, signal);
  },
};
