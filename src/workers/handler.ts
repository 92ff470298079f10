/** The worker side, independent of the host: keeps the mesh and config, runs range jobs. */
import { StrataError } from '../errors.js';
import type { PreparedMesh } from '../slice/index.js';
import { computeRange, type RegionsHeld } from './layer-work.js';
import { loadCustomInfill } from '../infill/registry.js';
import type { InfillPattern } from '../infill/types.js';
import type { PrintSetup } from '../regions/objects.js';
import type { FromWorker, ToWorker } from './protocol.js';

interface State {
  meshes: PreparedMesh[];
  setup: PrintSetup;
  /** The slice's custom infill, compiled on this thread. */
  custom?: InfillPattern;
  /** Regions kept for this worker's later 'held' jobs. */
  held: RegionsHeld;
}

/**
 * `clock` (ms) times each job for the pool's scheduling: the thread's CPU time where the host can
 * tell, so that a loaded machine does not look like a big job.
 */
export function makeHandler(
  post: (msg: FromWorker) => void,
  clock: () => number = () => performance.now(),
): (msg: ToWorker) => void {
  let state: Promise<State> = Promise.reject(new Error('worker used before init'));
  state.catch(() => {});
  return (msg) => {
    if (msg.type === 'init') {
      const { meshes, setup, custom } = msg;
      // the shader compiler loads only when a custom infill needs it
      state = custom
        ? loadCustomInfill().then((m) => ({
            meshes,
            setup,
            custom: m.customPattern(custom, setup.configs[0]),
            held: new Map(),
          }))
        : Promise.resolve({ meshes, setup, held: new Map() });
      state.catch(() => {});
      return;
    }
    state
      .then((s) => {
        const t0 = clock();
        const result = computeRange(s.meshes, s.setup, msg.job, s.custom, s.held);
        post({ type: 'result', id: msg.id, result, ms: clock() - t0 });
      })
      .catch((e: unknown) => {
        const code = e instanceof StrataError ? e.code : 'INTERNAL';
        post({ type: 'error', id: msg.id, code, message: e instanceof Error ? e.message : String(e) });
      });
  };
}
