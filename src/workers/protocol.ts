/** Messages between the pipeline and its layer workers: plain data only. */
import type { PreparedMesh } from '../slice/index.js';
import type { RangeJob, RangeResult } from './layer-work.js';
import type { PrintSetup } from '../regions/objects.js';
import type { CustomInfillSpec } from '../infill/patterns/custom.js';

export type ToWorker =
  | { type: 'init'; meshes: PreparedMesh[]; setup: PrintSetup; custom?: CustomInfillSpec }
  | { type: 'range'; id: number; job: RangeJob };

export type FromWorker =
  /** `ms`: how long the job took. */
  | { type: 'result'; id: number; result: RangeResult; ms: number }
  | { type: 'error'; id: number; code: string; message: string };
