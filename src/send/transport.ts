/**
 * How a print host is reached: two HTTP operations, a small request and a multipart upload with progress.
 * Node uses node:http (node-transport.ts), a page XMLHttpRequest (browser.ts); the hosts'
 * logic (hosts.ts) is the same for both.
 */

export interface HttpReply {
  status: number;
  statusText: string;
  body: string;
}

/** The one file of a multipart upload. */
export interface FormFile {
  field: string;
  name: string;
  type: string;
  bytes: Uint8Array;
}

export interface Transport {
  request(
    method: 'GET' | 'POST',
    url: string,
    headers: Record<string, string>,
    body?: string,
    signal?: AbortSignal,
  ): Promise<HttpReply>;
  /** POST multipart/form-data: the fields, then the file; `onProgress` as bytes are sent. */
  upload(
    url: string,
    headers: Record<string, string>,
    fields: Record<string, string>,
    file: FormFile,
    onProgress?: (sent: number, total: number) => void,
    signal?: AbortSignal,
  ): Promise<HttpReply>;
}

/** The host could not be reached at all (no HTTP answer): `reason` in words, e.g. "connection refused". */
export class Unreachable extends Error {
  constructor(readonly reason: string) {
    super(reason);
    this.name = 'Unreachable';
  }
}

/** A multipart/form-data body as three pieces (fields and file head, the file, the tail), for streaming. */
export function multipartBody(
  fields: Record<string, string>,
  file: FormFile,
): { contentType: string; head: Uint8Array; tail: Uint8Array; total: number } {
  // random enough never to occur in the text around it; G-code has no such line
  let boundary = '----strata';
  for (let i = 0; i < 24; i++) boundary += 'abcdefghijklmnopqrstuvwxyz0123456789'[Math.floor(Math.random() * 36)];
  const quote = (s: string) => s.replace(/[\r\n"]/g, (c) => (c === '"' ? '%22' : ' '));
  let head = '';
  for (const [name, value] of Object.entries(fields))
    head += `--${boundary}\r\nContent-Disposition: form-data; name="${quote(name)}"\r\n\r\n${value}\r\n`;
  head += `--${boundary}\r\nContent-Disposition: form-data; name="${quote(file.field)}"; filename="${quote(file.name)}"\r\nContent-Type: ${file.type}\r\n\r\n`;
  const enc = new TextEncoder();
  const h = enc.encode(head);
  const t = enc.encode(`\r\n--${boundary}--\r\n`);
  return {
    contentType: `multipart/form-data; boundary=${boundary}`,
    head: h,
    tail: t,
    total: h.length + file.bytes.length + t.length,
  };
}
