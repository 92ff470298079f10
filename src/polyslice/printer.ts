/**
 * `Printer`, as the seeds' library has it: a machine's build volume, bed shape, origin, heating and
 * nozzles, with getters and chainable setters, made from a name. Here the name finds one of Strata's
 * printer presets (any name `findPrinter` takes: the seeds' `Ender3`, ours `creality-ender-3`, PrusaSlicer's
 * and Cura's), and the facts come from that preset; the slicer then uses the whole preset (start and end
 * G-code, speeds, retraction, limits), not only the size and nozzle.
 *
 * Differences from the seeds' library: an unknown name throws (it printed a warning and gave an Ender 3);
 * a printer the seeds name but Strata has no preset for still gives its facts, and slicing for it says why
 * it cannot (polyslice.ts).
 */
import { StrataError } from '../errors.js';
import { findPrinter, listPresets, printerWithoutPreset, PRINTER_PRESETS } from '../settings/presets/index.js';
import { POLYSLICE_NAMES, PRINTERS_WITHOUT_PRESET } from '../settings/presets/aliases.js';
import { suggest } from '../settings/resolve.js';

export interface Nozzle {
  /** Filament diameter, mm. */
  filament: number;
  /** Nozzle diameter, mm. */
  diameter: number;
  /** Height of the gantry above the nozzle tip, mm (the seeds' field; Strata does not use it). */
  gantry: number;
}

/** Printers with a closed (heated or warmed) build chamber among the presets. */
const ENCLOSED: ReadonlySet<string> = new Set([
  'bambu-lab-x1c',
  'bambu-lab-p1s',
  'creality-k1',
  'creality-k1-max',
  'creality-k1c',
  'prusa-core-one',
  'voron-2.4-350',
  'voron-trident-300',
  'voron-0.2',
  'qidi-q1-pro',
  'qidi-x-plus-3',
]);

/** Gantry height the seeds' library gives most printers, mm. */
const DEFAULT_GANTRY = 25;

/** A positive finite number, or a one-line error naming the setter. */
function positive(what: string, v: unknown): number {
  if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0)
    throw new StrataError('BAD_SETTING', `${what} must be a number above 0, got ${JSON.stringify(v)}`);
  return v;
}

function flag(what: string, v: unknown): boolean {
  if (typeof v !== 'boolean')
    throw new StrataError('BAD_SETTING', `${what} must be true or false, got ${JSON.stringify(v)}`);
  return v;
}

export class Printer {
  /** The name it was made with. */
  model: string;
  /** Strata's preset id, or null for a printer without a preset. */
  readonly presetId: string | null;
  size: { x: number; y: number; z: number };
  shape: 'rectangular' | 'circular';
  centred: boolean;
  heated: { volume: boolean; bed: boolean };
  nozzles: Nozzle[];

  constructor(model = 'Ender3') {
    const preset = findPrinter(model);
    const gap = preset ? undefined : printerWithoutPreset(model);
    if (!preset && !gap) {
      const names = [...Object.keys(POLYSLICE_NAMES.printers), ...listPresets().printers.map((p) => p.id)];
      const s = suggest(String(model), names);
      throw new StrataError(
        'UNKNOWN_PRESET',
        `unknown printer "${model}"${s ? ` (did you mean "${s}"?)` : ''}; listAvailablePrinters() lists them`,
      );
    }
    this.model = model;
    if (preset) {
      const s = preset.settings;
      this.presetId = preset.id;
      this.size = { x: s.buildPlateWidth!, y: s.buildPlateLength!, z: s.buildVolumeHeight! };
      this.centred = s.originAtCenter === true;
      // the presets' centre-origin printers are deltas, with round beds
      this.shape = this.centred ? 'circular' : 'rectangular';
      this.heated = { volume: ENCLOSED.has(preset.id), bed: s.heatedBed !== false };
      this.nozzles = [{ filament: s.filamentDiameter!, diameter: s.nozzleDiameter!, gantry: DEFAULT_GANTRY }];
    } else {
      const g = gap!;
      this.presetId = null;
      this.size = { x: g.size[0], y: g.size[1], z: g.size[2] };
      this.centred = false;
      this.shape = 'rectangular';
      this.heated = { volume: false, bed: g.kind === 'g-code' };
      this.nozzles = [{ filament: g.filament, diameter: g.nozzle, gantry: DEFAULT_GANTRY }];
    }
  }

  /** Why Strata cannot slice for this printer, or null when it can. */
  get unsupportedReason(): string | null {
    if (this.presetId) return null;
    const gap = printerWithoutPreset(this.model)!;
    return `no printer preset for ${gap.name}: ${gap.why}`;
  }

  getModel(): string {
    return this.model;
  }
  getSize(): { x: number; y: number; z: number } {
    return this.size;
  }
  getSizeX(): number {
    return this.size.x;
  }
  getSizeY(): number {
    return this.size.y;
  }
  getSizeZ(): number {
    return this.size.z;
  }
  getShape(): 'rectangular' | 'circular' {
    return this.shape;
  }
  getCentred(): boolean {
    return this.centred;
  }
  getHeated(): { volume: boolean; bed: boolean } {
    return this.heated;
  }
  getHeatedVolume(): boolean {
    return this.heated.volume;
  }
  getHeatedBed(): boolean {
    return this.heated.bed;
  }
  getNozzles(): Nozzle[] {
    return this.nozzles;
  }
  getNozzle(index = 0): Nozzle | null {
    return index >= 0 && index < this.nozzles.length ? this.nozzles[index]! : null;
  }
  getNozzleCount(): number {
    return this.nozzles.length;
  }

  /** Set the build volume, mm; an argument left out keeps its value. */
  setSize(x?: number, y?: number, z?: number): this {
    if (x !== undefined) this.size.x = positive('setSize x', x);
    if (y !== undefined) this.size.y = positive('setSize y', y);
    if (z !== undefined) this.size.z = positive('setSize z', z);
    return this;
  }
  setSizeX(x: number): this {
    this.size.x = positive('setSizeX', x);
    return this;
  }
  setSizeY(y: number): this {
    this.size.y = positive('setSizeY', y);
    return this;
  }
  setSizeZ(z: number): this {
    this.size.z = positive('setSizeZ', z);
    return this;
  }
  setShape(shape: 'rectangular' | 'circular'): this {
    if (shape !== 'rectangular' && shape !== 'circular')
      throw new StrataError('BAD_SETTING', `setShape: "rectangular" or "circular", got ${JSON.stringify(shape)}`);
    this.shape = shape;
    return this;
  }
  setCentred(centred: boolean): this {
    this.centred = flag('setCentred', centred);
    return this;
  }
  setHeatedVolume(heated: boolean): this {
    this.heated.volume = flag('setHeatedVolume', heated);
    return this;
  }
  setHeatedBed(heated: boolean): this {
    this.heated.bed = flag('setHeatedBed', heated);
    return this;
  }
  /** Change nozzle `index`; an argument left out keeps its value. */
  setNozzle(index: number, filament?: number, diameter?: number, gantry?: number): this {
    const n = this.getNozzle(index);
    if (!n)
      throw new StrataError('BAD_SETTING', `setNozzle: no nozzle ${index} (the printer has ${this.nozzles.length})`);
    if (filament !== undefined) n.filament = positive('setNozzle filament', filament);
    if (diameter !== undefined) n.diameter = positive('setNozzle diameter', diameter);
    if (gantry !== undefined) n.gantry = positive('setNozzle gantry', gantry);
    return this;
  }
  addNozzle(filament = 1.75, diameter = 0.4, gantry = DEFAULT_GANTRY): this {
    this.nozzles.push({
      filament: positive('addNozzle filament', filament),
      diameter: positive('addNozzle diameter', diameter),
      gantry: positive('addNozzle gantry', gantry),
    });
    return this;
  }
  removeNozzle(index: number): this {
    if (!this.getNozzle(index))
      throw new StrataError('BAD_SETTING', `removeNozzle: no nozzle ${index} (the printer has ${this.nozzles.length})`);
    this.nozzles.splice(index, 1);
    return this;
  }

  listAvailablePrinters(): string[] {
    return listAvailablePrinters();
  }
}

/**
 * Every printer name a `Printer` takes: the seeds' library's names (those without a Strata preset too, which
 * give their facts but do not slice), then the ids of Strata's presets that no seeds' name covers.
 */
export function listAvailablePrinters(): string[] {
  const seeds = [...Object.keys(POLYSLICE_NAMES.printers), ...Object.keys(PRINTERS_WITHOUT_PRESET)];
  const covered = new Set(Object.values(POLYSLICE_NAMES.printers));
  return [...seeds, ...Object.keys(PRINTER_PRESETS).filter((id) => !covered.has(id))];
}
