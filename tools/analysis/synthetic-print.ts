/**
 * Hand-made inputs for the analyser's tests and benchmarks: an axis-aligned box mesh and a small G-code writer
 * that extrudes w·h per mm of path (Cura's volume rule) in absolute or relative E.
 */
import type { Mesh } from '#strata/mesh/types.js';
import { filamentArea } from './raster.js';

/** Several closed meshes as one (their shells side by side; sections union them). */
export function mergeMeshes(...meshes: Mesh[]): Mesh {
  const positions: number[] = [];
  const indices: number[] = [];
  for (const m of meshes) {
    const base = positions.length / 3;
    positions.push(...m.positions);
    for (const i of m.indices) indices.push(base + i);
  }
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices) };
}

/**
 * G-code lines (relative E, Cura's volume rule w·h per mm) that fill the rectangle [x0, x1] × [y0, y1] with
 * parallel lines `spacing` apart along x (or along y with `alongY`), under `;TYPE:type`. Line centres keep half a
 * line width inside the rectangle.
 */
export function rectLines(
  rect: [number, number, number, number],
  spacing: number,
  h: number,
  lineWidth: number,
  filamentDiameter: number,
  type: string,
  alongY = false,
): string[] {
  const [x0, y0, x1, y1] = rect;
  const area = filamentArea(filamentDiameter);
  const out = [`;TYPE:${type}`];
  const half = lineWidth / 2;
  const [a0, a1, b0, b1] = alongY ? [y0, y1, x0, x1] : [x0, x1, y0, y1];
  for (let b = b0 + half; b <= b1 - half + 1e-9; b += spacing) {
    const e = ((lineWidth * h * (a1 - a0 - 2 * half)) / area).toFixed(5);
    const [sx, sy, ex, ey] = alongY ? [b, a0 + half, b, a1 - half] : [a0 + half, b, a1 - half, b];
    out.push(`G0 X${fmt(sx)} Y${fmt(sy)} F6000`, `G1 X${fmt(ex)} Y${fmt(ey)} E${e} F1800`);
  }
  return out;
}

/** A closed box with outward-facing triangles. */
export function boxMesh(x0: number, y0: number, z0: number, x1: number, y1: number, z1: number): Mesh {
  const positions = new Float32Array([
    x0,
    y0,
    z0,
    x1,
    y0,
    z0,
    x1,
    y1,
    z0,
    x0,
    y1,
    z0, // 0..3 bottom: 000 100 110 010
    x0,
    y0,
    z1,
    x1,
    y0,
    z1,
    x1,
    y1,
    z1,
    x0,
    y1,
    z1, // 4..7 top:    001 101 111 011
  ]);
  // Quads counter-clockwise as seen from outside.
  const quads = [
    [0, 3, 2, 1], // bottom
    [4, 5, 6, 7], // top
    [0, 1, 5, 4], // front (-y)
    [2, 3, 7, 6], // back (+y)
    [3, 0, 4, 7], // left (-x)
    [1, 2, 6, 5], // right (+x)
  ];
  const indices: number[] = [];
  for (const [a, b, c, d] of quads) indices.push(a!, b!, c!, a!, c!, d!);
  return { positions, indices: new Uint32Array(indices) };
}

/** A copy of a mesh with every triangle's winding reversed (inward-facing). */
export function flipMesh(mesh: Mesh): Mesh {
  const indices = mesh.indices.slice();
  for (let t = 0; t < indices.length; t += 3) {
    const b = indices[t + 1]!;
    indices[t + 1] = indices[t + 2]!;
    indices[t + 2] = b;
  }
  return { positions: mesh.positions, indices };
}

/** A copy of a mesh without the triangles for which `drop(t)` holds (an open mesh). */
export function dropTriangles(mesh: Mesh, drop: (t: number) => boolean): Mesh {
  const kept: number[] = [];
  for (let t = 0; t < mesh.indices.length / 3; t++) {
    if (!drop(t)) kept.push(mesh.indices[3 * t]!, mesh.indices[3 * t + 1]!, mesh.indices[3 * t + 2]!);
  }
  return { positions: mesh.positions, indices: Uint32Array.from(kept) };
}

export interface WriterOptions {
  lineWidth: number;
  filamentDiameter: number;
  relativeE: boolean;
  /** 'cura' writes ;LAYER:n, 'prusa' ;LAYER_CHANGE, 'none' no layer markers. */
  markers: 'cura' | 'prusa' | 'none';
}

/** Builds G-code text line by line. Coordinates in mm. */
export class GcodeWriter {
  private readonly out: string[] = [];
  private x = 0;
  private y = 0;
  private e = 0;
  private h = 0.2;
  private readonly area: number;

  constructor(private readonly o: WriterOptions) {
    this.area = filamentArea(o.filamentDiameter);
    this.out.push('G21', 'G90', o.relativeE ? 'M83' : 'M82', 'G92 E0');
  }

  raw(line: string): this {
    this.out.push(line);
    return this;
  }

  /** Starts layer `index` at print Z `z`, `height` thick (for E). */
  layer(index: number, z: number, height: number): this {
    if (this.o.markers === 'cura') this.out.push(`;LAYER:${index}`);
    if (this.o.markers === 'prusa') this.out.push(';LAYER_CHANGE', `;Z:${z}`);
    this.h = height;
    this.out.push(`G0 Z${fmt(z)} F600`);
    return this;
  }

  type(name: string): this {
    this.out.push(`;TYPE:${name}`);
    return this;
  }

  travel(x: number, y: number): this {
    this.x = x;
    this.y = y;
    this.out.push(`G0 X${fmt(x)} Y${fmt(y)} F6000`);
    return this;
  }

  /** Extrudes a straight line to (x, y) at `width` (default: the line width). */
  line(x: number, y: number, width = this.o.lineWidth): this {
    const len = Math.hypot(x - this.x, y - this.y);
    const de = (width * this.h * len) / this.area;
    this.x = x;
    this.y = y;
    this.out.push(`G1 X${fmt(x)} Y${fmt(y)} E${this.eWord(de)} F1800`);
    return this;
  }

  /** A closed rectangle loop starting at its (x0, y0) corner, counter-clockwise. */
  rect(x0: number, y0: number, x1: number, y1: number): this {
    return this.travel(x0, y0).line(x1, y0).line(x1, y1).line(x0, y1).line(x0, y0);
  }

  retract(amount: number): this {
    this.out.push(`G1 E${this.eWord(-amount)} F2400`);
    return this;
  }

  prime(amount: number): this {
    this.out.push(`G1 E${this.eWord(amount)} F2400`);
    return this;
  }

  text(): string {
    return this.out.join('\n') + '\n';
  }

  private eWord(de: number): string {
    if (this.o.relativeE) return de.toFixed(5);
    this.e += de;
    return this.e.toFixed(5);
  }
}

function fmt(v: number): string {
  return String(Math.round(v * 1000) / 1000);
}

export interface BoxPrintOptions {
  size: [number, number, number];
  origin: [number, number];
  layerHeight: number;
  lineWidth: number;
  walls: number;
  skinLayers: number;
  /** Distance between parallel sparse infill lines in each of the two grid directions (mm). */
  infillSpacing: number;
  writer: GcodeWriter;
  /** Layers to leave without walls, skin or infill, and layer to shift by dx. */
  skipWallsOn?: number[];
  skipSkinOn?: number[];
  shift?: { layer: number; dx: number };
}

/**
 * Writes a box the way a slicer would: `walls` perimeters inset by half a width and then a width each, ±x/±y
 * alternating solid skin on the bottom and top `skinLayers`, and a grid of sparse lines elsewhere.
 */
export function writeBoxPrint(o: BoxPrintOptions): void {
  const [sx, sy, sz] = o.size;
  const layers = Math.round(sz / o.layerHeight);
  const w = o.lineWidth;
  const g = o.writer;
  for (let l = 0; l < layers; l++) {
    const dx = o.shift?.layer === l ? o.shift.dx : 0;
    const x0 = o.origin[0] + dx;
    const y0 = o.origin[1];
    g.layer(l, Math.round((l + 1) * o.layerHeight * 1000) / 1000, o.layerHeight);
    if (!o.skipWallsOn?.includes(l)) {
      for (let k = o.walls - 1; k >= 0; k--) {
        const inset = w / 2 + k * w;
        g.type(k === 0 ? 'WALL-OUTER' : 'WALL-INNER').rect(x0 + inset, y0 + inset, x0 + sx - inset, y0 + sy - inset);
      }
    }
    const inner = o.walls * w;
    const ix0 = x0 + inner,
      iy0 = y0 + inner,
      ix1 = x0 + sx - inner,
      iy1 = y0 + sy - inner;
    const solid = l < o.skinLayers || l >= layers - o.skinLayers;
    if (solid) {
      if (o.skipSkinOn?.includes(l)) continue;
      g.type('SKIN');
      if (l % 2 === 0) {
        for (let y = iy0 + w / 2, k = 0; y < iy1; y += w, k++) {
          g.travel(k % 2 === 0 ? ix0 : ix1, y).line(k % 2 === 0 ? ix1 : ix0, y);
        }
      } else {
        for (let x = ix0 + w / 2, k = 0; x < ix1; x += w, k++) {
          g.travel(x, k % 2 === 0 ? iy0 : iy1).line(x, k % 2 === 0 ? iy1 : iy0);
        }
      }
    } else {
      g.type('FILL');
      for (let y = iy0 + o.infillSpacing / 2; y < iy1; y += o.infillSpacing) g.travel(ix0, y).line(ix1, y);
      for (let x = ix0 + o.infillSpacing / 2; x < ix1; x += o.infillSpacing) g.travel(x, iy0).line(x, iy1);
    }
  }
}
