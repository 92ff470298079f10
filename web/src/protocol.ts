/** Messages between the page and its slicing worker: plain data, big arrays transferred. */
import type { SliceOptions } from '../../src/settings/schema.js';
import type { PreviewArrays } from '../../src/preview/plan-arrays.js';
import type { Placement } from '../../src/mesh/placement.js';
import type { CustomInfillSpec } from '../../src/pipeline/custom-infill.js';

/** One object of the plate: its file, and where it stands (null: as `strata slice` places it). */
export interface SliceItem {
  fileName: string;
  bytes: ArrayBuffer;
  placement: Placement | null;
}

export type ToWorker =
  | { type: 'load'; id: number; fileName: string; bytes: ArrayBuffer }
  | { type: 'slice'; id: number; items: SliceItem[]; options: SliceOptions; custom: CustomInfillSpec | null }
  | { type: 'infiller'; id: number; spec: CustomInfillSpec };

export interface LoadedModel {
  /** Object names in the file (a 3MF may hold several). */
  objects: string[];
  triangles: number;
  /** Welded vertices (xyz, mm, the file's coordinates): bounds and placement. */
  vertices: Float32Array;
  /** Triangle corners (xyz, mm) and their face normals, for drawing. */
  positions: Float32Array;
  normals: Float32Array;
  openEdges: number;
  nonManifoldEdges: number;
  warnings: string[];
}

export interface SliceSummary {
  layers: number;
  printTimeSeconds: number;
  filamentMm: number;
  filamentGrams: number;
  triangles: number;
  sliceSeconds: number;
  threads: number;
}

export interface InfillerDescription {
  kind: 'shader' | 'image';
  params: { name: string; type: string; default: number | boolean; tooltip: string }[];
  warnings: string[];
}

export type FromWorker =
  | { type: 'loaded'; id: number; model: LoadedModel }
  | { type: 'progress'; id: number; stage: string; fraction: number }
  | { type: 'sliced'; id: number; gcode: ArrayBuffer; stats: SliceSummary; warnings: string[]; preview: PreviewArrays }
  | { type: 'infiller'; id: number; info: InfillerDescription }
  | { type: 'error'; id: number; message: string };
