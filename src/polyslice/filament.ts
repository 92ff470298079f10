/**
 * `Filament`, as the seeds' library has it: a spool's material, temperatures, cooling, density and
 * retraction, with getters and chainable setters, made from a name that finds one of Strata's filament
 * presets (the seeds' `GenericPLA`, `PrusamentPLA`…, ours `pla`, `prusament-pla`, Cura's `generic_pla`).
 *
 * Differences from the seeds' library: an unknown name throws (it warned and gave Generic PLA); retraction
 * belongs to the printer's extruder (a direct drive retracts ~0.8 mm, a bowden ~5 mm), so a filament carries
 * a retraction only where its material needs one (flexible filament: short and slow), else null and the
 * printer's applies; weight and cost are not known for a material (0 until set).
 */
import { StrataError } from '../errors.js';
import { FILAMENT_PRESETS, findFilament, listPresets } from '../settings/presets/index.js';
import { POLYSLICE_NAMES } from '../settings/presets/aliases.js';
import { suggest } from '../settings/resolve.js';

/** Makers sold by the branded presets, by id prefix; the rest are generic materials. */
const BRANDS: ReadonlyArray<[prefix: string, brand: string]> = [
  ['prusament-', 'Prusa'],
  ['bambu-', 'Bambu Lab'],
  ['polymaker-', 'Polymaker'],
  ['hatchbox-', 'Hatchbox'],
  ['esun-', 'eSUN'],
  ['overture-', 'Overture'],
  ['sunlu-', 'SUNLU'],
  ['colorfabb-', 'colorFabb'],
  ['ninjaflex', 'NinjaTek'],
  ['sainsmart-', 'SainSmart'],
  ['3dxtech-', '3DXTech'],
  ['ultimaker-', 'UltiMaker'],
];

/** Presets sold on 2.85 mm spools. */
const SPOOL_285: ReadonlySet<string> = new Set(['ultimaker-pla', 'ultimaker-tough-pla']);

/** How far below the printing temperature a nozzle waits between uses (the seeds' "standby"), °C. */
const STANDBY_BELOW = 20;

function nonNegative(what: string, v: unknown, max = Infinity): number {
  if (typeof v !== 'number' || !Number.isFinite(v) || v < 0 || v > max)
    throw new StrataError(
      'BAD_SETTING',
      `${what} must be a number from 0${max < Infinity ? ` to ${max}` : ''}, got ${JSON.stringify(v)}`,
    );
  return v;
}

function text(what: string, v: unknown): string {
  if (typeof v !== 'string') throw new StrataError('BAD_SETTING', `${what} must be a string, got ${JSON.stringify(v)}`);
  return v;
}

export class Filament {
  /** The name it was made with. */
  material: string;
  /** Strata's preset id. */
  readonly presetId: string;
  type: string;
  name: string;
  description: string;
  brand: string;
  color: string;
  /** mm */
  diameter: number;
  /** g/cm³ */
  density: number;
  /** Spool weight, g (0: not known). */
  weight: number;
  /** Spool cost (0: not known). */
  cost: number;
  /** Part-cooling fan, %. */
  fan: number;
  /** °C */
  temperature: { bed: number; nozzle: number; standby: number };
  /** mm/s and mm, or null where the printer's retraction applies. */
  retraction: { speed: number | null; distance: number | null };

  constructor(material = 'GenericPLA') {
    const preset = findFilament(material);
    if (!preset) {
      const names = [...Object.keys(POLYSLICE_NAMES.filaments), ...listPresets().filaments.map((f) => f.id)];
      const s = suggest(String(material), names);
      throw new StrataError(
        'UNKNOWN_PRESET',
        `unknown filament "${material}"${s ? ` (did you mean "${s}"?)` : ''}; listAvailableFilaments() lists them`,
      );
    }
    const s = preset.settings;
    this.material = material;
    this.presetId = preset.id;
    this.type = preset.material.toLowerCase();
    this.name = preset.name;
    this.brand = BRANDS.find(([prefix]) => preset.id.startsWith(prefix))?.[1] ?? 'Generic';
    this.description = `${preset.name}: ${preset.material}${preset.abrasive ? ', abrasive (use a hardened nozzle)' : ''}`;
    this.color = '#FFFFFF';
    this.diameter = SPOOL_285.has(preset.id) ? 2.85 : 1.75;
    this.density = s.filamentDensity!;
    this.weight = 0;
    this.cost = 0;
    this.fan = s.fanSpeed!;
    this.temperature = {
      bed: s.bedTemperature!,
      nozzle: s.nozzleTemperature!,
      standby: Math.max(0, s.nozzleTemperature! - STANDBY_BELOW),
    };
    this.retraction = {
      speed: s.retractionDistance !== undefined ? (s.retractionSpeed ?? null) : null,
      distance: s.retractionDistance ?? null,
    };
  }

  getMaterial(): string {
    return this.material;
  }
  getType(): string {
    return this.type;
  }
  getName(): string {
    return this.name;
  }
  getDescription(): string {
    return this.description;
  }
  getBrand(): string {
    return this.brand;
  }
  getColor(): string {
    return this.color;
  }
  getDiameter(): number {
    return this.diameter;
  }
  getDensity(): number {
    return this.density;
  }
  getWeight(): number {
    return this.weight;
  }
  getCost(): number {
    return this.cost;
  }
  getFan(): number {
    return this.fan;
  }
  getTemperature(): { bed: number; nozzle: number; standby: number } {
    return this.temperature;
  }
  getBedTemperature(): number {
    return this.temperature.bed;
  }
  getNozzleTemperature(): number {
    return this.temperature.nozzle;
  }
  getStandbyTemperature(): number {
    return this.temperature.standby;
  }
  getRetraction(): { speed: number | null; distance: number | null } {
    return this.retraction;
  }
  getRetractionSpeed(): number | null {
    return this.retraction.speed;
  }
  getRetractionDistance(): number | null {
    return this.retraction.distance;
  }

  setType(type: string): this {
    this.type = text('setType', type);
    return this;
  }
  setName(name: string): this {
    this.name = text('setName', name);
    return this;
  }
  setDescription(description: string): this {
    this.description = text('setDescription', description);
    return this;
  }
  setBrand(brand: string): this {
    this.brand = text('setBrand', brand);
    return this;
  }
  setColor(color: string): this {
    this.color = text('setColor', color);
    return this;
  }
  setDiameter(diameter: number): this {
    if (nonNegative('setDiameter', diameter) === 0) throw new StrataError('BAD_SETTING', 'setDiameter must be above 0');
    this.diameter = diameter;
    return this;
  }
  setDensity(density: number): this {
    if (nonNegative('setDensity', density) === 0) throw new StrataError('BAD_SETTING', 'setDensity must be above 0');
    this.density = density;
    return this;
  }
  setWeight(weight: number): this {
    this.weight = nonNegative('setWeight', weight);
    return this;
  }
  setCost(cost: number): this {
    this.cost = nonNegative('setCost', cost);
    return this;
  }
  setFan(fan: number): this {
    this.fan = nonNegative('setFan', fan, 100);
    return this;
  }
  setBedTemperature(temp: number): this {
    this.temperature.bed = nonNegative('setBedTemperature', temp);
    return this;
  }
  setNozzleTemperature(temp: number): this {
    this.temperature.nozzle = nonNegative('setNozzleTemperature', temp);
    return this;
  }
  setStandbyTemperature(temp: number): this {
    this.temperature.standby = nonNegative('setStandbyTemperature', temp);
    return this;
  }
  setRetractionSpeed(speed: number): this {
    if (nonNegative('setRetractionSpeed', speed) === 0)
      throw new StrataError('BAD_SETTING', 'setRetractionSpeed must be above 0');
    this.retraction.speed = speed;
    return this;
  }
  setRetractionDistance(distance: number): this {
    this.retraction.distance = nonNegative('setRetractionDistance', distance);
    return this;
  }

  listAvailableFilaments(): string[] {
    return listAvailableFilaments();
  }
}

/** Every filament name a `Filament` takes: the seeds' library's names, then Strata's presets no seeds' name covers. */
export function listAvailableFilaments(): string[] {
  const covered = new Set(Object.values(POLYSLICE_NAMES.filaments));
  return [...Object.keys(POLYSLICE_NAMES.filaments), ...Object.keys(FILAMENT_PRESETS).filter((id) => !covered.has(id))];
}
