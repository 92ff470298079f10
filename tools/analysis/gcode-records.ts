/**
 * The parser's raw, file-ordered records before they are grouped into layers. Every record carries the id of the
 * block it was written in: a block starts at each layer marker, or (without markers) whenever extrusion continues
 * at a new Z.
 */
import { growableF32, growableF64, growableU32, growableU8 } from './growable.js';

export class RawRecords {
  readonly ext = {
    x0: growableF32(4096),
    y0: growableF32(4096),
    x1: growableF32(4096),
    y1: growableF32(4096),
    z: growableF32(4096),
    e: growableF32(4096),
    feedrate: growableF32(4096),
    feature: growableU8(4096),
    block: growableU32(4096),
  };
  readonly travel = {
    x0: growableF32(4096),
    y0: growableF32(4096),
    z0: growableF32(4096),
    x1: growableF32(4096),
    y1: growableF32(4096),
    z1: growableF32(4096),
    block: growableU32(4096),
  };
  readonly retraction = {
    kind: growableU8(256),
    amount: growableF32(256),
    line: growableU32(256),
    block: growableU32(256),
  };
  /** Marker value per block (NaN for blocks not opened by a marker). */
  readonly blockMarker = growableF64(256);
  /** Layer height the G-code declares in the block (`;HEIGHT:`, its first one), NaN without. */
  readonly blockHeight = growableF64(256);
  /** Blocks with an id below this come before the first layer marker; Infinity when no marker was seen. */
  firstMarkerBlock = Infinity;

  constructor() {
    this.blockMarker.push(NaN);
    this.blockHeight.push(NaN);
  }

  get blockCount(): number {
    return this.blockMarker.length;
  }

  /** Opens a new block and returns its id. */
  openBlock(marker: number): number {
    this.blockMarker.push(marker);
    this.blockHeight.push(NaN);
    return this.blockMarker.length - 1;
  }

  /** Record a `;HEIGHT:` of block b (the first one counts). */
  declareHeight(b: number, heightMm: number): void {
    if (Number.isNaN(this.blockHeight.data[b]!)) this.blockHeight.data[b] = heightMm;
  }

  pushExtrusion(
    x0: number,
    y0: number,
    x1: number,
    y1: number,
    z: number,
    e: number,
    f: number,
    feature: number,
    block: number,
  ): void {
    const t = this.ext;
    t.x0.push(x0);
    t.y0.push(y0);
    t.x1.push(x1);
    t.y1.push(y1);
    t.z.push(z);
    t.e.push(e);
    t.feedrate.push(f);
    t.feature.push(feature);
    t.block.push(block);
  }

  pushTravel(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number, block: number): void {
    const t = this.travel;
    t.x0.push(x0);
    t.y0.push(y0);
    t.z0.push(z0);
    t.x1.push(x1);
    t.y1.push(y1);
    t.z1.push(z1);
    t.block.push(block);
  }

  /** More filament for the last retraction record (a retraction spread over several moves: a wipe). */
  extendRetraction(amount: number): void {
    const a = this.retraction.amount;
    if (a.length > 0) a.data[a.length - 1] += amount;
  }

  pushRetraction(kind: number, amount: number, line: number, block: number): void {
    const r = this.retraction;
    r.kind.push(kind);
    r.amount.push(amount);
    r.line.push(line);
    r.block.push(block);
  }
}
