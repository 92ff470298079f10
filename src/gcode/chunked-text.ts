/**
 * A text builder for G-code that writes bytes into one reusable buffer and hands the sink a string of
 * about `chunkBytes` at each line end past that size. Numbers are written digit by digit, so the hot
 * path (millions of move lines) allocates no intermediate strings. The number format is the one of
 * format.ts's `fixedDecimal`: exact decimals, no trailing zeros, no `-0`.
 */

/** Room kept past the chunk size for the line that crosses it (move lines are far shorter). */
const LINE_ROOM = 4096;
const MINUS = 45;
const DOT = 46;
const ZERO = 48;
const NEWLINE = 10;

export class ChunkedText {
  private bytes: Uint8Array;
  private n = 0;
  private readonly decoder = new TextDecoder();
  private readonly encoder = new TextEncoder();

  constructor(
    private readonly sink: (chunk: string) => void,
    private readonly chunkBytes: number,
  ) {
    this.bytes = new Uint8Array(chunkBytes + LINE_ROOM);
  }

  private ensure(extra: number): void {
    if (this.n + extra <= this.bytes.length) return;
    let size = this.bytes.length * 2;
    while (this.n + extra > size) size *= 2;
    const bigger = new Uint8Array(size);
    bigger.set(this.bytes.subarray(0, this.n));
    this.bytes = bigger;
  }

  /** Append text (any Unicode; ASCII takes the fast path). */
  text(s: string): void {
    const length = s.length;
    this.ensure(length * 3);
    const bytes = this.bytes;
    let n = this.n;
    for (let i = 0; i < length; i++) {
      const c = s.charCodeAt(i);
      if (c >= 128) {
        this.n += this.encoder.encodeInto(s, bytes.subarray(this.n)).written;
        return;
      }
      bytes[n++] = c;
    }
    this.n = n;
  }

  /** Append a non-negative integer (< 2^53). */
  private digits(value: number): void {
    if (value < 10) {
      this.bytes[this.n++] = ZERO + value;
      return;
    }
    let count = 1;
    for (let p = 10; p <= value; p *= 10) count++;
    const bytes = this.bytes;
    let i = this.n + count;
    this.n = i;
    let v = value;
    while (i > this.n - count) {
      const q = Math.floor(v / 10);
      bytes[--i] = ZERO + (v - q * 10);
      v = q;
    }
  }

  /** Append an integer. */
  int(value: number): void {
    if (value < 0) {
      this.bytes[this.n++] = MINUS;
      this.digits(-value);
    } else this.digits(value);
  }

  /**
   * Append the integer `units` as a decimal with `decimals` places at most (scale = 10^decimals),
   * trailing zeros dropped: `fixed(10500, 1000, 3)` appends `10.5`.
   */
  fixed(units: number, scale: number, decimals: number): void {
    let magnitude = units;
    if (units < 0) {
      this.bytes[this.n++] = MINUS;
      magnitude = -units;
    }
    const whole = Math.floor(magnitude / scale);
    this.digits(whole);
    let fraction = magnitude - whole * scale;
    if (fraction === 0) return;
    let width = decimals;
    while (fraction % 10 === 0) {
      fraction /= 10;
      width--;
    }
    const bytes = this.bytes;
    bytes[this.n++] = DOT;
    let end = this.n + width;
    const start = this.n;
    this.n = end;
    while (end > start) {
      const q = Math.floor(fraction / 10);
      bytes[--end] = ZERO + (fraction - q * 10);
      fraction = q;
    }
  }

  /** End the line; pass the buffer to the sink once it holds a chunk. */
  endLine(): void {
    this.bytes[this.n++] = NEWLINE;
    if (this.n >= this.chunkBytes) this.flush();
  }

  /** A whole line of text. */
  line(s: string): void {
    this.text(s);
    this.endLine();
  }

  /** Pass whatever is buffered to the sink. */
  flush(): void {
    if (this.n === 0) return;
    this.sink(this.decoder.decode(this.bytes.subarray(0, this.n)));
    this.n = 0;
  }
}
