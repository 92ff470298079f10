/**
 * "Send to printer": the sliced G-code to OctoPrint or Moonraker over the network (the host's address and
 * kind remembered in localStorage; the API key too when asked), or to a USB printer running Marlin through
 * Web Serial (Chrome, Edge, Opera), with line numbers, checksums, `ok` flow control, pause and cancel.
 * The browser's rules apply to the network hosts: the host must allow this page's origin (CORS), and a page
 * served over https:// cannot call an http:// host.
 */
import { MarlinSender, StrataError, sendToPrinter, type HostKind } from 'strata-slicer';
import { h } from './dom.js';

/** The Web Serial API, as far as the page uses it (TypeScript's DOM types do not have it yet). */
interface SerialPortLike {
  open(options: { baudRate: number }): Promise<void>;
  close(): Promise<void>;
  readonly readable: ReadableStream<Uint8Array> | null;
  readonly writable: WritableStream<Uint8Array> | null;
}
interface SerialLike {
  requestPort(): Promise<SerialPortLike>;
}

type Kind = HostKind | 'usb';

interface Saved {
  kind: Kind;
  url: string;
  apiKey?: string;
  rememberKey: boolean;
  print: boolean;
  baud: number;
}

const STORAGE_KEY = 'strata.send';
const DEFAULTS: Saved = { kind: 'octoprint', url: '', rememberKey: false, print: true, baud: 115200 };
const BAUDS = [250000, 230400, 115200, 57600];
const HOST_NAMES: Record<Kind, string> = { octoprint: 'OctoPrint', moonraker: 'Moonraker', usb: 'USB' };

function load(): Saved {
  try {
    const s = JSON.parse(localStorage.getItem(STORAGE_KEY) ?? 'null') as Partial<Saved> | null;
    if (!s || typeof s !== 'object') return { ...DEFAULTS };
    return {
      kind: s.kind === 'moonraker' || s.kind === 'usb' ? s.kind : 'octoprint',
      url: typeof s.url === 'string' ? s.url : '',
      apiKey: typeof s.apiKey === 'string' ? s.apiKey : undefined,
      rememberKey: s.rememberKey === true,
      print: s.print !== false,
      baud: BAUDS.includes(s.baud as number) ? (s.baud as number) : 115200,
    };
  } catch {
    return { ...DEFAULTS };
  }
}

function save(s: Saved): void {
  try {
    const { apiKey, ...rest } = s;
    localStorage.setItem(STORAGE_KEY, JSON.stringify(s.rememberKey ? { ...rest, apiKey } : rest));
  } catch {
    // storage off or full: remembered until the page closes
  }
}

const message = (e: unknown) => (e instanceof Error ? e.message : String(e));

export interface SendPanelOptions {
  /** The button it goes after (Download G-code); it is enabled when that one is. */
  after: HTMLButtonElement;
  /** The G-code to send and its file name, or null when there is none. */
  current: () => { name: string; gcode: ArrayBuffer } | null;
}

export function setupSendPanel(o: SendPanelOptions): void {
  const saved = load();
  const open = h(
    'button',
    { id: 'send', class: 'button', type: 'button', disabled: o.after.disabled },
    'Send to printer',
  );
  o.after.insertAdjacentElement('afterend', open);
  // enabled and disabled with Download
  new MutationObserver(() => (open.disabled = o.after.disabled)).observe(o.after, {
    attributes: true,
    attributeFilter: ['disabled'],
  });

  const kinds = (['octoprint', 'moonraker', 'usb'] as const).map((k) =>
    h(
      'label',
      { class: 'send-kind' },
      h('input', { type: 'radio', name: 'send-kind', value: k, checked: saved.kind === k }),
      k === 'usb' ? ' USB (Marlin)' : ` ${HOST_NAMES[k]}`,
    ),
  );
  const url = h('input', {
    id: 'send-url',
    type: 'text',
    inputmode: 'url',
    placeholder: 'http://octopi.local',
    value: saved.url,
    autocomplete: 'url',
  });
  const key = h('input', { id: 'send-key', type: 'password', value: saved.apiKey ?? '', autocomplete: 'off' });
  const remember = h('input', { id: 'send-remember', type: 'checkbox', checked: saved.rememberKey });
  const print = h('input', { id: 'send-print', type: 'checkbox', checked: saved.print });
  const baud = h(
    'select',
    { id: 'send-baud' },
    ...BAUDS.map((b) => h('option', { value: b, selected: b === saved.baud }, String(b))),
  );
  const progress = h('progress', { id: 'send-progress', max: 1, value: 0, hidden: true });
  const status = h('p', { id: 'send-status', role: 'status' });
  const go = h('button', { class: 'button primary', type: 'button' }, 'Send');
  const pause = h('button', { class: 'button', type: 'button', hidden: true }, 'Pause');
  const stop = h('button', { class: 'button', type: 'button', hidden: true }, 'Cancel');
  const close = h('button', { class: 'button', type: 'button' }, 'Close');
  const hostFields = h(
    'div',
    { class: 'send-host' },
    h('label', { for: 'send-url' }, 'Address'),
    url,
    h('label', { for: 'send-key' }, 'API key'),
    key,
    h('label', { class: 'send-check' }, remember, ' remember the key on this computer'),
    h(
      'p',
      { class: 'send-note' },
      "The host must allow this page's origin (CORS): OctoPrint's Settings › API › Allow Cross Origin Resource Sharing, Moonraker's [authorization] cors_domains. A page on https:// cannot reach an http:// host.",
    ),
  );
  const usbFields = h(
    'div',
    { class: 'send-usb' },
    h('label', { for: 'send-baud' }, 'Baud rate'),
    baud,
    h(
      'p',
      { class: 'send-note' },
      'Through Web Serial (Chrome, Edge, Opera): pick the printer when asked. Keep this page open until the print ends.',
    ),
  );
  const dialog = h(
    'dialog',
    { id: 'send-dialog', 'aria-labelledby': 'send-title' },
    h('h2', { id: 'send-title' }, 'Send to printer'),
    h('fieldset', {}, h('legend', {}, 'Printer'), ...kinds),
    hostFields,
    usbFields,
    h('label', { class: 'send-check' }, print, ' start printing'),
    progress,
    status,
    h('div', { class: 'send-buttons' }, go, pause, stop, close),
  );
  document.body.append(dialog);

  const kind = (): Kind =>
    (dialog.querySelector<HTMLInputElement>('input[name="send-kind"]:checked')?.value as Kind | undefined) ??
    'octoprint';
  const showKind = () => {
    hostFields.hidden = kind() === 'usb';
    usbFields.hidden = kind() !== 'usb';
    print.disabled = kind() === 'usb';
  };
  for (const k of kinds) k.addEventListener('change', showKind);
  showKind();
  const state = (): Saved => ({
    kind: kind(),
    url: url.value.trim(),
    apiKey: key.value.trim() || undefined,
    rememberKey: remember.checked,
    print: print.checked,
    baud: Number(baud.value),
  });
  remember.addEventListener('change', () => save(state()));

  let busy = false;
  let abort: AbortController | null = null;
  let sender: MarlinSender | null = null;
  const running = (on: boolean, usb = false) => {
    busy = on;
    go.disabled = on;
    stop.hidden = !on;
    pause.hidden = !(on && usb);
    pause.textContent = 'Pause';
    progress.hidden = !on;
    if (on) progress.value = 0;
  };
  const say = (text: string, error = false) => {
    status.textContent = text;
    status.classList.toggle('error', error);
  };

  open.addEventListener('click', () => {
    if (!dialog.open) dialog.showModal();
  });
  close.addEventListener('click', () => dialog.close());
  stop.addEventListener('click', () => {
    abort?.abort();
    sender?.cancel();
  });
  pause.addEventListener('click', () => {
    if (!sender) return;
    if (sender.paused) {
      sender.resume();
      pause.textContent = 'Pause';
      say('Printing over USB…');
    } else {
      sender.pause();
      pause.textContent = 'Resume';
      say('Paused: the printer finishes the line it has and waits.');
    }
  });

  go.addEventListener('click', async () => {
    const job = o.current();
    if (busy || !job) return;
    const s = state();
    save(s);
    if (s.kind === 'usb') return void usb(job, s);
    running(true);
    abort = new AbortController();
    say(`Uploading ${job.name} to ${HOST_NAMES[s.kind]}…`);
    try {
      const r = await sendToPrinter(new Uint8Array(job.gcode), {
        name: job.name,
        to: s.kind,
        url: s.url,
        apiKey: s.apiKey,
        print: s.print,
        keyName: 'the API key field',
        signal: abort.signal,
        onProgress: ({ sent, total }) => (progress.value = total ? sent / total : 0),
      });
      say(
        `Sent ${r.name} to ${HOST_NAMES[s.kind]} at ${r.url}${r.started ? ': printing.' : r.notStarted ? `. Not printing: ${r.notStarted}.` : '.'}`,
        !!r.notStarted,
      );
    } catch (e) {
      say(e instanceof StrataError && e.code === 'CANCELLED' ? 'Upload cancelled.' : message(e), true);
    } finally {
      abort = null;
      running(false);
    }
  });

  async function usb(job: { name: string; gcode: ArrayBuffer }, s: Saved): Promise<void> {
    const serial = (navigator as Navigator & { serial?: SerialLike }).serial;
    if (!serial)
      return say(
        'This browser has no Web Serial: printing over USB needs Chrome, Edge or Opera (on http://localhost or https://).',
        true,
      );
    let port: SerialPortLike;
    try {
      port = await serial.requestPort();
      await port.open({ baudRate: s.baud });
    } catch (e) {
      return say(`No printer: ${message(e)}`, true);
    }
    const writer = port.writable!.getWriter();
    const reader = port.readable!.getReader();
    const encoder = new TextEncoder();
    const decoder = new TextDecoder();
    running(true, true);
    say('Printing over USB…');
    sender = new MarlinSender((data) => writer.write(encoder.encode(data)), {
      onProgress: ({ done, total }) => (progress.value = done / total),
    });
    const current = sender;
    const reading = (async () => {
      for (;;) {
        const { value, done } = await reader.read();
        if (done) break;
        current.receive(decoder.decode(value, { stream: true }));
      }
    })().catch(() => {});
    try {
      await current.print(new TextDecoder().decode(job.gcode));
      say(`${job.name}: every line sent; the printer finishes the last moves.`);
    } catch (e) {
      say(
        e instanceof StrataError && e.code === 'CANCELLED'
          ? 'Print cancelled: heaters, fan and motors turned off.'
          : message(e),
        true,
      );
    } finally {
      sender = null;
      running(false);
      await reader.cancel().catch(() => {});
      await reading;
      reader.releaseLock();
      writer.releaseLock();
      await port.close().catch(() => {});
    }
  }
}
