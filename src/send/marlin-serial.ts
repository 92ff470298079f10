/**
 * Streaming G-code to a Marlin printer over a serial line (USB), as OctoPrint and Pronterface do: every line
 * numbered (`N12 G1 X10*93`, the checksum the XOR of its bytes), one line in flight at a time and the next
 * sent on the printer's `ok`, a line the printer got garbled sent again from where it asks (`Resend: N` or
 * `rs N`, then its `ok`), and `busy:` and temperature reports while it heats keeping the wait alive.
 * Pausable (no new line is sent until resumed), cancellable (the stream stops and heaters, fan and motors are
 * turned off). Independent of the transport: the page connects it to Web Serial, the tests to a simulated
 * Marlin (test-fake-marlin.ts).
 */
import { StrataError } from '../errors.js';

export interface MarlinOptions {
  /** Lines acknowledged so far, of all the print's lines. */
  onProgress?: (p: { done: number; total: number }) => void;
  /** Every line the printer sends (for a console). */
  onReceive?: (line: string) => void;
  /** Give up when the printer says nothing for this long, ms (default 60 s: heating to temperature reports every second). */
  idleTimeoutMs?: number;
}

/** The G-code a cancel sends: heaters, fan and motors off. */
export const CANCEL_GCODE = ['M104 S0', 'M140 S0', 'M107', 'M84'];

/** A line as it is sent: without its comment and surrounding blanks (empty when only a comment). */
export function cleanLine(line: string): string {
  const semi = line.indexOf(';');
  return (semi >= 0 ? line.slice(0, semi) : line).trim();
}

/** The commands of a G-code text, in order (comments and blank lines left out). */
export function gcodeCommands(gcode: string): string[] {
  const out: string[] = [];
  for (const raw of gcode.split(/\r?\n/)) {
    const c = cleanLine(raw);
    if (c) out.push(c);
  }
  return out;
}

/** `N{n} {command}*{checksum}`, the checksum the XOR of every byte before the `*`. */
export function numberedLine(n: number, command: string): string {
  const body = `N${n} ${command}`;
  let cs = 0;
  for (let i = 0; i < body.length; i++) cs ^= body.charCodeAt(i) & 0xff;
  return `${body}*${cs}`;
}

/** How long a printer that restarted as the port opened is given to boot, ms. */
const BOOT_MS = 1500;

/** Errors the printer recovers from by asking for the line again (a `Resend:` follows). */
const RECOVERABLE = /checksum|line ?number|expected line|format error|no line number|last line/i;

export class MarlinSender {
  readonly #write: (data: string) => Promise<void>;
  readonly #opts: MarlinOptions;
  #buffer = '';
  /** Commands of the current stream; line k + 1 is `N{k + 1}` (N0 is the M110 that resets the count). */
  #lines: string[] = [];
  /** Index in #lines of the line waiting for its `ok` (-1: the M110). */
  #inFlight = -2;
  #resendFrom: number | null = null;
  #paused = false;
  #cancelled = false;
  #total = 0;
  #timer: ReturnType<typeof setTimeout> | undefined;
  #settle: { resolve: () => void; reject: (e: unknown) => void } | null = null;

  constructor(write: (data: string) => Promise<void>, opts: MarlinOptions = {}) {
    this.#write = write;
    this.#opts = opts;
  }

  get paused(): boolean {
    return this.#paused;
  }

  /** Lines acknowledged so far. */
  get done(): number {
    return Math.max(0, Math.min(this.#inFlight, this.#total));
  }

  /** Feed what the printer sent (any chunking; lines end in \n). */
  receive(chunk: string): void {
    this.#buffer += chunk;
    let nl: number;
    while ((nl = this.#buffer.indexOf('\n')) >= 0) {
      const line = this.#buffer.slice(0, nl).replace(/\r$/, '').trim();
      this.#buffer = this.#buffer.slice(nl + 1);
      if (line) this.#line(line);
    }
  }

  /**
   * Send `gcode` line by line; resolves when the printer has acknowledged every line (or, cancelled, the
   * cancel G-code), rejects with a one-line StrataError if the printer reports a fault, restarts or stops
   * answering, or if writing fails.
   */
  print(gcode: string): Promise<void> {
    if (this.#settle) throw new StrataError('BAD_SETTING', 'a print is already being sent');
    this.#lines = gcodeCommands(gcode);
    this.#total = this.#lines.length;
    this.#cancelled = false;
    this.#paused = false;
    this.#resendFrom = null;
    this.#inFlight = -1;
    return new Promise<void>((resolve, reject) => {
      this.#settle = { resolve, reject };
      this.#send(-1);
    });
  }

  /** Stop sending after the line in flight; the printer finishes what it has and waits. */
  pause(): void {
    this.#paused = true;
  }

  resume(): void {
    if (!this.#paused) return;
    this.#paused = false;
    // the line in flight was acknowledged while paused: go on with the next
    if (this.#settle && this.#waiting === false) this.#next();
  }

  /** Stop the print: nothing more of it is sent; heaters, fan and motors are turned off. */
  cancel(): void {
    if (!this.#settle || this.#cancelled) return;
    this.#cancelled = true;
    this.#paused = false;
    // the cancel lines continue the numbering after the line in flight
    this.#lines = [...this.#lines.slice(0, Math.max(0, this.#inFlight + 1)), ...CANCEL_GCODE];
    this.#total = this.#lines.length;
    if (this.#waiting === false) this.#next();
  }

  /** Whether a line is out and its `ok` not in yet (false: idle between lines, when paused). */
  #waiting = false;

  #line(line: string): void {
    this.#opts.onReceive?.(line);
    if (!this.#settle) return;
    this.#arm();
    const resend = /^(?:Resend:|rs)\s*N?:?\s*(\d+)/i.exec(line);
    if (resend) {
      this.#resendFrom = Number(resend[1]);
      return;
    }
    if (/^ok\b/i.test(line)) return this.#ok();
    if (/^start\b/i.test(line)) {
      // many boards restart when the port opens: before the first line is through, start again after it boots
      if (this.#inFlight === -1) {
        this.#waiting = false;
        setTimeout(() => this.#settle && !this.#waiting && this.#send(-1), BOOT_MS);
        return;
      }
      return this.#fail('the printer restarted (it sent "start"): the print is stopped');
    }
    if (/^(?:Error|!!)/i.test(line) && !RECOVERABLE.test(line))
      return this.#fail(`the printer reported: ${line.replace(/^(Error:|!!)\s*/i, '')}`);
    // busy:, echo:, temperatures while heating, wait: the timer was reset above
  }

  #ok(): void {
    if (!this.#waiting) return;
    this.#waiting = false;
    if (this.#resendFrom !== null) {
      // the ok answers the error: send again from the line the printer asked for (N0 is the M110)
      const from = this.#resendFrom - 1;
      this.#resendFrom = null;
      if (from < -1 || from > this.#inFlight)
        return this.#fail(`the printer asked for line ${from + 1}, which was not sent yet`);
      this.#send(from);
      return;
    }
    if (this.#inFlight >= 0)
      this.#opts.onProgress?.({ done: Math.min(this.#inFlight + 1, this.#total), total: this.#total });
    this.#next();
  }

  #next(): void {
    const next = this.#inFlight + 1;
    if (next >= this.#lines.length) return this.#finish();
    if (this.#paused) return;
    this.#send(next);
  }

  #send(index: number): void {
    this.#inFlight = index;
    this.#waiting = true;
    const text = index < 0 ? numberedLine(0, 'M110 N0') : numberedLine(index + 1, this.#lines[index]!);
    this.#arm();
    this.#write(text + '\n').catch((e) =>
      this.#fail(`cannot write to the printer: ${e instanceof Error ? e.message : String(e)}`),
    );
  }

  #arm(): void {
    clearTimeout(this.#timer);
    if (!this.#settle) return;
    const ms = this.#opts.idleTimeoutMs ?? 60_000;
    this.#timer = setTimeout(
      () => this.#fail(`the printer stopped answering (nothing for ${Math.round(ms / 1000)} s)`),
      ms,
    );
  }

  #finish(): void {
    clearTimeout(this.#timer);
    const s = this.#settle;
    this.#settle = null;
    this.#waiting = false;
    if (this.#cancelled)
      s?.reject(new StrataError('CANCELLED', 'the print was cancelled (heaters, fan and motors turned off)'));
    else s?.resolve();
  }

  #fail(message: string): void {
    clearTimeout(this.#timer);
    const s = this.#settle;
    this.#settle = null;
    this.#waiting = false;
    s?.reject(new StrataError('WRITE_FAILED', message));
  }
}
