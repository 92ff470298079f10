/**
 * What the page's module worker does (worker.ts is its entry): reads models, slices (the library's worker
 * pool runs inside it when more threads are asked for), and builds the preview arrays, so the page thread
 * only draws. The page cancels a slice by ending the worker.
 */
import { Slicer, StrataError, loadCustomInfill, loadModelBytes, prepareMesh } from '../../src/browser.js';
import { mergeObjects, type ModelInput } from '../../src/mesh/place.js';
import { placeObjects } from '../../src/mesh/placement.js';
import { planToArrays, transferList } from '../../src/preview/plan-arrays.js';
import type { FromWorker, LoadedModel, SliceItem, ToWorker } from './protocol.js';

const scope = globalThis as unknown as {
  postMessage(m: FromWorker, transfer?: Transferable[]): void;
  onmessage: ((e: MessageEvent<ToWorker>) => void) | null;
};

function post(m: FromWorker, transfer: Transferable[] = []): void {
  scope.postMessage(m, transfer);
}

/** The error in words for the page: a StrataError's own message, anything else named as internal. */
function describe(e: unknown): string {
  if (e instanceof StrataError) return e.message;
  return `internal error: ${e instanceof Error ? e.message : String(e)}`;
}

function load(fileName: string, bytes: ArrayBuffer): LoadedModel {
  const objects = loadModelBytes(new Uint8Array(bytes), fileName);
  if (objects.length === 0) throw new StrataError('EMPTY_MODEL', `${fileName} holds no mesh`);
  const { mesh, report } = prepareMesh(mergeObjects(objects));
  if (mesh.indices.length === 0) throw new StrataError('EMPTY_MODEL', `${fileName} has no printable triangles`);
  const tris = mesh.indices.length / 3;
  const positions = new Float32Array(tris * 9);
  const normals = new Float32Array(tris * 9);
  const p = mesh.positions, ix = mesh.indices;
  for (let t = 0; t < tris; t++) {
    const a = ix[t * 3] * 3, b = ix[t * 3 + 1] * 3, c = ix[t * 3 + 2] * 3;
    const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
    const vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
    let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const len = Math.hypot(nx, ny, nz) || 1;
    nx /= len;
    ny /= len;
    nz /= len;
    for (let k = 0; k < 3; k++) {
      const src = ix[t * 3 + k] * 3, o = t * 9 + k * 3;
      positions[o] = p[src];
      positions[o + 1] = p[src + 1];
      positions[o + 2] = p[src + 2];
      normals[o] = nx;
      normals[o + 1] = ny;
      normals[o + 2] = nz;
    }
  }
  return {
    objects: objects.map((o) => o.name),
    triangles: tris,
    vertices: mesh.positions,
    positions,
    normals,
    openEdges: report.openEdges,
    nonManifoldEdges: report.nonManifoldEdges,
    warnings: report.warnings,
  };
}

/**
 * The slicer's input, one model per file (its objects kept together): a file at the place
 * `strata slice` would put it goes in as read (so the G-code is the CLI's, byte for byte); a placed
 * one is moved to its placement first.
 */
function sliceInput(items: readonly SliceItem[]): { input: ModelInput[]; placed: boolean } {
  let placed = false;
  const input = items.map((it) => {
    const objects = loadModelBytes(new Uint8Array(it.bytes), it.fileName);
    if (!it.placement) return { name: it.fileName, objects };
    placed = true;
    return { name: it.fileName, objects: placeObjects(objects, it.placement) };
  });
  return { input, placed };
}

async function handle(msg: ToWorker): Promise<void> {
  switch (msg.type) {
    case 'load': {
      const model = load(msg.fileName, msg.bytes);
      post({ type: 'loaded', id: msg.id, model }, [model.vertices.buffer, model.positions.buffer, model.normals.buffer] as ArrayBuffer[]);
      return;
    }
    case 'infiller': {
      // the shader compiler loads here, the first time a custom infill is chosen
      const compiler = await loadCustomInfill();
      const shader = await import('../../src/shader/index.js');
      const info = shader.describeInfiller(shader.loadInfiller(msg.spec));
      compiler.customGenerator(msg.spec, new Slicer().config);
      post({ type: 'infiller', id: msg.id, info: { kind: info.kind, params: info.params.map((p) => ({ ...p })), warnings: info.warnings } });
      return;
    }
    case 'slice': {
      const { input, placed } = sliceInput(msg.items);
      // a placed object is already where it goes: the slicer only drops it onto the bed
      const slicer = new Slicer(placed ? { ...msg.options, center: false } : msg.options);
      if (msg.custom) slicer.setCustomInfill(msg.custom);
      const chunks: string[] = [];
      const { plan, stats, warnings } = await slicer.slicePlan(input, {
        onProgress: (p) => post({ type: 'progress', id: msg.id, stage: p.stage, fraction: p.fraction }),
      }, (c) => chunks.push(c));
      const gcode = new TextEncoder().encode(chunks.join('')).buffer as ArrayBuffer;
      const preview = planToArrays(plan);
      const { bounds: _bounds, ...summary } = stats;
      post({ type: 'sliced', id: msg.id, gcode, stats: summary, warnings, preview }, [gcode, ...transferList(preview)]);
      return;
    }
  }
}

/** Handle one message from the page; errors go back to it in words. */
export function onMessage(msg: ToWorker): void {
  handle(msg).catch((err: unknown) => post({ type: 'error', id: msg.id, message: describe(err) }));
}
