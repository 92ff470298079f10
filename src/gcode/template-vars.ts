/**
 * The variables templates can use: every setting under its own name, the values the writer derives for
 * each use (layer count, bounds, estimates, the layer), and the names PrusaSlicer, OrcaSlicer and Cura
 * give the same quantities, so their templates run as written.
 *
 * PrusaSlicer's per-extruder values are lists (`{temperature[0]}`, `[temperature]`,
 * `{first_layer_temperature[initial_extruder]}`): Strata has one extruder, so any index gives its value
 * (PrusaSlicer too falls back to the first for an index past the end), and the name alone gives it as
 * well; `is_extruder_used[i]` is true for 0 only. Points are two-value lists (`first_layer_print_min[0]`
 * is X, `[1]` Y). Everything else is a single value, and indexing it is an error.
 */
import { SCHEMA, type Settings } from '../settings/schema.js';
import type { TemplateValue } from './template-lang.js';
import { TemplateProblem } from './template-lang.js';

export type TemplateValues = Readonly<Record<string, TemplateValue | null>>;

/** Where a template runs: the settings and the values of this use (which win over settings). */
export interface TemplateScope {
  settings: Settings;
  values: TemplateValues;
}

/**
 * Values the writer gives every template (Strata's names): the plan's layer count, bounds and
 * estimates, the first layer's extent, and the layer the template runs at (the first for the start
 * template, the last for the end template).
 */
export const DERIVED_VALUES = [
  'layerCount',
  'printTimeSeconds',
  'filamentMm',
  'filamentGrams',
  'minX',
  'minY',
  'minZ',
  'maxX',
  'maxY',
  'maxZ',
  'firstLayerMinX',
  'firstLayerMinY',
  'firstLayerMaxX',
  'firstLayerMaxY',
  'layerIndex',
  'layerZ',
  'maxLayerZ',
  'extrudedVolume',
  'extrudedWeight',
] as const;

/**
 * Nullable settings whose empty value means "same as another setting", as the schema describes: used
 * when the caller has not already resolved them.
 */
const FALLBACKS: Readonly<Record<string, readonly string[]>> = {
  firstLayerNozzleTemperature: ['nozzleTemperature'],
  firstLayerBedTemperature: ['bedTemperature'],
  lineWidth: ['nozzleDiameter'],
  firstLayerLineWidth: ['lineWidth', 'nozzleDiameter'],
  topSkinThickness: ['shellSkinThickness'],
  bottomSkinThickness: ['shellSkinThickness'],
  travelAcceleration: ['acceleration'],
  retractAcceleration: ['maxAccelerationE', 'acceleration'],
  jerkX: ['jerkY', 'cornerVelocity'],
  jerkY: ['jerkX', 'cornerVelocity'],
};

const has = (o: object, key: string) => Object.prototype.hasOwnProperty.call(o, key);

/** A setting value with the schema's fallbacks for empty (null) derived settings applied. */
export function settingValue(settings: Settings, key: string): TemplateValue | null | undefined {
  const table = settings as unknown as Record<string, TemplateValue | null>;
  if (!has(SCHEMA, key) || !has(table, key)) return undefined;
  let value = table[key];
  for (const other of FALLBACKS[key] ?? []) {
    if (value !== null && value !== undefined) break;
    value = table[other];
  }
  return value ?? null;
}

type Kind = 'single' | 'extruder' | 'point';
interface Variable {
  kind: Kind;
  /** The Strata setting or derived value it reads, when it is one of them. */
  key?: string;
  get(scope: TemplateScope, index: number): TemplateValue | null;
}

/** A Strata setting or derived value (a derived value of the use wins). */
function strata(scope: TemplateScope, key: string): TemplateValue | null {
  if (has(scope.values, key)) return scope.values[key] ?? null;
  return settingValue(scope.settings, key) ?? null;
}

const single = (get: (s: TemplateScope) => TemplateValue | null): Variable => ({ kind: 'single', get: (s) => get(s) });
const of = (key: string): Variable => ({ kind: 'single', key, get: (s) => strata(s, key) });
const perExtruder = (key: string, scale = 1): Variable => ({
  kind: 'extruder',
  key,
  get: (s) => {
    const v = strata(s, key);
    return typeof v === 'number' && scale !== 1 ? v * scale : v;
  },
});
const point = (
  x: (s: TemplateScope) => TemplateValue | null,
  y: (s: TemplateScope) => TemplateValue | null,
): Variable => ({
  kind: 'point',
  get: (s, i) => (i === 0 ? x(s) : y(s)),
});
const constant = (v: TemplateValue): Variable => single(() => v);

/** The bed's extent in printer coordinates. */
const bedMin = (s: TemplateScope, axis: 'x' | 'y') =>
  s.settings.originAtCenter ? -(axis === 'x' ? s.settings.buildPlateWidth : s.settings.buildPlateLength) / 2 : 0;
const bedSize = (s: TemplateScope, axis: 'x' | 'y') =>
  axis === 'x' ? s.settings.buildPlateWidth : s.settings.buildPlateLength;

/** Cura's print time: hours, minutes and seconds, `01:23:45`. */
function clock(seconds: TemplateValue | null): string | null {
  if (typeof seconds !== 'number') return null;
  const t = Math.max(0, Math.round(seconds));
  const two = (n: number) => String(n).padStart(2, '0');
  return `${two(Math.floor(t / 3600))}:${two(Math.floor((t % 3600) / 60))}:${two(t % 60)}`;
}

/** Other slicers' names for Strata's quantities. */
const ALIASES: Readonly<Record<string, Variable>> = {
  // PrusaSlicer, SuperSlicer (lists per extruder where they are)
  temperature: perExtruder('nozzleTemperature'),
  first_layer_temperature: perExtruder('firstLayerNozzleTemperature'),
  bed_temperature: perExtruder('bedTemperature'),
  first_layer_bed_temperature: perExtruder('firstLayerBedTemperature'),
  nozzle_diameter: perExtruder('nozzleDiameter'),
  filament_diameter: perExtruder('filamentDiameter'),
  filament_type: perExtruder('filamentType'),
  filament_density: perExtruder('filamentDensity'),
  extrusion_multiplier: perExtruder('flowRate', 0.01),
  retract_length: perExtruder('retractionDistance'),
  retract_speed: perExtruder('retractionSpeed'),
  retract_lift: perExtruder('zHop'),
  is_extruder_used: { kind: 'extruder', get: (_s, i) => i === 0 },
  layer_height: of('layerHeight'),
  first_layer_height: of('firstLayerHeight'),
  max_print_height: of('buildVolumeHeight'),
  travel_speed: of('travelSpeed'),
  gcode_flavor: of('gcodeFlavor'),
  use_relative_e_distances: single((s) => s.settings.extruderMode === 'relative'),
  use_firmware_retraction: of('firmwareRetraction'),
  machine_max_acceleration_extruding: perExtruder('acceleration'),
  machine_max_acceleration_travel: perExtruder('travelAcceleration'),
  machine_max_acceleration_retracting: perExtruder('retractAcceleration'),
  machine_max_acceleration_x: perExtruder('maxAccelerationX'),
  machine_max_acceleration_y: perExtruder('maxAccelerationY'),
  machine_max_acceleration_z: perExtruder('maxAccelerationZ'),
  machine_max_acceleration_e: perExtruder('maxAccelerationE'),
  machine_max_feedrate_x: perExtruder('maxSpeedX'),
  machine_max_feedrate_y: perExtruder('maxSpeedY'),
  machine_max_feedrate_z: perExtruder('maxSpeedZ'),
  machine_max_feedrate_e: perExtruder('maxSpeedE'),
  machine_max_jerk_x: perExtruder('jerkX'),
  machine_max_jerk_y: perExtruder('jerkY'),
  total_layer_count: of('layerCount'),
  layer_num: of('layerIndex'),
  layer_z: of('layerZ'),
  max_layer_z: of('maxLayerZ'),
  extruded_volume_total: of('extrudedVolume'),
  extruded_weight_total: of('extrudedWeight'),
  first_layer_print_min: point(
    (s) => strata(s, 'firstLayerMinX'),
    (s) => strata(s, 'firstLayerMinY'),
  ),
  first_layer_print_max: point(
    (s) => strata(s, 'firstLayerMaxX'),
    (s) => strata(s, 'firstLayerMaxY'),
  ),
  first_layer_print_size: point(
    (s) => difference(strata(s, 'firstLayerMaxX'), strata(s, 'firstLayerMinX')),
    (s) => difference(strata(s, 'firstLayerMaxY'), strata(s, 'firstLayerMinY')),
  ),
  print_bed_min: point(
    (s) => bedMin(s, 'x'),
    (s) => bedMin(s, 'y'),
  ),
  print_bed_max: point(
    (s) => bedMin(s, 'x') + bedSize(s, 'x'),
    (s) => bedMin(s, 'y') + bedSize(s, 'y'),
  ),
  print_bed_size: point(
    (s) => bedSize(s, 'x'),
    (s) => bedSize(s, 'y'),
  ),
  // one extruder, no wipe tower, no Z offset (Strata writes none), no spiral vase unless a setting says so
  initial_tool: constant(0),
  initial_extruder: constant(0),
  current_extruder: constant(0),
  current_object_idx: constant(0),
  color_change_extruder: constant(0),
  filament_extruder_id: constant(0),
  num_extruders: constant(1),
  total_toolchanges: constant(0),
  has_wipe_tower: constant(false),
  has_single_extruder_multi_material_priming: constant(false),
  single_extruder_multi_material: constant(false),
  z_offset: constant(0),
  spiral_vase: single((s) => settingValue(s.settings, 'spiralVase') ?? false),
  // OrcaSlicer, Bambu Studio
  nozzle_temperature: perExtruder('nozzleTemperature'),
  nozzle_temperature_initial_layer: perExtruder('firstLayerNozzleTemperature'),
  bed_temperature_initial_layer: perExtruder('firstLayerBedTemperature'),
  bed_temperature_initial_layer_single: of('firstLayerBedTemperature'),
  hot_plate_temp: perExtruder('bedTemperature'),
  hot_plate_temp_initial_layer: perExtruder('firstLayerBedTemperature'),
  initial_layer_print_height: of('firstLayerHeight'),
  printable_height: of('buildVolumeHeight'),
  retraction_length: perExtruder('retractionDistance'),
  initial_no_support_extruder: constant(0),
  // Cura
  material_print_temperature: of('nozzleTemperature'),
  material_print_temperature_layer_0: of('firstLayerNozzleTemperature'),
  material_initial_print_temperature: of('firstLayerNozzleTemperature'),
  material_final_print_temperature: of('nozzleTemperature'),
  default_material_print_temperature: of('nozzleTemperature'),
  print_temperature: of('nozzleTemperature'),
  material_bed_temperature: of('bedTemperature'),
  material_bed_temperature_layer_0: of('firstLayerBedTemperature'),
  default_material_bed_temperature: of('bedTemperature'),
  print_bed_temperature: of('bedTemperature'),
  machine_width: of('buildPlateWidth'),
  machine_depth: of('buildPlateLength'),
  machine_height: of('buildVolumeHeight'),
  machine_nozzle_size: of('nozzleDiameter'),
  machine_heated_bed: of('heatedBed'),
  machine_center_is_zero: of('originAtCenter'),
  material_diameter: of('filamentDiameter'),
  layer_height_0: of('firstLayerHeight'),
  speed_travel: of('travelSpeed'),
  retraction_amount: of('retractionDistance'),
  retraction_speed: of('retractionSpeed'),
  initial_extruder_nr: constant(0),
  extruders_enabled_count: constant(1),
  machine_extruder_count: constant(1),
  print_time: single((s) => clock(strata(s, 'printTimeSeconds'))),
  filament_amount: single((s) => metres(strata(s, 'filamentMm'))),
  filament_weight: of('filamentGrams'),
};

function difference(a: TemplateValue | null, b: TemplateValue | null): number | null {
  return typeof a === 'number' && typeof b === 'number' ? Math.round((a - b) * 1000) / 1000 : null;
}

function metres(mm: TemplateValue | null): number | null {
  return typeof mm === 'number' ? Math.round(mm / 10) / 100 : null;
}

/** Whether `name` is a variable templates can use (with `values` the use's own values). */
export function isTemplateVariable(name: string, values: TemplateValues = {}): boolean {
  return (
    has(values, name) ||
    (has(SCHEMA, name) && name !== 'threads') ||
    has(ALIASES, name) ||
    (DERIVED_VALUES as readonly string[]).includes(name)
  );
}

/** The other slicers' names Strata reads (for documentation and the import). */
export const TEMPLATE_ALIASES: readonly string[] = Object.keys(ALIASES);

/** The Strata setting or derived value another slicer's name stands for, when it stands for one. */
export function aliasOf(name: string): string | undefined {
  return has(ALIASES, name) ? ALIASES[name]!.key : undefined;
}

/** The value of variable `name` in `scope` (`index` when indexed), null for none; undefined for no such variable. */
export function templateVariable(
  name: string,
  index: number | undefined,
  scope: TemplateScope,
): TemplateValue | null | undefined {
  if (
    has(scope.values, name) ||
    (has(SCHEMA, name) && name !== 'threads') ||
    (DERIVED_VALUES as readonly string[]).includes(name)
  ) {
    if (index !== undefined) throw new TemplateProblem(`${name} is a single value: it takes no [${index}]`);
    return strata(scope, name);
  }
  const v = ALIASES[name];
  if (!v) return undefined;
  if (v.kind === 'single' && index !== undefined)
    throw new TemplateProblem(`${name} is a single value: it takes no [${index}]`);
  if (v.kind === 'point') {
    if (index === undefined) throw new TemplateProblem(`${name} is a point: write ${name}[0] for X, ${name}[1] for Y`);
    if (index > 1) throw new TemplateProblem(`${name}[${index}]: a point has [0] (X) and [1] (Y) only`);
  }
  return v.get(scope, index ?? 0);
}

/** How many values a variable holds. */
export function templateVariableSize(name: string): number {
  return ALIASES[name]?.kind === 'point' ? 2 : 1;
}
