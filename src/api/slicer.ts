/**
 * The library API: `new Slicer(options)`, chainable `setX`/`getX` for every setting, and
 * `await slicer.slice(input)` → `{ gcode, stats, warnings }`, or `sliceToSink` to stream the G-code.
 */
import { isNode, nodeBuiltin } from '../runtime.js';
import { positionBounds } from '../mesh/index.js';
import { checkTemplatesForFlavor } from '../gcode/custom-gcode.js';
import { imageDecodeBytes } from '../shader/image.js';
import { StrataError } from '../errors.js';
import { MiB, prepareModel, prepareModelSteps, type PreparedModel } from './prepare-model.js';
import type { SettingsSource } from '../mesh/types.js';
import { settingsFromSource } from '../profiles/object-settings.js';
import { Pacer, paced, wait, type Steps } from '../pipeline/pacer.js';
import { runPipelineSteps, type Progress, type RunResult, type ThinLoss, type VaseFlat } from '../pipeline/run.js';
import { VASE_SPECK_MM2 } from '../regions/layer-regions.js';
import { plateOf } from './plate.js';
import { ConfigTable } from '../settings/scoped.js';
import type { PrintPlan } from '../plan/types.js';
import type { CustomInfillSpec } from '../infill/patterns/custom.js';
import { isTransferable, loadCustomInfill, loadedCustomInfill } from '../infill/registry.js';
import { releaseWorkers, startWorkers } from '../workers/pool.js';
import { SCHEMA, SETTING_KEYS, type SettingKey, type Settings, type SliceOptions } from '../settings/schema.js';
import { checkKey, resolveConfig, validateValue, type Config } from '../settings/resolve.js';

export interface SliceStats {
  layers: number;
  printTimeSeconds: number;
  filamentMm: number;
  filamentGrams: number;
  triangles: number;
  /** Wall-clock seconds the slice took. */
  sliceSeconds: number;
  /** Extents of the printed part, mm. */
  bounds: { minX: number; minY: number; minZ: number; maxX: number; maxY: number; maxZ: number };
  threads: number;
  /** Layers with parts too thin for any wall line (thinner than minFeatureSize), which are left out. */
  thinLost: ThinLoss[];
}

export interface SliceResult {
  gcode: string;
  stats: SliceStats;
  warnings: string[];
}

export { prepareModel, type PreparedModel } from './prepare-model.js';

/** An object's own settings, volumes and layer ranges (`Slicer.addObject`). */
export interface ObjectOptions {
  name?: string;
  settings?: Partial<Settings>;
  volumes?: Array<{
    type: 'part' | 'modifier' | 'negative' | 'support-blocker' | 'support-enforcer';
    mesh: unknown;
    name?: string;
    settings?: Partial<Settings>;
  }>;
  layerRanges?: Array<{ fromZ: number; toZ: number; settings: Partial<Settings> }>;
  /** Variable layer height: z0, h0, z1, h1, … mm from the object's bottom (PrusaSlicer's layer_height_profile). */
  layerHeightProfile?: number[];
}

/** How `Slicer.saveProject` writes the project. */
export interface SaveProjectOptions {
  /**
   * The print settings of Strata's copy in the project (Strata's keys, with `printer` and `filament` preset
   * names), instead of every setting as resolved.
   */
  printSettings?: Readonly<Record<string, unknown>>;
}

export interface SliceCallOptions {
  onProgress?: (p: Progress) => void;
  signal?: AbortSignal;
}

async function coreCount(): Promise<number> {
  const nav = (globalThis as { navigator?: { hardwareConcurrency?: number } }).navigator;
  if (isNode) {
    const os = await nodeBuiltin<typeof import('node:os')>('os');
    return os.availableParallelism?.() ?? os.cpus().length;
  }
  return nav?.hardwareConcurrency ?? 1;
}

/** The placement settings of objects saved as placed (a project's objects are not turned or scaled again). */
const PLACED = {
  upAxis: 'z',
  rotateX: 0,
  rotateY: 0,
  rotateZ: 0,
  scale: 1,
  scaleX: null,
  scaleY: null,
  scaleZ: null,
} as const;

/** Settings of how a slice runs, which a project file does not choose for the machine it is opened on. */
const RUNTIME_KEYS: ReadonlySet<string> = new Set(['threads', 'inflateBudget']);

/**
 * Automatic thread count: one per core with more than two cores, else one. With a worker, the calling
 * thread mostly plans while the worker computes, and V8's background compiler already keeps a second
 * core busy for one thread: on two cores, two threads measured no faster than one, with ~45 MiB more.
 */
async function autoThreads(): Promise<number> {
  const cores = await coreCount();
  return cores > 2 ? cores : 1;
}

/** Below this (thousands of triangles + layers / 50) a slice runs on one thread when threads = 0 (auto). */
const SMALL_JOB = 4;

/** With threads = 0 (auto), workers start before the model is read only for an input this big. */
const EARLY_START_BYTES = 256 * 1024;

/** Size of a model given as bytes or text (0 for anything else). */
function inputBytes(input: unknown): number {
  if (typeof input === 'string') return input.length;
  if (input instanceof ArrayBuffer || ArrayBuffer.isView(input)) return input.byteLength;
  return 0;
}

type Accessors = { [K in SettingKey as `set${Capitalize<K>}`]: (value: Settings[K]) => Slicer } & {
  [K in SettingKey as `get${Capitalize<K>}`]: () => Settings[K];
};

export interface Slicer extends Accessors {}

export class Slicer {
  #options: SliceOptions;
  #config: Config;
  #custom: CustomInfillSpec | undefined;
  #objects: Array<ObjectOptions & { mesh: unknown }> = [];

  /**
   * @param options settings (any subset), `printer` and `filament` preset names, and optionally
   *   `customInfill`: an IceSL-style infiller `{ name, shader?: glslText, image?: pngBytes, params? }`.
   */
  constructor(options: SliceOptions & { customInfill?: CustomInfillSpec } = {}) {
    const { customInfill, ...settings } = options;
    this.#config = resolveConfig(settings);
    this.#options = { ...settings };
    if (customInfill) this.setCustomInfill(customInfill);
  }

  /**
   * Use a custom infiller (IceSL format: a GLSL `cellular()` shader or a cells.png image) instead
   * of the built-in pattern; null goes back to `infillPattern`. Compiled now, so errors show here,
   * when the shader compiler is loaded (always from the Node entry; in the browser build after
   * `await loadCustomInfill()`); otherwise the slice loads it and reports the error.
   */
  setCustomInfill(spec: CustomInfillSpec | null): this {
    if (spec) {
      checkImageBudget(spec, this.#config);
      loadedCustomInfill()?.customGenerator(spec, this.#config);
      this.#custom = { ...spec, params: spec.params ? { ...spec.params } : undefined };
    } else {
      this.#custom = undefined;
    }
    return this;
  }

  getCustomInfill(): CustomInfillSpec | undefined {
    return this.#custom;
  }

  /** The resolved, frozen configuration (presets and defaults applied). */
  get config(): Config {
    return this.#config;
  }

  /** Set one setting by key (validated now); chainable. */
  set<K extends SettingKey>(key: K, value: Settings[K]): this {
    checkKey(key);
    validateValue(key, value);
    return this.#apply({ ...this.#options, [key]: value });
  }

  /** Resolve new options (throws, leaving the slicer unchanged, if they are invalid) and keep them. */
  #apply(next: SliceOptions): this {
    this.#config = resolveConfig(next);
    this.#options = next;
    return this;
  }

  /** The resolved value of one setting. */
  get<K extends SettingKey>(key: K): Settings[K] {
    checkKey(key);
    return this.#config.settings[key];
  }

  /** Choose a printer preset (validated now); chainable. */
  setPrinter(name: string): this {
    return this.#apply({ ...this.#options, printer: name });
  }

  /** Choose a filament preset (validated now); chainable. */
  setFilament(name: string): this {
    return this.#apply({ ...this.#options, filament: name });
  }

  /**
   * Add an object to the plate the next `slice()` without a model slices: a mesh (any model input) with
   * settings of its own (object- and region-scoped ones), volumes (`{ type: 'modifier' | 'negative' |
   * 'support-blocker' | 'support-enforcer' | 'part', mesh, settings? }`, in the mesh's coordinates) and
   * layer ranges (`{ fromZ, toZ, settings }`, mm from the bed). Settings are checked now, each misuse (a
   * key that does not exist, a value out of range, a setting that cannot vary there) one clear error.
   */
  addObject(mesh: unknown, object: ObjectOptions = {}): this {
    const name = object.name ?? `object ${this.#objects.length + 1}`;
    const table = new ConfigTable(this.#options, this.#config);
    const own = { settings: object.settings, use: 'object' as const, where: `object "${name}"` };
    table.resolve([own]);
    for (const v of object.volumes ?? []) {
      if (v.settings)
        table.resolve([
          own,
          { settings: v.settings, use: 'modifier', where: `${v.type} "${v.name ?? ''}" of "${name}"` },
        ]);
    }
    for (const r of object.layerRanges ?? [])
      table.resolve([
        own,
        { settings: r.settings, use: 'layer range', where: `object "${name}" layers ${r.fromZ}–${r.toZ} mm` },
      ]);
    this.#objects.push({ ...object, name, mesh, settings: object.settings ?? {} });
    return this;
  }

  /**
   * The options a project's print settings make with this slicer's: the project's under the caller's
   * own, and the project's objects kept where it put them (unless `center` was set).
   */
  #projectConfig(project: SettingsSource): { config: Config; options: SliceOptions; warnings: string[] } {
    const mapped = settingsFromSource(project);
    const warnings: string[] = [];
    const own: Record<string, unknown> = Object.fromEntries(
      Object.entries(mapped.settings).filter(([k]) => !RUNTIME_KEYS.has(k)),
    );
    // Strata's own projects name their presets too
    for (const k of ['printer', 'filament'] as const)
      if (project.format === 'strata' && typeof project.values[k] === 'string') own[k] = project.values[k];
    const unknown = mapped.ignored.filter(
      (k) => !(project.format === 'strata' && (k === 'printer' || k === 'filament')),
    );
    if (unknown.length)
      warnings.push(
        `${unknown.length} of the project's print settings have no Strata equivalent and are ignored${unknown.length <= 8 ? ` (${unknown.join(', ')})` : ''}`,
      );
    for (const r of mapped.rejected) warnings.push(`the project's ${r.key} = ${r.value} is not taken: ${r.reason}`);
    const options: SliceOptions = { ...own, ...('center' in this.#options ? {} : { center: false }), ...this.#options };
    try {
      return { config: resolveConfig(options), options, warnings };
    } catch (e) {
      if (e instanceof StrataError) throw new StrataError(e.code, `the project's print settings: ${e.message}`);
      throw e;
    }
  }

  /**
   * The plate as a project 3MF (PrusaSlicer's layout, which PrusaSlicer opens, with Strata's own copy of every
   * setting): the objects placed as a slice would place them, their volumes, settings and layer ranges, and
   * this slicer's options as the print settings. `input` as for `slice` (default: the objects added).
   * `options.printSettings` chooses the print settings of Strata's copy (Strata's keys, `printer` and
   * `filament`), e.g. only those a user changed, so that the project keeps following its presets; by default
   * it holds every setting as resolved. Either way the objects are saved turned and scaled already, so the
   * placement settings (`upAxis`, `rotateX`…, `scale`…) are saved as doing nothing more; PrusaSlicer's copy
   * has every setting as resolved.
   */
  async saveProject(input?: unknown, options: SaveProjectOptions = {}): Promise<Uint8Array> {
    const source = input === undefined && this.#objects.length ? this.#objects : input;
    const model = prepareModel(source, this.#config);
    // every setting as resolved (presets included), so that the project slices the same anywhere
    const cfg = this.#config;
    const print: Record<string, unknown> = { printer: cfg.printerId, filament: cfg.filamentId };
    for (const k of SETTING_KEYS) if (!RUNTIME_KEYS.has(k)) print[k] = cfg.settings[k];
    // the objects are saved as placed: turned, scaled and stood up already
    Object.assign(print, PLACED);
    const own = options.printSettings ? { ...options.printSettings, ...PLACED } : print;
    // loaded when first used: a slice that saves no project does not load the writer
    const [{ writeProject3mf }, { toSlic3rKeys }] = await Promise.all([
      import('../profiles/threemf-write.js'),
      import('../profiles/to-slic3r.js'),
    ]);
    return writeProject3mf(model.objects, {
      printSettings: own,
      slic3rPrintSettings: toSlic3rKeys(print, this.#config.layerHeight),
    });
  }

  /** Take every object added with `addObject` off the plate. */
  clearObjects(): this {
    this.#objects = [];
    return this;
  }

  /**
   * Slice at once, on this thread (no workers, nothing awaited), and return the whole G-code: the same
   * G-code as `slice()` with the same settings. It blocks the thread for the whole slice, so in a page run
   * it in a worker. Cancellation: a signal already aborted stops it. A custom infill needs its compiler
   * loaded first (always in Node; in a browser `await loadCustomInfill()`).
   */
  sliceSync(input?: unknown, opts: Omit<SliceCallOptions, 'signal'> & { signal?: AbortSignal } = {}): SliceResult {
    const chunks: string[] = [];
    const steps = this.#sliceSteps(
      { input: input === undefined && this.#objects.length ? this.#objects : input },
      opts,
      (c) => chunks.push(c),
      true,
    );
    const { stats, warnings } = new Pacer(opts.signal).driveSync(steps);
    return { gcode: chunks.join(''), stats, warnings };
  }

  /** Slice and return the whole G-code as a string. */
  // slice and sliceToSink hand `input` on without awaiting, so that only the slice holds it, and lets it go
  // once the model is read (a file's bytes are not kept while the G-code is made)
  slice(input?: unknown, opts: SliceCallOptions = {}): Promise<SliceResult> {
    const chunks: string[] = [];
    return this.sliceToSink(input, (c) => chunks.push(c), opts).then(({ stats, warnings }) => ({
      gcode: chunks.join(''),
      stats,
      warnings,
    }));
  }

  /** Slice and stream the G-code to `sink` in chunks. */
  sliceToSink(
    input: unknown,
    sink: (chunk: string) => void,
    opts: SliceCallOptions = {},
  ): Promise<{ stats: SliceStats; warnings: string[] }> {
    return this.slicePlan(input, opts, sink).then(({ stats, warnings }) => ({ stats, warnings }));
  }

  /** Slice and return the structured toolpath plan (layers of typed paths) as well as the stats. */
  slicePlan(
    input?: unknown,
    opts: SliceCallOptions = {},
    sink: (chunk: string) => void = () => {},
  ): Promise<{ plan: PrintPlan; stats: SliceStats; warnings: string[] }> {
    // the input travels in a box the slice empties once the model is read (an async function's own
    // parameters stay alive until it returns)
    const pacer = new Pacer(opts.signal);
    return pacer.drive(
      this.#sliceSteps(
        { input: input === undefined && this.#objects.length ? this.#objects : input },
        opts,
        sink,
        false,
      ),
    );
  }

  /** The slice as paced steps; `sync`: on this thread only (one thread, nothing to wait for). */
  *#sliceSteps(
    given: { input: unknown },
    opts: SliceCallOptions,
    sink: (chunk: string) => void,
    sync: boolean,
  ): Steps<{ plan: PrintPlan; stats: SliceStats; warnings: string[] }> {
    const t0 = performance.now();
    const cfg = this.#config;
    // refuse what would fail only after slicing: templates the flavour cannot run, an image over budget
    checkTemplatesForFlavor(cfg);
    if (this.#custom) checkImageBudget(this.#custom, cfg);
    // the shader compiler loads on first use (the pipeline compiles the infiller and reports its errors)
    if (this.#custom && !loadedCustomInfill()) {
      if (sync)
        throw new StrataError(
          'BAD_SETTING',
          'a custom infill in a synchronous slice needs the shader compiler loaded first: await loadCustomInfill(), or use slice()',
        );
      yield* wait(loadCustomInfill());
    }
    // Workers start loading now, while the model is read and placed, if they will be needed (a custom
    // density given as a JS function cannot travel to a worker).
    const auto = sync ? 1 : yield* wait(autoThreads());
    const wanted = sync ? 1 : cfg.threads > 0 ? cfg.threads : inputBytes(given.input) >= EARLY_START_BYTES ? auto : 1;
    const started =
      wanted > 1 && (!this.#custom || isTransferable(this.#custom)) ? startWorkers(wanted - 1) : undefined;
    let run: RunResult;
    let model: PreparedModel;
    let threads: number;
    try {
      // paced like the slice itself, so an abort acts while a big model is still being read
      model = yield* paced(prepareModelSteps(given.input, cfg, (project) => this.#projectConfig(project)));
      // the meshes are made: the caller's bytes need not stay alive here while the slice runs
      given.input = undefined;
      const b = positionBounds(model.mesh.positions);
      const layersEstimate = b.max[2] / cfg.layerHeight;
      const small = model.mesh.indices.length / 3 / 1000 + layersEstimate / 50 < SMALL_JOB;
      threads = sync ? 1 : cfg.threads > 0 ? cfg.threads : small ? 1 : auto;
      const warnings = [...model.warnings];
      const plate = plateOf(
        model.objects,
        model.project?.options ?? this.#options,
        model.config,
        warnings,
        model.project?.settings,
      );
      model = { ...model, warnings };
      run = yield* runPipelineSteps(
        plate,
        // a custom infill's layers in workers, so that an abort never waits for a shader's layer
        {
          threads,
          sink,
          onProgress: opts.onProgress,
          signal: opts.signal,
          custom: this.#custom,
          started,
          customInWorkers: !sync,
        },
        new Pacer(opts.signal),
      );
    } catch (e) {
      if (started) yield* wait(releaseWorkers(started));
      throw e;
    }
    const stats: SliceStats = {
      layers: run.layers,
      printTimeSeconds: run.estimate.printTimeSeconds,
      filamentMm: run.estimate.filamentMm,
      filamentGrams: run.estimate.filamentGrams,
      triangles: model.mesh.indices.length / 3,
      sliceSeconds: (performance.now() - t0) / 1000,
      bounds: run.plan.bounds,
      threads,
      thinLost: run.thinLost,
    };
    const extra = [
      thinLossWarning(run.thinLost, cfg),
      vaseFlatWarning(run.vaseFlat),
      vaseSpeckWarning(run.vaseSpecks),
      firstLayerWarning(run.firstLayerFilledMm2, cfg),
    ].filter((w): w is string => w !== null);
    return { plan: run.plan, stats, warnings: extra.length ? [...model.warnings, ...extra] : model.warnings };
  }
}

/**
 * No warning for less than this left out on any one layer and in all, mm²: the tip of a sharp corner or a
 * crease's last sliver, not a feature (a 0.06 mm fin 2 mm long is 0.12 mm² a layer).
 */
const THIN_LOSS_WARN_LAYER_MM2 = 0.1;
const THIN_LOSS_WARN_TOTAL_MM2 = 0.5;

/** One line saying what was too thin to print, where and how much, or null when it is only specks. */
export function thinLossWarning(lost: readonly ThinLoss[], cfg: Config): string | null {
  let total = 0,
    most = 0;
  for (const l of lost) {
    total += l.areaMm2;
    if (l.areaMm2 > most) most = l.areaMm2;
  }
  if (lost.length === 0 || (most < THIN_LOSS_WARN_LAYER_MM2 && total < THIN_LOSS_WARN_TOTAL_MM2)) return null;
  const first = lost[0],
    last = lost[lost.length - 1];
  const layers =
    lost.length === 1
      ? `layer ${first.layer} (Z ${first.z.toFixed(2)} mm)`
      : `${lost.length} layers between ${first.layer} and ${last.layer} (Z ${first.z.toFixed(2)}–${last.z.toFixed(2)} mm)`;
  const min = ((cfg.minFeatureSize / 100) * cfg.nozzleDiameter).toFixed(2);
  const why = cfg.wallGenerator === 'classic' ? 'thinner than a line' : `thinner than minFeatureSize (${min} mm)`;
  return `${total.toFixed(2)} mm² of the model's sections is too thin to print (${why}) and is left out, on ${layers}`;
}

/** One line saying the first layer was repaired under an open or pointed bottom, or null when it was not. */
export function firstLayerWarning(filledMm2: number, cfg: Config): string | null {
  if (!(filledMm2 > 0)) return null;
  return `the model's bottom is open or too thin to print at the first layer (Z ${cfg.firstLayerHeight} mm): the first layer takes the section of the layer above as well (${filledMm2.toFixed(1)} mm² added), so the print starts on the bed`;
}

/** One line naming the spiral vase layers printed flat (not one wall loop), or null when every one turned. */
export function vaseFlatWarning(flat: readonly VaseFlat[]): string | null {
  if (flat.length === 0) return null;
  const first = flat[0],
    last = flat[flat.length - 1];
  const where =
    flat.length === 1
      ? `layer ${first.layer} (Z ${first.z.toFixed(2)} mm)`
      : `${flat.length} layers between ${first.layer} and ${last.layer} (Z ${first.z.toFixed(2)}–${last.z.toFixed(2)} mm)`;
  return `spiral vase: ${where} ${flat.length === 1 ? 'is' : 'are'} not one single wall loop (several islands, or a part too thin for a loop) and ${flat.length === 1 ? 'prints' : 'print'} flat, with a layer change; the spiral starts again above`;
}

/** One line naming the spiral vase layers whose specks beside the main island were left out, or null. */
export function vaseSpeckWarning(specks: readonly ThinLoss[]): string | null {
  if (specks.length === 0) return null;
  let total = 0;
  for (const s of specks) total += s.areaMm2;
  const first = specks[0],
    last = specks[specks.length - 1];
  const where =
    specks.length === 1
      ? `layer ${first.layer} (Z ${first.z.toFixed(2)} mm)`
      : `${specks.length} layers between ${first.layer} and ${last.layer} (Z ${first.z.toFixed(2)}–${last.z.toFixed(2)} mm)`;
  return `spiral vase: ${total.toFixed(2)} mm² of islands smaller than ${VASE_SPECK_MM2} mm² beside the main one ${specks.length === 1 ? 'is' : 'are'} left out on ${where}`;
}

/** An infill image that would take more than inflateBudget to decode is refused before it is decoded. */
function checkImageBudget(spec: CustomInfillSpec, cfg: Config): void {
  if (spec.image === undefined || spec.shader !== undefined) return;
  const name = `${spec.name}/cells.png`;
  const cost = imageDecodeBytes(spec.image, name);
  if (cost > cfg.inflateBudget * MiB) {
    throw new StrataError(
      'LIMIT_EXCEEDED',
      `${name}: decoding the image takes ${Math.ceil(cost / MiB)} MiB, more than inflateBudget (${cfg.inflateBudget} MiB); raise inflateBudget or use a smaller image`,
    );
  }
}

for (const key of SETTING_KEYS) {
  const cap = key[0].toUpperCase() + key.slice(1);
  Object.defineProperty(Slicer.prototype, `set${cap}`, {
    value: function (this: Slicer, v: unknown) {
      return this.set(key, v as never);
    },
    writable: false,
    enumerable: false,
  });
  Object.defineProperty(Slicer.prototype, `get${cap}`, {
    value: function (this: Slicer) {
      return this.get(key);
    },
    writable: false,
    enumerable: false,
  });
}

/** Every setting's definition, for UIs and documentation. */
export const settingsSchema = SCHEMA;
