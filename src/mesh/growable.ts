/**
 * Append-only typed-array buffers that double their capacity, for parsers that do not know
 * their element count up front.
 */

type NumericArray = Float32Array | Float64Array | Uint32Array;

/** A growing list of numbers backed by one kind of typed array. */
class Growable<A extends NumericArray> {
  data: A;
  length = 0;
  readonly #make: (n: number) => A;
  constructor(make: (n: number) => A, capacity: number) {
    this.#make = make;
    this.data = make(Math.max(16, capacity));
  }
  push(a: number): void {
    if (this.length + 1 > this.data.length) this.#grow(this.length + 1);
    this.data[this.length++] = a;
  }
  push3(a: number, b: number, c: number): void {
    if (this.length + 3 > this.data.length) this.#grow(this.length + 3);
    const d = this.data;
    const n = this.length;
    d[n] = a;
    d[n + 1] = b;
    d[n + 2] = c;
    this.length = n + 3;
  }
  #grow(min: number): void {
    const next = this.#make(Math.max(min, this.data.length * 2));
    next.set(this.data.subarray(0, this.length));
    this.data = next;
  }
  /** A copy trimmed to the used length. */
  toArray(): A {
    return this.data.slice(0, this.length) as A;
  }
}

export class GrowableF32 extends Growable<Float32Array> {
  constructor(capacity = 1024) {
    super((n) => new Float32Array(n), capacity);
  }
}

export class GrowableF64 extends Growable<Float64Array> {
  constructor(capacity = 1024) {
    super((n) => new Float64Array(n), capacity);
  }
}

export class GrowableU32 extends Growable<Uint32Array> {
  constructor(capacity = 1024) {
    super((n) => new Uint32Array(n), capacity);
  }
}
