/** The worker side, independent of the host: keeps the mesh and config, runs range jobs. */
import { StrataError } from '../errors.js';
import type { PreparedMesh } from '../slice/index.js';
import { computeRange } from '../pipeline/layer-work.js';
import { customGenerator } from '../pipeline/custom-infill.js';
import type { CustomInfillGenerator } from '../shader/index.js';
import type { Config } from '../settings/resolve.js';
import type { FromWorker, ToWorker } from './protocol.js';

export function makeHandler(post: (msg: FromWorker) => void): (msg: ToWorker) => void {
  let mesh: PreparedMesh | null = null;
  let cfg: Config | null = null;
  let custom: CustomInfillGenerator | undefined;
  return (msg) => {
    if (msg.type === 'init') {
      mesh = msg.mesh;
      cfg = msg.cfg;
      custom = msg.custom ? customGenerator(msg.custom, msg.cfg) : undefined;
      return;
    }
    try {
      if (!mesh || !cfg) throw new Error('worker used before init');
      post({ type: 'result', id: msg.id, result: computeRange(mesh, cfg, msg.job, custom) });
    } catch (e) {
      const code = e instanceof StrataError ? e.code : 'INTERNAL';
      post({ type: 'error', id: msg.id, code, message: e instanceof Error ? e.message : String(e) });
    }
  };
}
