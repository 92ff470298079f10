/**
 * A deliberately crude G-code generator over the analyser's own sections, for benchmarks and smoke tests on real
 * models: each layer prints its section outline as the wall, skin lines at line-width spacing where the model
 * has top or bottom surfaces, and sparse lines elsewhere. Not a slicer; just realistic-sized input.
 */
import type { Mesh } from '#strata/mesh/types.js';
import { filamentArea } from './raster.js';
import { createSectioner, sectionSpans } from './section.js';
import { skinRegions } from './skin.js';
import type { Spans } from './spans.js';
import { erodeSpans, spansBoolean } from './spans.js';

export interface ToyOptions {
  layerHeight: number;
  firstLayerHeight: number;
  lineWidth: number;
  filamentDiameter: number;
  /** Distance between sparse lines (one direction), mm. */
  infillSpacing: number;
  skinLayers: number;
  /** The part printed this much higher (mm), as over a raft. */
  zOffset?: number;
  /** Layers printed before the part's first, as a raft: print Z, height and G-code lines (relative E). */
  prelude?: { z: number; h: number; lines: string[] }[];
  /** More G-code for part layer i (relative E), such as support, written after the layer's Z move. */
  extra?: (i: number, z: number, h: number) => string[];
}

export function toyGcode(mesh: Mesh, o: ToyOptions): string {
  const sectioner = createSectioner(mesh);
  const area = filamentArea(o.filamentDiameter);
  const out: string[] = ['G21', 'G90', 'M83'];
  const spansAt = (z: number): Spans => sectionSpans(sectioner.section(z), o.lineWidth);
  const fmt = (v: number) => (Math.round(v * 1000) / 1000).toString();
  const prelude = o.prelude ?? [];
  prelude.forEach((l, k) => out.push(`;LAYER:${k - prelude.length}`, `G0 Z${fmt(l.z)} F600`, ...l.lines));
  const offset = o.zOffset ?? 0;
  for (let i = 0; ; i++) {
    const z = o.firstLayerHeight + i * o.layerHeight;
    const h = i === 0 ? o.firstLayerHeight : o.layerHeight;
    const mid = z - h / 2;
    if (mid >= sectioner.zMax) break;
    out.push(`;LAYER:${i}`, `G0 Z${fmt(z + offset)} F600`);
    if (o.extra) out.push(...o.extra(i, z + offset, h));
    out.push(';TYPE:WALL-OUTER');
    const seg = sectioner.section(mid);
    let x = NaN;
    let y = NaN;
    for (let k = 0; k < seg.count; k++) {
      if (seg.x0[k] !== x || seg.y0[k] !== y) out.push(`G0 X${fmt(seg.x0[k]!)} Y${fmt(seg.y0[k]!)} F6000`);
      x = seg.x1[k]!;
      y = seg.y1[k]!;
      const len = Math.hypot(x - seg.x0[k]!, y - seg.y0[k]!);
      out.push(`G1 X${fmt(x)} Y${fmt(y)} E${((o.lineWidth * h * len) / area).toFixed(5)} F1800`);
    }
    const spans = spansAt(mid);
    const neighbours = (dir: number) => {
      const list: Spans[] = [];
      for (let k = 1; k <= o.skinLayers; k++) list.push(spansAt(mid + dir * k * o.layerHeight));
      return list;
    };
    const skin = skinRegions(spans, neighbours(1), neighbours(-1));
    const solid = erodeSpans(spansBoolean(skin.top, skin.bottom, 'union'), o.lineWidth);
    const sparse = spansBoolean(erodeSpans(spans, o.lineWidth), solid, 'subtract');
    const every = Math.max(1, Math.round(o.infillSpacing / o.lineWidth));
    const lines = (s: Spans, type: string, rowStep: number) => {
      out.push(`;TYPE:${type}`);
      for (let r = 0; r < s.rows; r++) {
        if ((s.j0 + r) % rowStep !== 0) continue;
        const yc = (s.j0 + r + 0.5) * s.cell;
        for (let q = s.start[r]!; q < s.start[r + 1]!; q++) {
          const a = s.xs[2 * q]!;
          const b = s.xs[2 * q + 1]!;
          out.push(`G0 X${fmt(a)} Y${fmt(yc)} F6000`);
          out.push(`G1 X${fmt(b)} E${((o.lineWidth * h * (b - a)) / area).toFixed(5)} F3000`);
        }
      }
    };
    lines(solid, 'SKIN', 1);
    lines(sparse, 'FILL', every);
  }
  return out.join('\n') + '\n';
}

/** Triangles of a binary or ASCII STL as an unwelded mesh (test and benchmark input only). */
export function readStl(bytes: Uint8Array): Mesh {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const binaryCount = bytes.length >= 84 ? view.getUint32(80, true) : -1;
  if (binaryCount >= 0 && 84 + binaryCount * 50 === bytes.length) {
    const positions = new Float32Array(binaryCount * 9);
    for (let t = 0; t < binaryCount; t++) {
      const base = 84 + t * 50 + 12;
      for (let k = 0; k < 9; k++) positions[t * 9 + k] = view.getFloat32(base + 4 * k, true);
    }
    return { positions, indices: Uint32Array.from({ length: binaryCount * 3 }, (_, i) => i) };
  }
  const text = new TextDecoder().decode(bytes);
  const values: number[] = [];
  for (const m of text.matchAll(/vertex\s+(\S+)\s+(\S+)\s+(\S+)/g)) values.push(+m[1]!, +m[2]!, +m[3]!);
  const indices = Uint32Array.from({ length: values.length / 3 }, (_, i) => i);
  return { positions: Float32Array.from(values), indices };
}

/** The mesh moved so that its bounding box is centred on (cx, cy) and rests on z = 0, as slicers place it. */
export function placeOnBed(mesh: Mesh, cx: number, cy: number): Mesh {
  const p = mesh.positions;
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let k = 0; k < p.length; k++) {
    min[k % 3] = Math.min(min[k % 3]!, p[k]!);
    max[k % 3] = Math.max(max[k % 3]!, p[k]!);
  }
  const shift = [cx - (min[0]! + max[0]!) / 2, cy - (min[1]! + max[1]!) / 2, -min[2]!];
  return { positions: p.map((v, k) => v + shift[k % 3]!), indices: mesh.indices };
}
