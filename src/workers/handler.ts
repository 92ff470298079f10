/** The worker side, independent of the host: keeps the mesh and config, runs range jobs. */
import { StrataError } from '../errors.js';
import { loadCustomInfill } from '../infill/registry.js';
import { computeRange, type LayerWork } from './layer-work.js';
import type { FromWorker, ToWorker } from './protocol.js';

/**
 * `clock` (ms) times each job for the pool's scheduling: the thread's CPU time where the host can
 * tell, so that a loaded machine does not look like a big job.
 */
export function makeHandler(
  post: (msg: FromWorker) => void,
  clock: () => number = () => performance.now(),
): (msg: ToWorker) => void {
  let state: Promise<LayerWork> = Promise.reject(new Error('worker used before init'));
  state.catch(() => {});
  return (msg) => {
    if (msg.type === 'init') {
      const { meshes, setup, custom } = msg;
      const work: LayerWork = { meshes: () => meshes, setup, held: new Map() };
      // the shader compiler loads only when a custom infill needs it
      state = custom
        ? loadCustomInfill().then((m) => ({ ...work, custom: m.customPattern(custom, setup.configs[0]) }))
        : Promise.resolve(work);
      state.catch(() => {});
      return;
    }
    state
      .then((work) => {
        const t0 = clock();
        const result = computeRange(work, msg.job);
        post({ type: 'result', id: msg.id, result, ms: clock() - t0 });
      })
      .catch((e: unknown) => {
        const code = e instanceof StrataError ? e.code : 'INTERNAL';
        post({ type: 'error', id: msg.id, code, message: e instanceof Error ? e.message : String(e) });
      });
  };
}
