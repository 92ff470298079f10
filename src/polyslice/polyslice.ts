/**
 * `Polyslice`: the seeds' library's slicer API over Strata. The same constructor options (names and units:
 * `lengthUnit`, `speedUnit`, `temperatureUnit`, `angleUnit`, `timeUnit`), a getter and a chainable setter for
 * each, `printer` / `filament` as `Printer` / `Filament` objects (or names), and a synchronous
 * `slice(meshOrScene)` returning the G-code (also kept in `slicer.gcode`). The G-code is Strata's: the same,
 * byte for byte, as `strata slice` and `new Slicer(...).slice()` with the same settings.
 *
 * Where the seeds' library is wrong, this does what is right (README lists the differences): every visible
 * mesh of a group or scene is sliced, with its parents' transforms, and set down on the bed; options left out
 * take Strata's defaults and the presets' values (the seeds' library heats nothing without a filament and
 * travels at 120 mm/s on any printer); an invalid value throws a one-line StrataError naming the option
 * (the seeds' setters ignored it silently); a progress callback is called only if given.
 */
import { Slicer, type SliceResult, type SliceStats } from '../api/slicer.js';
import { StrataError } from '../errors.js';
import type { Progress } from '../pipeline/run.js';
import { FILAMENT_PRESETS, PRINTER_PRESETS } from '../settings/presets/index.js';
import type { Config } from '../settings/resolve.js';
import { SCHEMA, type SettingKey, type Settings, type SliceOptions } from '../settings/schema.js';
import { Filament } from './filament.js';
import {
  OPTIONS,
  type KeptOption,
  type MappedOption,
  type OptionName,
  type PolysliceSettings,
  type ProgressInfo,
} from './options.js';
import { Printer } from './printer.js';
import {
  ANGLE_UNITS,
  checkUnit,
  fromInternal,
  LENGTH_UNITS,
  SPEED_UNITS,
  TEMPERATURE_UNITS,
  TIME_UNITS,
  toInternal,
  type Units,
} from './units.js';

export type { ProgressInfo, PolysliceSettings } from './options.js';

/** Constructor options: any of the seeds' options, and the printer and filament (objects, names or null). */
export type PolysliceOptions = Partial<PolysliceSettings> &
  Partial<Omit<Settings, keyof PolysliceSettings>> & {
    printer?: Printer | string | null;
    filament?: Filament | string | null;
  };

/** Strata's own settings are options too (in Strata's units: mm, mm/s, °C), where the seeds' library has no option of that name. */
const isSettingKey = (name: string): name is SettingKey => Object.hasOwn(SCHEMA, name);

const UNIT_OPTIONS = {
  lengthUnit: LENGTH_UNITS,
  speedUnit: SPEED_UNITS,
  temperatureUnit: TEMPERATURE_UNITS,
  angleUnit: ANGLE_UNITS,
  timeUnit: TIME_UNITS,
} as const;
type UnitOption = keyof typeof UNIT_OPTIONS;
const ADHESION_TYPES = ['skirt', 'brim', 'raft'] as const;

type Accessors = { [K in OptionName as `get${Capitalize<K>}`]: () => PolysliceSettings[K] } & {
  [K in OptionName as `set${Capitalize<K>}`]: (value: PolysliceSettings[K]) => Polyslice;
};

/** The settings a printer object sets: its preset, and what was changed on it. */
function printerOptions(p: Printer | null): SliceOptions {
  if (!p) return {};
  if (!p.presetId)
    throw new StrataError(
      'UNKNOWN_PRESET',
      `${p.unsupportedReason}; make a Polyslice without a printer and give buildPlateWidth and buildPlateLength (${p.size.x} × ${p.size.y} mm) for a generic Marlin printer`,
    );
  const s = PRINTER_PRESETS[p.presetId]!.settings;
  const out: SliceOptions = { printer: p.presetId };
  const nozzle = p.getNozzle(0);
  const differ = <K extends keyof SliceOptions>(key: K, value: SliceOptions[K]) => {
    if (value !== undefined && value !== s[key as keyof typeof s]) out[key] = value;
  };
  differ('buildPlateWidth', p.size.x);
  differ('buildPlateLength', p.size.y);
  differ('buildVolumeHeight', p.size.z);
  differ('originAtCenter', p.centred);
  differ('heatedBed', p.heated.bed);
  if (nozzle) {
    differ('nozzleDiameter', nozzle.diameter);
    differ('filamentDiameter', nozzle.filament);
  }
  return out;
}

/** The settings a filament object sets: its preset, and what was changed on it (or differs from the preset: a 2.85 mm spool). */
function filamentOptions(f: Filament | null): SliceOptions {
  if (!f) return {};
  const s = FILAMENT_PRESETS[f.presetId]!.settings;
  const out: SliceOptions = { filament: f.presetId };
  const differ = <K extends keyof SliceOptions>(key: K, value: SliceOptions[K] | null) => {
    if (value !== null && value !== undefined && value !== s[key as keyof typeof s]) out[key] = value;
  };
  differ('nozzleTemperature', f.temperature.nozzle);
  differ('bedTemperature', f.temperature.bed);
  differ('fanSpeed', f.fan);
  differ('filamentDensity', f.density);
  differ('retractionDistance', f.retraction.distance);
  differ('retractionSpeed', f.retraction.speed);
  if (f.diameter !== 1.75) out.filamentDiameter = f.diameter;
  return out;
}

export interface Polyslice extends Accessors {}

export class Polyslice {
  /** The G-code of the last slice ('' before the first). */
  gcode = '';
  /** Line ending of the G-code (Strata writes "\n"). */
  readonly newline = '\n';
  /** What the last slice warned about (a Y-up scene, thin parts left out…). */
  warnings: string[] = [];
  /** Statistics of the last slice (layers, print time, filament), or null before the first. */
  stats: SliceStats | null = null;

  #units: Units & { timeUnit: (typeof TIME_UNITS)[number] } = {
    lengthUnit: 'millimeters',
    speedUnit: 'millimeterSecond',
    temperatureUnit: 'celsius',
    angleUnit: 'degree',
    timeUnit: 'milliseconds',
  };
  #printer: Printer | null = null;
  #filament: Filament | null = null;
  /** Strata settings set by options and setters (over the printer's and the filament's). */
  #own: SliceOptions = {};
  #kept: Partial<Record<OptionName, unknown>> = {};
  /** The adhesion kind `adhesionEnabled(true)` turns on. */
  #adhesionKind: (typeof ADHESION_TYPES)[number] = 'skirt';
  #progress: ((info: ProgressInfo) => void) | null = null;
  #slicer: Slicer;

  constructor(options: PolysliceOptions = {}) {
    if (options === null || typeof options !== 'object')
      throw new StrataError('BAD_SETTING', 'Polyslice options must be an object');
    for (const [name, def] of Object.entries(OPTIONS) as Array<[OptionName, MappedOption | KeptOption]>)
      if (def.kind === 'kept') this.#kept[name] = def.initial;
    // units first: the other values are in them
    for (const u of Object.keys(UNIT_OPTIONS) as UnitOption[])
      if (options[u] !== undefined) this.#setUnit(u, options[u]);
    this.#printer = Polyslice.#asPrinter(options.printer);
    this.#filament = Polyslice.#asFilament(options.filament);
    this.#slicer = new Slicer(this.#compose());
    const own: SliceOptions = {};
    const rest = { ...options } as Record<string, unknown>;
    if (rest.adhesionType !== undefined) this.#setAdhesionType(rest.adhesionType, own);
    if (rest.adhesionEnabled !== undefined) this.#setAdhesionEnabled(rest.adhesionEnabled, own);
    if (rest.progressCallback !== undefined)
      this.setProgressCallback(rest.progressCallback as PolysliceSettings['progressCallback']);
    // options converted through the config (brimLineCount: lines × line width) go last, over the others resolved
    const converted = (name: string) => (OPTIONS[name as OptionName] as MappedOption | undefined)?.to !== undefined;
    const entries = Object.entries(rest).sort(([a], [b]) => Number(converted(a)) - Number(converted(b)));
    let resolved = false;
    for (const [name, value] of entries) {
      if (
        value === undefined ||
        name in UNIT_OPTIONS ||
        ['printer', 'filament', 'adhesionType', 'adhesionEnabled', 'progressCallback'].includes(name)
      )
        continue;
      if (converted(name) && !resolved) {
        this.#slicer = new Slicer(this.#compose(own));
        resolved = true;
      }
      const def = OPTIONS[name as OptionName];
      if (def) this.#setOption(name as OptionName, def, value, own);
      else if (isSettingKey(name)) (own as Record<string, unknown>)[name] = value;
      else
        throw new StrataError(
          'UNKNOWN_SETTING',
          `unknown Polyslice option "${name}" (neither the seeds' library's nor a Strata setting)`,
        );
    }
    this.#apply(own);
  }

  static #asPrinter(p: Printer | string | null | undefined): Printer | null {
    if (p === undefined || p === null) return null;
    if (typeof p === 'string') return new Printer(p);
    if (p instanceof Printer) return p;
    throw new StrataError('BAD_SETTING', 'printer must be a Printer, a printer name or null');
  }

  static #asFilament(f: Filament | string | null | undefined): Filament | null {
    if (f === undefined || f === null) return null;
    if (typeof f === 'string') return new Filament(f);
    if (f instanceof Filament) return f;
    throw new StrataError('BAD_SETTING', 'filament must be a Filament, a filament name or null');
  }

  /** Strata's options: the printer's, the filament's over them, then the caller's. */
  #compose(own: SliceOptions = this.#own): SliceOptions {
    return { ...printerOptions(this.#printer), ...filamentOptions(this.#filament), ...own };
  }

  /** Take new settings (resolved at once: invalid ones throw and change nothing). */
  #apply(own: SliceOptions): void {
    this.#slicer = new Slicer(this.#compose(own));
    this.#own = own;
  }

  /** The resolved Strata configuration. */
  get config(): Config {
    return this.#slicer.config;
  }

  /** The Strata `Slicer` behind this one, for its async API (`await slicer.strata.slice(mesh)`, streaming, cancellation). */
  get strata(): Slicer {
    return this.#slicer;
  }

  #setUnit(name: UnitOption, value: unknown): void {
    this.#units = { ...this.#units, [name]: checkUnit(name, value, UNIT_OPTIONS[name]) };
  }

  #setOption(name: OptionName, def: MappedOption | KeptOption, value: unknown, own: SliceOptions): void {
    if (def.kind === 'kept') {
      const ok = def.values
        ? def.values.includes(value)
        : typeof value === typeof def.initial && (typeof value !== 'number' || Number.isFinite(value));
      if (!ok)
        throw new StrataError(
          'BAD_SETTING',
          `${name}: ${def.values ? `one of ${def.values.map((v) => JSON.stringify(v)).join(', ')}` : `a ${typeof def.initial}`} expected, got ${JSON.stringify(value)}${name === 'positioningMode' ? ` (${def.why})` : ''}`,
        );
      this.#kept[name] = typeof value === 'number' ? toInternal(value, def.quantity, this.#units) : value;
      return;
    }
    let v = value;
    if (typeof v === 'number') {
      v = toInternal(v, def.quantity, this.#units);
      if (def.to) v = def.to(v as number, this.#slicer.config);
    } else if (def.quantity !== 'plain' || def.to) {
      throw new StrataError('BAD_SETTING', `${name} must be a number, got ${JSON.stringify(value)}`);
    }
    (own as Record<string, unknown>)[def.key] = v;
  }

  /** The value of one of the seeds' options, in the caller's units (the getters call this). */
  get<K extends OptionName>(name: K): PolysliceSettings[K];
  get(name: OptionName): unknown {
    if (name in UNIT_OPTIONS) return this.#units[name as UnitOption];
    if (name === 'adhesionEnabled') return this.getAdhesionEnabled();
    if (name === 'adhesionType') return this.getAdhesionType();
    if (name === 'progressCallback') return this.#progress;
    const def = OPTIONS[name]!;
    if (def.kind === 'kept') {
      const v = this.#kept[name];
      return typeof v === 'number' ? fromInternal(v, def.quantity, this.#units) : v;
    }
    const cfg = this.#slicer.config;
    const v = def.from ? def.from(cfg) : cfg.settings[def.key];
    return typeof v === 'number' ? fromInternal(v, def.quantity, this.#units) : v;
  }

  /** Set one of the seeds' options, in the caller's units (the setters call this); an invalid value throws and changes nothing. */
  set<K extends OptionName>(name: K, value: PolysliceSettings[K]): this;
  set(name: OptionName, value: unknown): this {
    if (name in UNIT_OPTIONS) {
      this.#setUnit(name as UnitOption, value);
      return this;
    }
    if (name === 'adhesionEnabled') return this.setAdhesionEnabled(value as boolean);
    if (name === 'adhesionType') return this.setAdhesionType(value as 'skirt');
    if (name === 'progressCallback') return this.setProgressCallback(value as null);
    const def = OPTIONS[name];
    if (!def) throw new StrataError('UNKNOWN_SETTING', `unknown Polyslice option "${name}"`);
    const own = { ...this.#own };
    try {
      this.#setOption(name, def, value, own);
      this.#apply(own);
    } catch (e) {
      if (e instanceof StrataError && !e.message.startsWith(name))
        throw new StrataError(e.code, `${name}: ${e.message}`);
      throw e;
    }
    return this;
  }

  #setAdhesionType(value: unknown, own: SliceOptions): void {
    if (!(ADHESION_TYPES as readonly unknown[]).includes(value))
      throw new StrataError(
        'BAD_SETTING',
        `adhesionType must be one of ${ADHESION_TYPES.join(', ')}, got ${JSON.stringify(value)}`,
      );
    this.#adhesionKind = value as (typeof ADHESION_TYPES)[number];
    if (this.#compose(own).adhesionType !== 'none' && this.#slicer.config.adhesionType !== 'none')
      own.adhesionType = this.#adhesionKind;
  }

  #setAdhesionEnabled(value: unknown, own: SliceOptions): void {
    if (typeof value !== 'boolean')
      throw new StrataError('BAD_SETTING', `adhesionEnabled must be true or false, got ${JSON.stringify(value)}`);
    own.adhesionType = value ? this.#adhesionKind : 'none';
  }

  getAdhesionEnabled(): boolean {
    return this.#slicer.config.adhesionType !== 'none';
  }
  setAdhesionEnabled(enabled = true): this {
    const own = { ...this.#own };
    this.#setAdhesionEnabled(enabled, own);
    this.#apply(own);
    return this;
  }
  getAdhesionType(): 'skirt' | 'brim' | 'raft' {
    const t = this.#slicer.config.adhesionType;
    return t === 'none' ? this.#adhesionKind : t;
  }
  setAdhesionType(type: 'skirt' | 'brim' | 'raft' = 'skirt'): this {
    const own = { ...this.#own };
    this.#setAdhesionType(type, own);
    this.#apply(own);
    return this;
  }

  getProgressCallback(): ((info: ProgressInfo) => void) | null {
    return this.#progress;
  }
  setProgressCallback(callback: ((info: ProgressInfo) => void) | null = null): this {
    if (callback !== null && typeof callback !== 'function')
      throw new StrataError('BAD_SETTING', 'progressCallback must be a function or null');
    this.#progress = callback;
    return this;
  }

  getPrinter(): Printer | null {
    return this.#printer;
  }
  /** Use this printer (its preset and what was changed on it), over the build plate and nozzle set before; null: the default printer. */
  setPrinter(printer: Printer | string | null): this {
    const next = Polyslice.#asPrinter(printer);
    const own = { ...this.#own };
    for (const k of [
      'buildPlateWidth',
      'buildPlateLength',
      'nozzleDiameter',
      ...(this.#filament ? [] : ['filamentDiameter']),
    ])
      delete (own as Record<string, unknown>)[k];
    const before = this.#printer;
    this.#printer = next;
    try {
      this.#apply(own);
    } catch (e) {
      this.#printer = before;
      throw e;
    }
    return this;
  }

  getFilament(): Filament | null {
    return this.#filament;
  }
  /** Use this filament (its preset and what was changed on it), over the temperatures, fan and retraction set before. */
  setFilament(filament: Filament | string | null): this {
    const next = Polyslice.#asFilament(filament);
    const own = { ...this.#own };
    for (const k of [
      'nozzleTemperature',
      'bedTemperature',
      'retractionDistance',
      'retractionSpeed',
      'filamentDiameter',
      'fanSpeed',
    ])
      delete (own as Record<string, unknown>)[k];
    const before = this.#filament;
    this.#filament = next;
    try {
      this.#apply(own);
    } catch (e) {
      this.#filament = before;
      throw e;
    }
    return this;
  }

  /**
   * Slice a three.js Mesh, Group or Scene (every visible mesh, with its parents' transforms; Z up, as the
   * seeds' library takes it), a BufferGeometry, STL/OBJ/3MF bytes or raw arrays, at once; returns the G-code
   * and keeps it in `gcode`. The input is not changed.
   */
  slice(meshOrScene?: unknown): string {
    return this.#done(this.#slicer.sliceSync(meshOrScene, { onProgress: this.#onProgress() }));
  }

  /** `slice`, off the calling thread's back: with Strata's worker threads, paced, cancellable by `signal`. */
  async sliceAsync(meshOrScene?: unknown, opts: { signal?: AbortSignal } = {}): Promise<string> {
    return this.#done(await this.#slicer.slice(meshOrScene, { onProgress: this.#onProgress(), signal: opts.signal }));
  }

  #done(r: SliceResult): string {
    this.gcode = r.gcode;
    this.warnings = r.warnings;
    this.stats = r.stats;
    this.#report({
      stage: 'complete',
      percent: 100,
      currentLayer: null,
      totalLayers: r.stats.layers,
      message: 'G-code generation complete',
    });
    return r.gcode;
  }

  #report(info: ProgressInfo): void {
    try {
      this.#progress?.(info);
    } catch {
      // as in the seeds' library, a failing callback does not stop the slice
    }
  }

  #onProgress(): ((p: Progress) => void) | undefined {
    if (!this.#progress) return undefined;
    this.#report({ stage: 'initializing', percent: 0, currentLayer: null, totalLayers: null, message: 'Starting...' });
    return (p) =>
      this.#report({
        stage: p.stage === 'writing' ? 'post-print' : 'slicing',
        percent: Math.min(99, Math.floor(p.fraction * 100)),
        currentLayer: null,
        totalLayers: null,
        message: p.stage,
      });
  }
}

// getX() and setX(value) for every option without its own methods above
for (const name of [...Object.keys(OPTIONS), ...Object.keys(UNIT_OPTIONS)] as OptionName[]) {
  const cap = name[0]!.toUpperCase() + name.slice(1);
  Object.defineProperty(Polyslice.prototype, `get${cap}`, {
    value: function (this: Polyslice) {
      return this.get(name);
    },
    writable: false,
    enumerable: false,
  });
  Object.defineProperty(Polyslice.prototype, `set${cap}`, {
    value: function (this: Polyslice, v: never) {
      return this.set(name, v);
    },
    writable: false,
    enumerable: false,
  });
}
