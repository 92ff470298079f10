/**
 * Sending G-code to a print host: OctoPrint (`POST /api/files/local`) or Moonraker, the API server of
 * Klipper printers that Mainsail and Fluidd use (`POST /server/files/upload`). One upload, with progress, that
 * starts the print when asked; every failure is one line that says what to do: a wrong or missing API key
 * (401/403; checked first with a small request), a host that cannot be reached, a full disk or an upload
 * limit on the host (507, 413, a 500 that says so), a file that is not G-code (checked before sending).
 *
 * Facts from the hosts' REST API documentation and their source (for status codes and reply fields).
 */
import { StrataError } from '../errors.js';
import { checkGcode, checkGcodeName } from './gcode-check.js';
import { Unreachable, type HttpReply, type Transport } from './transport.js';

export const HOST_KINDS = ['octoprint', 'moonraker'] as const;
export type HostKind = (typeof HOST_KINDS)[number];

const HOST_NAMES: Record<HostKind, string> = { octoprint: 'OctoPrint', moonraker: 'Moonraker' };

export interface SendOptions {
  /** The host's software. */
  to: HostKind;
  /** Its address, e.g. `http://octopi.local` or `http://192.168.1.20:7125` (http:// is assumed). */
  url: string;
  /** OctoPrint: a user's or application's API key (required); Moonraker: needed unless this machine is a trusted client. */
  apiKey?: string;
  /** Start printing the file once it is uploaded. */
  print?: boolean;
  /** Bytes sent so far of `total` (the upload's whole body). */
  onProgress?: (p: { sent: number; total: number }) => void;
  signal?: AbortSignal;
  /** How the API key is given where the caller takes it (for messages): `--api-key`, `apiKey`… */
  keyName?: string;
}

export interface SendResult {
  host: HostKind;
  /** The host's address as used. */
  url: string;
  /** The file's name (path) on the host. */
  name: string;
  bytes: number;
  /** The host started printing it. */
  started: boolean;
  /** Moonraker put it in its job queue instead (the printer was busy or not ready). */
  queued: boolean;
  /** Why the print did not start, when it was asked for and did not. */
  notStarted?: string;
}

/** The host's address as a URL ending in `/` (so that API paths resolve under a proxy's prefix too). */
export function hostUrl(text: string): URL {
  const t = text.trim();
  let url: URL;
  try {
    url = new URL(/^[a-z][a-z0-9+.-]*:\/\//i.test(t) ? t : `http://${t}`);
  } catch {
    throw new StrataError(
      'BAD_SETTING',
      `"${text}" is not a host address (e.g. http://octopi.local or http://192.168.1.20:7125)`,
    );
  }
  if (url.protocol !== 'http:' && url.protocol !== 'https:')
    throw new StrataError('BAD_SETTING', `"${text}": a print host is reached over http:// or https://`);
  if (!url.pathname.endsWith('/')) url.pathname += '/';
  url.search = '';
  url.hash = '';
  return url;
}

export function checkHostKind(to: unknown): HostKind {
  if (!(HOST_KINDS as readonly unknown[]).includes(to))
    throw new StrataError('BAD_SETTING', `the host must be one of ${HOST_KINDS.join(', ')}, got ${JSON.stringify(to)}`);
  return to as HostKind;
}

/** The host's own words from an error reply: OctoPrint's `{ error }`, Moonraker's `{ error: { message } }`, or the text. */
export function hostMessage(body: string): string {
  let text = body;
  try {
    const j = JSON.parse(body) as { error?: unknown; description?: unknown; message?: unknown };
    const e = j.error;
    text =
      typeof e === 'string'
        ? e
        : e && typeof e === 'object' && typeof (e as { message?: unknown }).message === 'string'
          ? (e as { message: string }).message
          : typeof j.description === 'string'
            ? j.description
            : typeof j.message === 'string'
              ? j.message
              : '';
  } catch {
    text = body.replace(/<[^>]*>/g, ' ');
  }
  const line = text.replace(/\s+/g, ' ').trim();
  return line.length > 200 ? line.slice(0, 197) + '...' : line;
}

const DISK_FULL = /no space|ENOSPC|Errno 28|disk (is )?full|insufficient storage/i;

/** The one line for a host's refusal. */
export function refusal(to: HostKind, url: string, reply: HttpReply, keyGiven: boolean, keyName: string): string {
  const host = `${HOST_NAMES[to]} at ${url}`;
  const status = `${reply.status}${reply.statusText ? ` ${reply.statusText}` : ''}`;
  const msg = hostMessage(reply.body);
  const said = msg ? `: ${msg}` : '';
  switch (true) {
    // OctoPrint takes a POST whose key it does not know for a browser's, without its CSRF token
    case reply.status === 401 ||
      reply.status === 403 ||
      (to === 'octoprint' && reply.status === 400 && /CSRF/i.test(msg)):
      if (!keyGiven)
        return `${host} needs an API key (${status}): give one with ${keyName}${to === 'octoprint' ? " (OctoPrint: Settings › Application Keys, or the user's API key)" : ''}`;
      return `${host} refused the API key (${status}): check ${keyName}${to === 'octoprint' ? " (OctoPrint: Settings › Application Keys, or the user's API key)" : " (Moonraker's is at /access/api_key from a trusted client)"}`;
    case reply.status === 507 || DISK_FULL.test(msg):
      return `${host} has no room for the file (disk full, ${status}${said}): delete old files on it`;
    case reply.status === 413:
      return `${host} refused the file as too large (${status}): raise its upload limit (${to === 'octoprint' ? 'OctoPrint: server.uploads.maxSize' : 'Moonraker: [server] max_upload_size'}, or a proxy's, e.g. nginx client_max_body_size)`;
    case reply.status === 415:
      return `${host} does not take this type of file (${status}${said})`;
    case reply.status === 404:
      return `${url} has no ${HOST_NAMES[to]} upload API (${status}): is it the ${HOST_NAMES[to]} address${to === 'moonraker' ? ' (port 7125, or the Mainsail/Fluidd address)' : ''}?`;
    case to === 'moonraker' && reply.status === 500 && /unable to save/i.test(msg):
      return `${host} could not save the file (${status}${said}): is its disk full?`;
    default:
      return `${host} refused the upload (${status}${said})`;
  }
}

/** A request that needs the key and changes nothing: OctoPrint's version, Moonraker's server info. */
const PROBE: Record<HostKind, string> = { octoprint: 'api/version', moonraker: 'server/info' };

/** The upload's request for each host. */
function uploadRequest(to: HostKind, print: boolean): { path: string; fields: Record<string, string> } {
  return to === 'octoprint'
    ? { path: 'api/files/local', fields: { select: print ? 'true' : 'false', print: print ? 'true' : 'false' } }
    : { path: 'server/files/upload', fields: { root: 'gcodes', print: print ? 'true' : 'false' } };
}

/** What the host's reply to a successful upload says: the file's name there, and whether it prints. */
function uploaded(
  to: HostKind,
  body: string,
  fallbackName: string,
  print: boolean,
): Pick<SendResult, 'name' | 'started' | 'queued' | 'notStarted'> {
  let j: Record<string, unknown> = {};
  try {
    j = JSON.parse(body) as Record<string, unknown>;
  } catch {
    // a reply without JSON still means the file arrived
  }
  if (to === 'octoprint') {
    const local = (j.files as { local?: { path?: string; name?: string } } | undefined)?.local;
    const started = j.effectivePrint === true;
    return {
      name: local?.path ?? local?.name ?? fallbackName,
      started,
      queued: false,
      ...(print && !started
        ? {
            notStarted:
              'OctoPrint did not start the print: the printer is not connected, or is busy (connect it, then start the file in OctoPrint)',
          }
        : {}),
    };
  }
  // Moonraker ≥ 0.8: { item: { path, root }, print_started, print_queued }; older: { result: … }
  const r = (j.result && typeof j.result === 'object' ? j.result : j) as {
    item?: { path?: string };
    print_started?: boolean;
    print_queued?: boolean;
  };
  const started = r.print_started === true;
  const queued = r.print_queued === true;
  return {
    name: r.item?.path ?? fallbackName,
    started,
    queued,
    ...(print && !started
      ? {
          notStarted: queued
            ? 'Moonraker put the file in its job queue (Klipper was busy or not ready): it prints when the queue runs'
            : 'Moonraker did not start the print: Klipper is not ready (is the printer on and connected?)',
        }
      : {}),
  };
}

/**
 * Upload G-code to a print host and, when asked, start printing it. Throws a one-line StrataError for a file
 * that is not G-code (before sending), an address that is not one, a host that cannot be reached or refuses.
 */
export async function sendGcode(
  file: { name: string; bytes: Uint8Array },
  opts: SendOptions,
  transport: Transport,
): Promise<SendResult> {
  const to = checkHostKind(opts.to);
  const base = hostUrl(opts.url);
  const name = checkGcodeName(file.name);
  checkGcode(file.bytes, name);
  const keyName = opts.keyName ?? 'apiKey';
  const headers: Record<string, string> = { Accept: 'application/json' };
  if (opts.apiKey) headers['X-Api-Key'] = opts.apiKey.trim();
  const print = opts.print === true;
  const { path, fields } = uploadRequest(to, print);
  const where = base.href.replace(/\/$/, '');
  const unreachable = (e: unknown) =>
    e instanceof Unreachable
      ? new StrataError('WRITE_FAILED', `cannot reach ${HOST_NAMES[to]} at ${where}: ${e.reason}`)
      : e;
  // First a small request with the key: a wrong key, a wrong address or a host that cannot be reached is
  // told before the file is sent (a host that refuses an upload may close the connection before its answer
  // arrives).
  let probe: HttpReply;
  try {
    probe = await transport.request('GET', new URL(PROBE[to], base).href, headers, undefined, opts.signal);
  } catch (e) {
    throw unreachable(e);
  }
  if (probe.status === 401 || probe.status === 403 || probe.status === 404)
    throw new StrataError('WRITE_FAILED', refusal(to, where, probe, !!opts.apiKey, keyName));
  let reply: HttpReply;
  try {
    reply = await transport.upload(
      new URL(path, base).href,
      headers,
      fields,
      { field: 'file', name, type: 'application/octet-stream', bytes: file.bytes },
      opts.onProgress && ((sent, total) => opts.onProgress!({ sent, total })),
      opts.signal,
    );
  } catch (e) {
    throw unreachable(e);
  }
  if (reply.status < 200 || reply.status >= 300)
    throw new StrataError('WRITE_FAILED', refusal(to, where, reply, !!opts.apiKey, keyName));
  return { host: to, url: where, bytes: file.bytes.length, ...uploaded(to, reply.body, name, print) };
}
