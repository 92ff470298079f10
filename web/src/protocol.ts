/** Messages between the page and its slicing worker: plain data, big arrays transferred. */
import type { SettingKey, SliceOptions } from '../../src/settings/schema.js';
import type { VolumeKind } from '../../src/mesh/types.js';
import type { PreviewArrays } from '../../src/preview/plan-arrays.js';
import type { Placement } from '../../src/mesh/placement.js';
import type { CustomInfillSpec } from '../../src/infill/patterns/custom.js';

/** Triangles as the slicer takes them (in the object's coordinates for a volume). */
export interface MeshArrays {
  positions: Float32Array;
  indices: Uint32Array;
}

/** A volume of an object, as the library's object description takes it. */
export interface SliceVolume {
  type: VolumeKind;
  name: string;
  mesh: MeshArrays;
  settings?: Partial<Record<SettingKey, unknown>>;
}

/**
 * One object of the plate: its file (or, for an object from a project, its mesh), where it stands
 * (null: as `strata slice` places it), and its own settings, volumes and layer ranges.
 */
export interface SliceItem {
  /** The object's name (the file's without its extension). */
  name: string;
  fileName: string;
  bytes: ArrayBuffer | null;
  mesh: MeshArrays | null;
  placement: Placement | null;
  settings: Partial<Record<SettingKey, unknown>>;
  volumes: SliceVolume[];
  layerRanges: Array<{ fromZ: number; toZ: number; settings: Partial<Record<SettingKey, unknown>> }>;
  /** Variable layer height from a project (z0, h0, z1, h1, … mm). */
  layerHeightProfile?: number[];
}

export type ToWorker =
  /** Read a model file; `mesh`: as one mesh (a volume's), a project's data not looked at. */
  | { type: 'load'; id: number; fileName: string; bytes: ArrayBuffer; mesh?: boolean }
  | { type: 'slice'; id: number; items: SliceItem[]; options: SliceOptions; custom: CustomInfillSpec | null }
  /** Write the plate as a project 3MF: the objects as the slicer places them, and the print's settings. */
  | { type: 'save'; id: number; items: SliceItem[]; options: SliceOptions; printSettings: Record<string, unknown> }
  | { type: 'infiller'; id: number; spec: CustomInfillSpec };

export interface LoadedModel {
  /** Object names in the file (a 3MF may hold several). */
  objects: string[];
  triangles: number;
  /** Welded vertices (xyz, mm, the file's coordinates): bounds and placement. */
  vertices: Float32Array;
  /** Three of `vertices` per triangle. */
  indices: Uint32Array;
  /** Triangle corners (xyz, mm) and their face normals, for drawing. */
  positions: Float32Array;
  normals: Float32Array;
  openEdges: number;
  nonManifoldEdges: number;
  warnings: string[];
}

/** One object of a project file, in the file's (bed) coordinates, its settings in Strata's keys. */
export interface ProjectObject {
  name: string;
  model: LoadedModel;
  settings: Partial<Record<SettingKey, unknown>>;
  volumes: Array<{ kind: VolumeKind; name: string; mesh: MeshArrays; settings: Partial<Record<SettingKey, unknown>> }>;
  layerRanges: Array<{ fromZ: number; toZ: number; settings: Partial<Record<SettingKey, unknown>> }>;
  /** PrusaSlicer's or OrcaSlicer's variable layer height profile of the object (z0, h0, z1, h1, … mm). */
  layerHeightProfile?: number[];
}

/** A 3MF with a slicer's project data: its objects one by one, and the print's settings it holds. */
export interface LoadedProject {
  objects: ProjectObject[];
  /** In Strata's keys (with `printer` and `filament` when Strata wrote them); null when it holds none. */
  printSettings: Record<string, unknown> | null;
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
  /** A model (`project` null), or a project's objects (`model` null). */
  | { type: 'loaded'; id: number; model: LoadedModel | null; project: LoadedProject | null }
  | { type: 'saved'; id: number; bytes: ArrayBuffer }
  | { type: 'progress'; id: number; stage: string; fraction: number }
  | { type: 'sliced'; id: number; gcode: ArrayBuffer; stats: SliceSummary; warnings: string[]; preview: PreviewArrays }
  | { type: 'infiller'; id: number; info: InfillerDescription }
  | { type: 'error'; id: number; message: string };
