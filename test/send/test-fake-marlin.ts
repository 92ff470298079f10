/**
 * A simulated Marlin for the serial protocol's tests: it checks each line's number and checksum as Marlin's
 * GCodeQueue does, asks for a garbled or missing line again (`Error:checksum mismatch, Last Line: n`,
 * `Resend: n+1`, `ok`), answers `ok` once a command is done, reports temperatures while M109/M190 wait, says
 * `echo:busy: processing` on long moves, and records every command it executed. The link between host and
 * printer can garble bytes on their way (a noisy USB cable).
 */

export interface FakeMarlinOptions {
  /** Garble the k-th line written to the printer (0-based count of writes) by flipping a character. */
  garble?: (k: number) => boolean;
  /** Simulated heating time of M109/M190, ms (temperature reports every `reportMs` meanwhile). */
  heatMs?: number;
  reportMs?: number;
  /** Say busy before the ok of every n-th G1 (0: never). */
  busyEvery?: number;
  /** Answer nothing to this command (a hung printer). */
  hangOn?: RegExp;
  /** Report this error line on this command (a fault). */
  faultOn?: { command: RegExp; line: string };
}

export class FakeMarlin {
  /** Commands executed, in order, without line numbers and checksums. */
  readonly executed: string[] = [];
  /** Resend requests made. */
  resends = 0;
  #expected = 1;
  #writes = 0;
  #buffer = '';
  #queue: string[] = [];
  #busy = false;
  readonly #send: (text: string) => void;
  readonly #o: FakeMarlinOptions;

  /** `send` gives the printer's output to the host. */
  constructor(send: (text: string) => void, opts: FakeMarlinOptions = {}) {
    this.#send = send;
    this.#o = opts;
  }

  /** The host writes (may garble on the way, per the options). */
  write(data: string): Promise<void> {
    let text = data;
    if (this.#o.garble?.(this.#writes++) && text.length > 4) {
      const i = Math.floor(text.length / 2);
      text = text.slice(0, i) + String.fromCharCode(text.charCodeAt(i) ^ 0x04) + text.slice(i + 1);
    }
    this.#buffer += text;
    let nl: number;
    while ((nl = this.#buffer.indexOf('\n')) >= 0) {
      this.#queue.push(this.#buffer.slice(0, nl));
      this.#buffer = this.#buffer.slice(nl + 1);
    }
    void this.#drain();
    return Promise.resolve();
  }

  async #drain(): Promise<void> {
    if (this.#busy) return;
    this.#busy = true;
    while (this.#queue.length) await this.#handle(this.#queue.shift()!);
    this.#busy = false;
  }

  #say(...lines: string[]): void {
    // as a serial line does, sometimes in pieces
    const text = lines.map((l) => l + '\n').join('');
    const cut = Math.floor(text.length / 3);
    setTimeout(() => this.#send(text.slice(0, cut)), 0);
    setTimeout(() => this.#send(text.slice(cut)), 1);
  }

  #resend(why: string): void {
    this.resends++;
    this.#say(`Error:${why}, Last Line: ${this.#expected - 1}`, `Resend: ${this.#expected}`, 'ok');
  }

  async #handle(raw: string): Promise<void> {
    const m = /^N(-?\d+) (.*)\*(\d+)$/.exec(raw.trim());
    if (!m) return this.#resend('No Checksum with line number');
    let cs = 0;
    const body = raw.trim().slice(0, raw.trim().lastIndexOf('*'));
    for (let i = 0; i < body.length; i++) cs ^= body.charCodeAt(i) & 0xff;
    if (cs !== Number(m[3])) return this.#resend('checksum mismatch');
    const n = Number(m[1]);
    const command = m[2]!.trim();
    if (/^M110\b/.test(command)) {
      this.#expected = Number(/N(\d+)/.exec(command)?.[1] ?? n) + 1;
      this.#say('ok');
      return;
    }
    if (n !== this.#expected) return this.#resend(`Line Number is not Last Line Number+1`);
    this.#expected++;
    if (this.#o.hangOn?.test(command)) return;
    if (this.#o.faultOn?.command.test(command)) {
      this.#say(this.#o.faultOn.line);
      return;
    }
    this.executed.push(command);
    if (/^M1(09|90)\b/.test(command) && this.#o.heatMs) {
      const until = Date.now() + this.#o.heatMs;
      while (Date.now() < until) {
        this.#say(' T:180.0 /210.0 B:60.0 /60.0 @:127 B@:0 W:?');
        await new Promise((r) => setTimeout(r, this.#o.reportMs ?? 20));
      }
    }
    if (this.#o.busyEvery && /^G1\b/.test(command) && this.executed.length % this.#o.busyEvery === 0)
      this.#say('echo:busy: processing');
    this.#say('ok');
  }
}
