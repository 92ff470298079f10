/**
 * Groups the parser's file-ordered blocks into layers by print Z. A block's print Z is the Z carrying most of its
 * extrusion length; blocks with the same print Z (sequential printing, repeated markers) merge into one layer.
 * Blocks before the first layer marker form the preamble (start G-code, purge lines) when markers exist.
 */
import type { ExtrusionTable, GcodeExtents, GcodeLayer, RetractionTable, TravelTable } from './gcode-types.js';
import type { RawRecords } from './gcode-records.js';

/** Print Z values that round to the same 0.1 µm step are the same layer. */
const Z_KEYS_PER_MM = 1e4;

/** Integer key of a print Z (mm). */
export function zKey(z: number): number {
  return Math.round(z * Z_KEYS_PER_MM);
}

const PREAMBLE = -1;

export interface GroupedLayers {
  layers: GcodeLayer[];
  preamble: { extrusions: ExtrusionTable; travels: TravelTable };
  retractions: RetractionTable;
  extents: GcodeExtents | null;
}

export function groupLayers(raw: RawRecords): GroupedLayers {
  const blocks = raw.blockCount;
  const segBlock = raw.ext.block.data;
  const nSeg = raw.ext.block.length;

  // Print Z of each block with extrusion.
  const blockZ = new Float64Array(blocks).fill(NaN);
  let s = 0;
  while (s < nSeg) {
    const b = segBlock[s]!;
    let end = s;
    while (end < nSeg && segBlock[end] === b) end++;
    blockZ[b] = dominantZ(raw, s, end);
    s = end;
  }

  // Distinct print Z values (excluding the preamble) become layers, sorted ascending.
  const keyToLayer = new Map<number, number>();
  const keys: number[] = [];
  for (let b = 0; b < blocks; b++) {
    if (b < raw.firstMarkerBlock && raw.firstMarkerBlock !== Infinity) continue;
    const z = blockZ[b]!;
    if (Number.isNaN(z)) continue;
    const key = zKey(z);
    if (!keyToLayer.has(key)) {
      keyToLayer.set(key, 0);
      keys.push(key);
    }
  }
  keys.sort((a, b) => a - b);
  keys.forEach((key, i) => keyToLayer.set(key, i));

  // Layer of each block; blocks without extrusion join the previous layer in file order (else the next one).
  const blockLayer = new Int32Array(blocks).fill(PREAMBLE);
  const inPreamble = (b: number) => raw.firstMarkerBlock !== Infinity && b < raw.firstMarkerBlock;
  let last = PREAMBLE;
  for (let b = 0; b < blocks; b++) {
    if (inPreamble(b)) continue;
    const z = blockZ[b]!;
    if (!Number.isNaN(z)) last = keyToLayer.get(zKey(z))!;
    blockLayer[b] = last;
  }
  let next = PREAMBLE;
  for (let b = blocks - 1; b >= 0; b--) {
    if (inPreamble(b)) continue;
    if (blockLayer[b] !== PREAMBLE) next = blockLayer[b]!;
    else blockLayer[b] = next;
  }

  const nLayers = keys.length;
  const extrusions = splitExtrusions(raw, blockLayer, nLayers);
  const travels = splitTravels(raw, blockLayer, nLayers);

  const layers: GcodeLayer[] = [];
  let prevZ = 0;
  const markerOf = new Float64Array(nLayers).fill(NaN);
  const heightOf = new Float64Array(nLayers).fill(NaN);
  for (let b = 0; b < blocks; b++) {
    const l = blockLayer[b]!;
    const m = raw.blockMarker.data[b]!;
    if (l >= 0 && Number.isNaN(markerOf[l]!) && !Number.isNaN(m)) markerOf[l] = m;
    const h = raw.blockHeight.data[b]!;
    if (l >= 0 && Number.isNaN(heightOf[l]!) && !Number.isNaN(h)) heightOf[l] = h;
  }
  for (let i = 0; i < nLayers; i++) {
    const table = extrusions.layers[i]!;
    let zMin = Infinity;
    let zMax = -Infinity;
    for (let k = 0; k < table.count; k++) {
      const z = table.z[k]!;
      if (z < zMin) zMin = z;
      if (z > zMax) zMax = z;
    }
    const z = keys[i]! / Z_KEYS_PER_MM;
    const marker = markerOf[i]!;
    layers.push({
      index: i,
      z,
      thickness: z - prevZ,
      zMin,
      zMax,
      marker: Number.isNaN(marker) ? null : marker,
      declaredHeight: Number.isNaN(heightOf[i]!) ? null : heightOf[i]!,
      extrusions: table,
      travels: travels.layers[i]!,
    });
    prevZ = z;
  }

  return {
    layers,
    preamble: { extrusions: extrusions.preamble, travels: travels.preamble },
    retractions: retractionTable(raw, blockLayer),
    extents: extentsOf(layers),
  };
}

/**
 * The Z with the largest extrusion length among segments [start, end); for a spiral turn (a spiral vase: Z
 * never falls through the block and no one Z carries half its length) the highest Z, where the turn ends
 * and which its layer marker declares.
 */
function dominantZ(raw: RawRecords, start: number, end: number): number {
  const z = raw.ext.z.data;
  const first = z[start]!;
  let uniform = true;
  for (let i = start + 1; i < end; i++) {
    if (z[i] !== first) {
      uniform = false;
      break;
    }
  }
  if (uniform) return first;
  const { x0, y0, x1, y1 } = raw.ext;
  const lengthByKey = new Map<number, number>();
  const zByKey = new Map<number, number>();
  for (let i = start; i < end; i++) {
    const key = zKey(z[i]!);
    const len = Math.hypot(x1.data[i]! - x0.data[i]!, y1.data[i]! - y0.data[i]!);
    lengthByKey.set(key, (lengthByKey.get(key) ?? 0) + len);
    if (!zByKey.has(key)) zByKey.set(key, z[i]!);
  }
  let best = first;
  let bestLen = -1;
  let total = 0;
  for (const [key, len] of lengthByKey) {
    total += len;
    if (len > bestLen) {
      bestLen = len;
      best = zByKey.get(key)!;
    }
  }
  if (bestLen < total / 2) {
    let rising = true;
    let top = first;
    for (let i = start + 1; i < end && rising; i++) {
      rising = z[i]! >= z[i - 1]!;
      if (z[i]! > top) top = z[i]!;
    }
    if (rising) return top;
  }
  return best;
}

function emptyExtrusions(n: number): ExtrusionTable {
  return {
    count: 0,
    x0: new Float32Array(n),
    y0: new Float32Array(n),
    x1: new Float32Array(n),
    y1: new Float32Array(n),
    z: new Float32Array(n),
    e: new Float32Array(n),
    feedrate: new Float32Array(n),
    feature: new Uint8Array(n),
  };
}

function emptyTravels(n: number): TravelTable {
  return {
    count: 0,
    x0: new Float32Array(n),
    y0: new Float32Array(n),
    z0: new Float32Array(n),
    x1: new Float32Array(n),
    y1: new Float32Array(n),
    z1: new Float32Array(n),
  };
}

/** Counts per destination (index 0 = preamble, i + 1 = layer i). */
function countsByLayer(blockOf: Uint32Array, n: number, blockLayer: Int32Array, nLayers: number): Uint32Array {
  const counts = new Uint32Array(nLayers + 1);
  for (let i = 0; i < n; i++) counts[blockLayer[blockOf[i]!]! + 1]!++;
  return counts;
}

function splitExtrusions(raw: RawRecords, blockLayer: Int32Array, nLayers: number) {
  const src = raw.ext;
  const n = src.block.length;
  const counts = countsByLayer(src.block.data, n, blockLayer, nLayers);
  const tables = Array.from(counts, (c) => emptyExtrusions(c));
  for (let i = 0; i < n; i++) {
    const t = tables[blockLayer[src.block.data[i]!]! + 1]!;
    const k = t.count++;
    t.x0[k] = src.x0.data[i]!;
    t.y0[k] = src.y0.data[i]!;
    t.x1[k] = src.x1.data[i]!;
    t.y1[k] = src.y1.data[i]!;
    t.z[k] = src.z.data[i]!;
    t.e[k] = src.e.data[i]!;
    t.feedrate[k] = src.feedrate.data[i]!;
    t.feature[k] = src.feature.data[i]!;
  }
  return { preamble: tables[0]!, layers: tables.slice(1) };
}

function splitTravels(raw: RawRecords, blockLayer: Int32Array, nLayers: number) {
  const src = raw.travel;
  const n = src.block.length;
  const counts = countsByLayer(src.block.data, n, blockLayer, nLayers);
  const tables = Array.from(counts, (c) => emptyTravels(c));
  for (let i = 0; i < n; i++) {
    const t = tables[blockLayer[src.block.data[i]!]! + 1]!;
    const k = t.count++;
    t.x0[k] = src.x0.data[i]!;
    t.y0[k] = src.y0.data[i]!;
    t.z0[k] = src.z0.data[i]!;
    t.x1[k] = src.x1.data[i]!;
    t.y1[k] = src.y1.data[i]!;
    t.z1[k] = src.z1.data[i]!;
  }
  return { preamble: tables[0]!, layers: tables.slice(1) };
}

function retractionTable(raw: RawRecords, blockLayer: Int32Array): RetractionTable {
  const r = raw.retraction;
  const n = r.kind.length;
  const layer = new Int32Array(n);
  for (let i = 0; i < n; i++) layer[i] = blockLayer[r.block.data[i]!]!;
  return { count: n, kind: r.kind.toArray(), amount: r.amount.toArray(), line: r.line.toArray(), layer };
}

function extentsOf(layers: GcodeLayer[]): GcodeExtents | null {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  let any = false;
  for (const layer of layers) {
    const t = layer.extrusions;
    for (let i = 0; i < t.count; i++) {
      any = true;
      const xa = t.x0[i]!,
        xb = t.x1[i]!,
        ya = t.y0[i]!,
        yb = t.y1[i]!,
        z = t.z[i]!;
      if (xa < min[0]) min[0] = xa;
      if (xb < min[0]) min[0] = xb;
      if (xa > max[0]) max[0] = xa;
      if (xb > max[0]) max[0] = xb;
      if (ya < min[1]) min[1] = ya;
      if (yb < min[1]) min[1] = yb;
      if (ya > max[1]) max[1] = ya;
      if (yb > max[1]) max[1] = yb;
      if (z < min[2]) min[2] = z;
      if (z > max[2]) max[2] = z;
    }
  }
  return any ? { min, max } : null;
}
