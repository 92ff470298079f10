/** Append-only typed arrays that double their capacity as they fill. */

type TypedArray = Float32Array | Float64Array | Uint32Array | Uint8Array;

export class Growable<T extends TypedArray> {
  data: T;
  length = 0;
  constructor(
    private readonly make: (capacity: number) => T,
    capacity = 1024,
  ) {
    this.data = make(capacity);
  }
  push(v: number): void {
    if (this.length === this.data.length) {
      const bigger = this.make(this.data.length * 2);
      bigger.set(this.data as never);
      this.data = bigger;
    }
    this.data[this.length++] = v;
  }
  /** A compact copy of the filled part. */
  toArray(): T {
    return this.data.slice(0, this.length) as T;
  }
}

export const growableF32 = (capacity?: number) => new Growable((n) => new Float32Array(n), capacity);
export const growableF64 = (capacity?: number) => new Growable((n) => new Float64Array(n), capacity);
export const growableU32 = (capacity?: number) => new Growable((n) => new Uint32Array(n), capacity);
export const growableU8 = (capacity?: number) => new Growable((n) => new Uint8Array(n), capacity);
