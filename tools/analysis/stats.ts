/** Small statistics helpers. */

/**
 * The q-quantile (0..1) of a sample made of `total` values of which `positives` are the nonzero ones (the rest
 * are zero). `positives` is sorted in place.
 */
export function quantileWithZeros(positives: Float64Array, total: number, q: number): number {
  if (total === 0) return 0;
  const rank = Math.min(total, Math.max(1, Math.ceil(q * total)));
  const zeros = total - positives.length;
  if (rank <= zeros) return 0;
  positives.sort();
  return positives[rank - zeros - 1]!;
}

/** A weighted histogram with fixed bins over [0, max), for medians of many values without sorting. */
export class WeightedHistogram {
  private readonly bins: Float64Array;
  private total = 0;
  constructor(
    private readonly max: number,
    private readonly binWidth: number,
  ) {
    this.bins = new Float64Array(Math.ceil(max / binWidth) + 1);
  }
  add(value: number, weight: number): void {
    if (!(weight > 0) || !Number.isFinite(value)) return;
    const b = Math.min(this.bins.length - 1, Math.max(0, Math.floor(value / this.binWidth)));
    this.bins[b] = this.bins[b]! + weight;
    this.total += weight;
  }
  /** The weighted quantile (bin centre), NaN when empty. */
  quantile(q: number): number {
    if (this.total <= 0) return NaN;
    let acc = 0;
    for (let b = 0; b < this.bins.length; b++) {
      acc += this.bins[b]!;
      if (acc >= q * this.total) return Math.min(this.max, (b + 0.5) * this.binWidth);
    }
    return this.max;
  }
}
