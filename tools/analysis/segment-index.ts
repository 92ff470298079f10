/**
 * Spatial indexes over 2D segments: a bucket grid for nearest-segment queries, and horizontal bands for exact
 * nonzero-winding point-in-region tests against closed, oriented loops.
 */

type Coords = Float32Array | Float64Array;

/** At most this many buckets; larger extents get coarser buckets. */
const MAX_BUCKETS = 1 << 20;

/** Nearest-segment queries within a bounded radius. */
export class SegmentIndex {
  /** Closest point and segment of the last successful nearest() query. */
  qx = 0;
  qy = 0;
  seg = -1;
  private readonly bucket: number;
  private readonly bx0: number;
  private readonly by0: number;
  private readonly cols: number;
  private readonly rows: number;
  private readonly start: Uint32Array;
  private readonly list: Uint32Array;

  /**
   * Indexes segments `ids` (or all `count` segments when ids is null). `bucketMm` should be about the query radius.
   */
  constructor(
    private readonly x0: Coords,
    private readonly y0: Coords,
    private readonly x1: Coords,
    private readonly y1: Coords,
    ids: Uint32Array | null,
    count: number,
    bucketMm: number,
  ) {
    const n = ids ? ids.length : count;
    let xmin = Infinity,
      ymin = Infinity,
      xmax = -Infinity,
      ymax = -Infinity;
    for (let k = 0; k < n; k++) {
      const i = ids ? ids[k]! : k;
      xmin = Math.min(xmin, x0[i]!, x1[i]!);
      xmax = Math.max(xmax, x0[i]!, x1[i]!);
      ymin = Math.min(ymin, y0[i]!, y1[i]!);
      ymax = Math.max(ymax, y0[i]!, y1[i]!);
    }
    if (n === 0) {
      xmin = ymin = 0;
      xmax = ymax = 1;
    }
    let b = bucketMm;
    while (((xmax - xmin) / b + 1) * ((ymax - ymin) / b + 1) > MAX_BUCKETS) b *= 2;
    this.bucket = b;
    this.bx0 = xmin;
    this.by0 = ymin;
    this.cols = Math.floor((xmax - xmin) / b) + 1;
    this.rows = Math.floor((ymax - ymin) / b) + 1;
    const counts = new Uint32Array(this.cols * this.rows + 1);
    for (let k = 0; k < n; k++) this.walk(ids ? ids[k]! : k, counts, null);
    for (let q = 0; q < this.cols * this.rows; q++) counts[q + 1] = counts[q + 1]! + counts[q]!;
    this.start = counts;
    this.list = new Uint32Array(counts[this.cols * this.rows]!);
    const fill = counts.slice(0, this.cols * this.rows);
    for (let k = 0; k < n; k++) this.walk(ids ? ids[k]! : k, null, fill);
  }

  /** Visits the buckets along segment i (samples every half bucket), counting or filling. */
  private walk(i: number, counts: Uint32Array | null, fill: Uint32Array | null): void {
    const ax = this.x0[i]!,
      ay = this.y0[i]!,
      bx = this.x1[i]!,
      by = this.y1[i]!;
    const len = Math.hypot(bx - ax, by - ay);
    const steps = Math.max(1, Math.ceil(len / (this.bucket / 2)));
    let last = -1;
    for (let s = 0; s <= steps; s++) {
      const t = s / steps;
      const cx = Math.floor((ax + t * (bx - ax) - this.bx0) / this.bucket);
      const cy = Math.floor((ay + t * (by - ay) - this.by0) / this.bucket);
      const q = Math.min(this.rows - 1, Math.max(0, cy)) * this.cols + Math.min(this.cols - 1, Math.max(0, cx));
      if (q === last) continue;
      last = q;
      if (counts) counts[q + 1]!++;
      else this.list[fill![q]!++] = i;
    }
  }

  /**
   * Distance from (px, py) to the nearest indexed segment if it is within maxDist, else Infinity. On success the
   * closest point is left in qx, qy and the segment id in seg.
   */
  nearest(px: number, py: number, maxDist: number): number {
    const b = this.bucket;
    const reach = Math.ceil((maxDist + b / 4) / b);
    const cx = Math.floor((px - this.bx0) / b);
    const cy = Math.floor((py - this.by0) / b);
    let best = maxDist * maxDist;
    let found = false;
    const ya = Math.max(0, cy - reach);
    const yb = Math.min(this.rows - 1, cy + reach);
    const xa = Math.max(0, cx - reach);
    const xb = Math.min(this.cols - 1, cx + reach);
    for (let y = ya; y <= yb; y++) {
      for (let x = xa; x <= xb; x++) {
        const q = y * this.cols + x;
        for (let k = this.start[q]!; k < this.start[q + 1]!; k++) {
          const i = this.list[k]!;
          const ax = this.x0[i]!,
            ay = this.y0[i]!;
          const dx = this.x1[i]! - ax,
            dy = this.y1[i]! - ay;
          const l2 = dx * dx + dy * dy;
          let t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
          t = t < 0 ? 0 : t > 1 ? 1 : t;
          const qx = ax + t * dx;
          const qy = ay + t * dy;
          const d2 = (px - qx) * (px - qx) + (py - qy) * (py - qy);
          if (d2 <= best) {
            best = d2;
            found = true;
            this.qx = qx;
            this.qy = qy;
            this.seg = i;
          }
        }
      }
    }
    return found ? Math.sqrt(best) : Infinity;
  }
}

/** Exact nonzero-winding tests against closed oriented loops, with segments binned in horizontal bands. */
export class WindingIndex {
  private readonly y0band: number;
  private readonly bands: number;
  private readonly start: Uint32Array;
  private readonly list: Uint32Array;

  constructor(
    private readonly x0: Coords,
    private readonly y0: Coords,
    private readonly x1: Coords,
    private readonly y1: Coords,
    count: number,
    private readonly band: number,
  ) {
    let ymin = Infinity,
      ymax = -Infinity;
    for (let i = 0; i < count; i++) {
      ymin = Math.min(ymin, y0[i]!, y1[i]!);
      ymax = Math.max(ymax, y0[i]!, y1[i]!);
    }
    if (count === 0) ymin = ymax = 0;
    this.y0band = ymin;
    this.bands = Math.floor((ymax - ymin) / band) + 1;
    const counts = new Uint32Array(this.bands + 1);
    for (let i = 0; i < count; i++) {
      const [a, b] = this.bandRange(i);
      for (let q = a; q <= b; q++) counts[q + 1]!++;
    }
    for (let q = 0; q < this.bands; q++) counts[q + 1] = counts[q + 1]! + counts[q]!;
    this.start = counts;
    this.list = new Uint32Array(counts[this.bands]!);
    const fill = counts.slice(0, this.bands);
    for (let i = 0; i < count; i++) {
      const [a, b] = this.bandRange(i);
      for (let q = a; q <= b; q++) this.list[fill[q]!++] = i;
    }
  }

  private bandRange(i: number): [number, number] {
    const lo = Math.min(this.y0[i]!, this.y1[i]!);
    const hi = Math.max(this.y0[i]!, this.y1[i]!);
    return [this.bandOf(lo), this.bandOf(hi)];
  }

  private bandOf(y: number): number {
    return Math.min(this.bands - 1, Math.max(0, Math.floor((y - this.y0band) / this.band)));
  }

  /** Winding number of the loops around (px, py): nonzero means inside. */
  winding(px: number, py: number): number {
    const q = Math.floor((py - this.y0band) / this.band);
    if (q < 0 || q >= this.bands) return 0;
    let w = 0;
    for (let k = this.start[q]!; k < this.start[q + 1]!; k++) {
      const i = this.list[k]!;
      const ya = this.y0[i]!,
        yb = this.y1[i]!;
      const up = ya <= py && py < yb;
      const down = yb <= py && py < ya;
      if (!up && !down) continue;
      const x = this.x0[i]! + ((py - ya) * (this.x1[i]! - this.x0[i]!)) / (yb - ya);
      if (x > px) w += up ? 1 : -1;
    }
    return w;
  }
}
