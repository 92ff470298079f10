/**
 * PrusaSlicer, SuperSlicer and OrcaSlicer settings (the Slic3r family) mapped onto Strata's. The three
 * share most keys; OrcaSlicer (from Bambu Studio) renamed many, and both names are read.
 *
 * Conversions, as those slicers define their values:
 * - Extrusion widths may be percentages: PrusaSlicer computes them over the layer height (the first
 *   layer's over the first layer height), SuperSlicer and OrcaSlicer over the nozzle diameter. A
 *   PrusaSlicer percentage that gives no usable width over the layer height (under 60 % of the nozzle)
 *   is read over the nozzle, as the files of its SuperSlicer-derived forks mean it. 0 means automatic.
 * - PrusaSlicer speeds may be percentages: the external perimeter of the perimeter speed, solid infill
 *   of the infill speed, top solid infill of the solid infill speed, the first layer of the perimeter
 *   speed; OrcaSlicer's first-layer travel of the travel speed.
 * - Overhangs: PrusaSlicer's dynamic overhang speeds are given at 75, 50, 25 and 0 % of the line over the layer
 *   below (Strata's steps of a quarter, half, three quarters and all of it over nothing), OrcaSlicer's for
 *   [25, 50), [50, 75) and [75, 100) % over nothing and its bridge speed for walls wholly over nothing; both
 *   may be % of the outer wall speed, and 0 is the wall's own speed. Strata steps where PrusaSlicer
 *   interpolates between its points, and does not slow walls with under a quarter over nothing (OrcaSlicer's
 *   10-25 % speed is reported unless 0). Fan: OrcaSlicer's overhang fan speed, and the highest of
 *   PrusaSlicer's dynamic fan speeds above the profile's fan (PrusaSlicer only ever raises the fan there).
 * - Top and bottom skin: a layer count and a minimum thickness; Strata takes the thicker of the two.
 * - Bed: the outline's extent; an outline centred on the origin is a centre-origin (delta) bed.
 * - Temperatures, fan and retraction lists hold one value per extruder: the first is taken. OrcaSlicer's
 *   bed temperature depends on the plate type (`curr_bed_type`); without one the textured PEI plate's.
 * - Fan: PrusaSlicer runs the fan at `min_fan_speed` on every layer when `fan_always_on`, otherwise only
 *   for short layers (Strata: 0); OrcaSlicer at `fan_min_speed` when it keeps the fan on
 *   (`reduce_fan_stop_start_freq`), else at `fan_max_speed` for the layers it cools.
 * - Pressure advance: OrcaSlicer's `pressure_advance` when enabled; PrusaSlicer's filament start G-code
 *   `M900 K…` or `SET_PRESSURE_ADVANCE ADVANCE=…`.
 * - Support: the overhang threshold is a slope from the horizontal there (0: automatic), from the vertical
 *   in Strata; organic (PrusaSlicer) and tree (OrcaSlicer) styles are tree support; the spacing of support
 *   lines becomes a density; a bottom contact distance of 0 and bottom interface layers of -1 mean "as the
 *   top"; the XY distance may be a percentage of the external perimeter width (taken over the nozzle); the
 *   tree's branch density becomes the tip spacing (a support line's width over it).
 *   PrusaSlicer's `dont_support_bridges` has no span: it is reported, for `supportSkipBridges` to be set.
 * - Walls: the perimeter generator (OrcaSlicer's `wall_generator`) arachne is Strata's variable walls,
 *   classic its classic ones. Arachne's minimum feature size, minimum perimeter width and transition
 *   length are % of the nozzle diameter in Strata: PrusaSlicer and SuperSlicer write them in % of the
 *   nozzle or in mm (turned into % of the profile's nozzle), OrcaSlicer in % only (a bare number is %).
 *   PrusaSlicer's `thin_walls` (the classic generator's thin-wall detection) has no Strata equivalent.
 * - Scarf seams: PrusaSlicer's `scarf_seam_placement` (contours, everywhere) and OrcaSlicer's `seam_slope_type`
 *   (external, all) put the scarf on the outer wall's loops, holes included (Strata's `outer`), or with their
 *   inner-wall switch on every wall (`all`). The start height is % of the layer height (OrcaSlicer's may be
 *   mm, turned into %); PrusaSlicer's largest segment length becomes a count of steps over the length. A
 *   scarf round the entire loop is reported: Strata's is `scarfLength` long.
 * - Fuzzy skin: `external` is the part's outside (`outer`), `all` holes too; OrcaSlicer's `allwalls` (inner
 *   walls as well) is taken as `all`, whose inner walls stay smooth.
 * - Sequential printing: PrusaSlicer's and SuperSlicer's `complete_objects`, OrcaSlicer's `print_sequence`
 *   (`by object`; `by layer` is off); the clearance radius as written; the gantry height from
 *   `extruder_clearance_height`, or OrcaSlicer's `extruder_clearance_height_to_rod` (nozzle tip to the X
 *   axis rods; its height to the lid limits the last object too, which Strata does not model, and is left
 *   unread).
 * - Wipe: see `wipe` below. PrusaSlicer's `retract_lift_above`/`retract_lift_below` (a Z range for the
 *   lift), its travel ramping and OrcaSlicer's `z_hop_types` (slope, spiral) have no Strata equivalent
 *   and are left unread.
 */
import { PATTERN_IDS, type PatternId } from '../infill/types.js';
import type { Settings } from '../settings/schema.js';
import { SCHEMA } from '../settings/schema.js';
import type { ImportContext } from './context.js';
import { importTemplate, listEntries } from './templates.js';
import {
  bool,
  first,
  num,
  numOrPercent,
  percent,
  percentOfNozzle,
  points,
  text,
  tipSpacingOfDensity,
} from './values.js';
import { WHOLE_QUOTIENT_EPS } from '../geometry/tolerances.js';

export type Slic3rFlavor = 'prusaslicer' | 'superslicer' | 'orcaslicer';

/** Keys that describe the profile rather than set anything (never reported as unused). */
export const SLIC3R_METADATA = new Set([
  'inherits',
  'compatible_printers',
  'compatible_printers_condition',
  'compatible_prints',
  'compatible_prints_condition',
  'print_settings_id',
  'filament_settings_id',
  'printer_settings_id',
  'printer_model',
  'printer_variant',
  'printer_vendor',
  'printer_technology',
  'name',
  'from',
  'type',
  'setting_id',
  'instantiation',
  'version',
  'is_custom_defined',
  'renamed_from',
  'alias',
  'notes',
  'printer_notes',
  'filament_notes',
  'default_print_profile',
  'default_filament_profile',
  'filament_vendor',
  'filament_type',
  'filament_colour',
  'extruder_colour',
  'filament_settings_id',
  'print_host',
  'printhost_apikey',
  'printhost_cafile',
  'host_type',
  'preset_name',
  'preset_names',
  'upward_compatible_machine',
  'printer_structure',
  'bed_custom_texture',
  'bed_custom_model',
  'thumbnails_with_bed',
  'thumbnails_color',
  'thumbnails_custom_color',
  'wipe_tower_x',
  'wipe_tower_y',
  'post_process',
  'threads',
]);

const INFILL: Readonly<Record<string, PatternId>> = {
  rectilinear: 'lines',
  alignedrectilinear: 'lines',
  'zig-zag': 'lines',
  line: 'lines',
  monotonic: 'lines',
  monotonicline: 'lines',
  grid: 'grid',
  triangles: 'triangles',
  stars: 'triangles',
  'tri-hexagon': 'triangles',
  cubic: 'cubic',
  adaptivecubic: 'cubic',
  supportcubic: 'cubic',
  honeycomb: 'hexagons',
  '3dhoneycomb': 'hexagons',
  gyroid: 'gyroid',
  concentric: 'concentric',
  archimedeanchords: 'spiral',
  octagramspiral: 'spiral',
  lightning: 'lightning',
};
const SKIN_PATTERN: Readonly<Record<string, Settings['topSkinPattern']>> = {
  rectilinear: 'lines',
  alignedrectilinear: 'lines',
  'zig-zag': 'lines',
  line: 'lines',
  monotonic: 'monotonic',
  monotonicline: 'monotonic',
  monotoniclines: 'monotonic',
  concentric: 'concentric',
};
const IRONING: Readonly<Record<string, Settings['ironingType']>> = { top: 'top', topmost: 'topmost', solid: 'all' };
const WALL_GENERATOR: Readonly<Record<string, Settings['wallGenerator']>> = { arachne: 'variable', classic: 'classic' };
const SEAM: Readonly<Record<string, Settings['seamPosition']>> = {
  aligned: 'aligned',
  nearest: 'nearest',
  rear: 'rear',
  back: 'rear',
  random: 'random',
};
const FLAVOR: Readonly<Record<string, Settings['gcodeFlavor']>> = {
  marlin: 'marlin',
  marlin2: 'marlin',
  marlinlegacy: 'marlin',
  marlinfirmware: 'marlin',
  reprap: 'marlin',
  sprinter: 'marlin',
  smoothie: 'marlin',
  repetier: 'marlin',
  klipper: 'klipper',
  reprapfirmware: 'reprap',
};
/** OrcaSlicer plate type → its bed temperature keys. */
const PLATES: Readonly<Record<string, string>> = {
  'Cool Plate': 'cool_plate_temp',
  'Engineering Plate': 'eng_plate_temp',
  'High Temp Plate': 'hot_plate_temp',
  'Textured PEI Plate': 'textured_plate_temp',
  'Textured Cool Plate': 'textured_cool_plate_temp',
  'SuperTack Plate': 'supertack_plate_temp',
};

const round = (v: number, digits = 4) => Math.round(v * 10 ** digits) / 10 ** digits;

/** Map the Slic3r-family keys of `c` onto Strata settings. */
export function mapSlic3rKeys(c: ImportContext, flavor: Slic3rFlavor): void {
  const nozzle = num(c.get('nozzle_diameter')) ?? (SCHEMA.nozzleDiameter.default as number);
  const layer = num(c.get('layer_height'));
  const layerHeight = layer ?? (SCHEMA.layerHeight.default as number);
  machine(c, nozzle);
  if (layer !== undefined) c.set('layerHeight', layer, 'layer_height');
  const fl = c.getAny('first_layer_height', 'initial_layer_print_height');
  if (fl) {
    const v = numOrPercent(fl.value);
    c.set('firstLayerHeight', v && round(v.percent ? (layerHeight * v.value) / 100 : v.value), fl.key, 'not a height');
  }
  const firstLayerHeight = c.settings.firstLayerHeight ?? layerHeight;
  adaptiveLayers(c);
  widths(c, flavor, nozzle, layerHeight, firstLayerHeight);
  walls(c, flavor, nozzle, layerHeight);
  seamsAndSurface(c, layerHeight);
  infill(c);
  surfaces(c);
  speeds(c);
  temperatures(c);
  cooling(c);
  overhangs(c, flavor);
  retraction(c);
  adhesion(c);
  support(c, flavor, nozzle, layerHeight);
  output(c);
  sequential(c);
}

/**
 * Variable layer height: OrcaSlicer's `adaptive_layer_height` switch, and the printer's (first extruder's)
 * limits, `min_layer_height` and `max_layer_height` (0: none given, Strata's default, as PrusaSlicer's 75 % of
 * the nozzle). PrusaSlicer's own variable heights are a per-object profile (the 3MF's layer height profile).
 */
function adaptiveLayers(c: ImportContext): void {
  const on = c.get('adaptive_layer_height');
  if (on !== undefined) c.set('adaptiveLayerHeight', bool(on), 'adaptive_layer_height', 'not a yes/no');
  for (const [key, setting] of [
    ['min_layer_height', 'minLayerHeight'],
    ['max_layer_height', 'maxLayerHeight'],
  ] as const) {
    const raw = c.get(key);
    if (raw === undefined) continue;
    const v = num(raw);
    if (v === 0) continue;
    c.set(setting, v, key, 'not a height');
  }
}

function machine(c: ImportContext, nozzle: number): void {
  if (c.get('nozzle_diameter') !== undefined) c.set('nozzleDiameter', nozzle, 'nozzle_diameter');
  const fd = c.getAny('filament_diameter');
  if (fd) c.set('filamentDiameter', num(fd.value), fd.key, 'not a diameter');
  const bed = c.getAny('bed_shape', 'printable_area');
  if (bed) {
    const pts = points(bed.value);
    if (!pts) c.reject(bed.key, 'not a bed outline (XxY points)');
    else {
      const xs = pts.map((p) => p[0]),
        ys = pts.map((p) => p[1]);
      const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
      c.set('buildPlateWidth', round(x1 - x0, 3), bed.key);
      c.set('buildPlateLength', round(y1 - y0, 3), bed.key);
      c.set('originAtCenter', Math.abs(x0 + x1) < 1 && Math.abs(y0 + y1) < 1 && x0 < 0, bed.key);
    }
  }
  const h = c.getAny('max_print_height', 'printable_height');
  if (h) c.set('buildVolumeHeight', num(h.value), h.key, 'not a height');
  const fl = c.getAny('gcode_flavor');
  if (fl) {
    const v = first(fl.value)?.toLowerCase() ?? '';
    c.set('gcodeFlavor', FLAVOR[v], fl.key, `G-code flavour "${v}" has no Strata equivalent (marlin, klipper, reprap)`);
  }
  const rel = c.getAny('use_relative_e_distances');
  if (rel)
    c.set(
      'extruderMode',
      bool(rel.value) === undefined ? undefined : bool(rel.value) ? 'relative' : 'absolute',
      rel.key,
      'not 0 or 1',
    );
  const fw = c.getAny('use_firmware_retraction');
  if (fw) c.set('firmwareRetraction', bool(fw.value), fw.key, 'not 0 or 1');
  // templates, kept as written (templates.ts); PrusaSlicer's names, then OrcaSlicer's
  for (const [keys, setting] of [
    [['start_gcode', 'machine_start_gcode'], 'startGcode'],
    [['end_gcode', 'machine_end_gcode'], 'endGcode'],
    [['before_layer_gcode', 'before_layer_change_gcode'], 'beforeLayerChangeGcode'],
    [['layer_gcode', 'layer_change_gcode'], 'layerChangeGcode'],
    [['color_change_gcode'], 'colorChangeGcode'],
    [['pause_print_gcode', 'machine_pause_gcode'], 'pauseGcode'],
  ] as const) {
    importTemplate(c, keys, setting);
  }
  const material = c.getAny('filament_type');
  if (material) c.set('filamentType', listEntries(material.value)[0], material.key, 'not a material name');
  limits(c);
}

function limits(c: ImportContext): void {
  const axes = [
    ['machine_max_feedrate_x', 'machine_max_speed_x', 'maxSpeedX'],
    ['machine_max_feedrate_y', 'machine_max_speed_y', 'maxSpeedY'],
    ['machine_max_feedrate_z', 'machine_max_speed_z', 'maxSpeedZ'],
    ['machine_max_feedrate_e', 'machine_max_speed_e', 'maxSpeedE'],
    ['machine_max_acceleration_x', '', 'maxAccelerationX'],
    ['machine_max_acceleration_y', '', 'maxAccelerationY'],
    ['machine_max_acceleration_z', '', 'maxAccelerationZ'],
    ['machine_max_acceleration_e', '', 'maxAccelerationE'],
    ['machine_max_acceleration_travel', '', 'travelAcceleration'],
    ['machine_max_acceleration_retracting', '', 'retractAcceleration'],
  ] as const;
  for (const [prusa, orca, setting] of axes) {
    const v = c.getAny(prusa, ...(orca ? [orca] : []));
    if (v) c.set(setting, num(v.value), v.key, 'not a number');
  }
  const sx = c.settings.maxSpeedX,
    sy = c.settings.maxSpeedY;
  if (sx !== undefined && sx !== null && sy !== undefined && sy !== null)
    c.set('maxSpeed', Math.min(sx, sy), 'machine_max_feedrate_x');
  const jerk = c.getAny('machine_max_jerk_x');
  if (jerk) c.set('cornerVelocity', num(jerk.value), jerk.key, 'not a number');
  // and Marlin's classic jerk itself, per axis, for the Marlin estimate (a Prusa firmware's junctions)
  for (const [key, setting] of [
    ['machine_max_jerk_x', 'jerkX'],
    ['machine_max_jerk_y', 'jerkY'],
    ['machine_max_jerk_z', 'jerkZ'],
    ['machine_max_jerk_e', 'jerkE'],
  ] as const) {
    const v = c.getAny(key);
    if (v) c.set(setting, num(v.value), v.key, 'not a number');
  }
  const usage = c.getAny('machine_limits_usage');
  if (usage) {
    const v = first(usage.value);
    const map: Record<string, Settings['machineLimits']> = {
      emit_to_gcode: 'write',
      time_estimate_only: 'estimate',
      ignore: 'ignore',
    };
    c.set(
      'machineLimits',
      v === undefined ? undefined : map[v],
      usage.key,
      'not emit_to_gcode, time_estimate_only or ignore',
    );
  }
  // OrcaSlicer's Klipper "accel to decel" (SET_VELOCITY_LIMIT ACCEL_TO_DECEL = acceleration × factor):
  // Klipper's minimum_cruise_ratio is 1 − factor
  const a2d = c.getAny('accel_to_decel_enable');
  const factor = c.getAny('accel_to_decel_factor');
  if (a2d && bool(a2d.value) && factor) {
    const f = numOrPercent(first(factor.value));
    const ratio = f ? 1 - (f.percent ? f.value / 100 : f.value) : undefined;
    c.set(
      'minimumCruiseRatio',
      ratio !== undefined && ratio >= 0 && ratio <= 0.99 ? Math.round(ratio * 1000) / 1000 : undefined,
      factor.key,
      'not a factor between 1 % and 100 %',
    );
  }
  const emit = c.getAny('emit_machine_limits_to_gcode');
  if (emit) c.set('machineLimits', bool(emit.value) ? 'write' : 'estimate', emit.key);
  // print acceleration: the profile's default, else the firmware's extruding limit
  const def = c.getAny('default_acceleration');
  const defValue = def ? num(def.value) : undefined;
  if (def && defValue !== undefined && defValue > 0) c.set('acceleration', defValue, def.key);
  else {
    const ext = c.getAny('machine_max_acceleration_extruding');
    if (ext) c.set('acceleration', num(ext.value), ext.key, 'not a number');
  }
}

/** An extrusion width in mm from a Slic3r-family value (0 or a missing key: automatic, undefined). */
function width(raw: string | undefined, flavor: Slic3rFlavor, nozzle: number, height: number): number | undefined {
  const v = numOrPercent(raw);
  if (!v || v.value <= 0) return undefined;
  if (!v.percent) return v.value;
  if (flavor === 'prusaslicer') {
    const overHeight = (height * v.value) / 100;
    if (overHeight >= 0.6 * nozzle) return round(overHeight);
  }
  return round((nozzle * v.value) / 100);
}

function widths(
  c: ImportContext,
  flavor: Slic3rFlavor,
  nozzle: number,
  layerHeight: number,
  firstLayerHeight: number,
): void {
  const main = c.getAny('extrusion_width', 'line_width');
  let w = main ? width(main.value, flavor, nozzle, layerHeight) : undefined;
  let from = main?.key;
  if (w === undefined) {
    const other = c.getAny(
      'perimeter_extrusion_width',
      'inner_wall_line_width',
      'external_perimeter_extrusion_width',
      'outer_wall_line_width',
    );
    if (other) {
      w = width(other.value, flavor, nozzle, layerHeight);
      from = other.key;
    }
  }
  if (w !== undefined) c.set('lineWidth', w, from!);
  const fl = c.getAny('first_layer_extrusion_width', 'initial_layer_line_width');
  if (fl) {
    const v = width(fl.value, flavor, nozzle, firstLayerHeight);
    if (v !== undefined) c.set('firstLayerLineWidth', v, fl.key);
  }
}

function walls(c: ImportContext, flavor: Slic3rFlavor, nozzle: number, layerHeight: number): void {
  const p = c.getAny('perimeters', 'wall_loops');
  if (p) c.set('wallCount', num(p.value), p.key, 'not a count');
  for (const [side, countKeys, thickKeys, setting] of [
    [
      'top',
      ['top_solid_layers', 'top_shell_layers'],
      ['top_solid_min_thickness', 'top_shell_thickness'],
      'topSkinThickness',
    ],
    [
      'bottom',
      ['bottom_solid_layers', 'bottom_shell_layers'],
      ['bottom_solid_min_thickness', 'bottom_shell_thickness'],
      'bottomSkinThickness',
    ],
  ] as const) {
    const n = c.getAny(...countKeys);
    const t = c.getAny(...thickKeys);
    const layers = n ? num(n.value) : undefined;
    const minimum = t ? (num(t.value) ?? 0) : 0;
    if (layers === undefined && !t) continue;
    c.set(
      setting,
      round(Math.max((layers ?? 0) * layerHeight, minimum), 4),
      `${n?.key ?? t!.key}${n && t ? ' + ' + t.key : ''}`,
      `no ${side} layer count`,
    );
  }
  const order = c.getAny('external_perimeters_first');
  if (order) c.set('wallOrder', bool(order.value) ? 'outer-first' : 'inner-first', order.key);
  const seq = c.getAny('wall_sequence', 'wall_infill_order');
  if (seq) {
    const v = first(seq.value) ?? '';
    c.set(
      'wallOrder',
      v.startsWith('outer') ? 'outer-first' : v.startsWith('inner') ? 'inner-first' : undefined,
      seq.key,
      `"${v}" has no Strata equivalent`,
    );
  }
  const seam = c.getAny('seam_position');
  if (seam) {
    const v = first(seam.value)?.toLowerCase() ?? '';
    c.set('seamPosition', SEAM[v], seam.key, `seam "${v}" has no Strata equivalent`);
  }
  variableWalls(c, flavor, nozzle);
}

/** The wall generator and Arachne's sizes (% of the nozzle; PrusaSlicer and SuperSlicer may write mm). */
function variableWalls(c: ImportContext, flavor: Slic3rFlavor, nozzle: number): void {
  const generator = c.getAny('perimeter_generator', 'wall_generator');
  if (generator) {
    const v = first(generator.value)?.toLowerCase() ?? '';
    c.set(
      'wallGenerator',
      WALL_GENERATOR[v],
      generator.key,
      `wall generator "${v}" has no Strata equivalent (arachne, classic)`,
    );
  }
  for (const [key, setting] of [
    ['min_feature_size', 'minFeatureSize'],
    ['min_bead_width', 'minBeadWidth'],
    ['wall_transition_length', 'wallTransitionLength'],
  ] as const) {
    const raw = c.get(key);
    if (raw === undefined) continue;
    const v = numOrPercent(raw);
    // OrcaSlicer's are percentages only: a bare number is one too
    const pct =
      v === undefined ? undefined : v.percent || flavor === 'orcaslicer' ? v.value : percentOfNozzle(v.value, nozzle);
    c.set(setting, pct, key, 'not a length or percentage');
  }
  const angle = c.getAny('wall_transition_angle');
  if (angle) c.set('wallTransitionAngle', num(angle.value), angle.key, 'not an angle');
  const count = c.getAny('wall_distribution_count');
  if (count) c.set('wallDistributionCount', num(count.value), count.key, 'not a count');
}

function infill(c: ImportContext): void {
  const d = c.getAny('fill_density', 'sparse_infill_density');
  if (d) c.set('infillDensity', percent(d.value, true), d.key, 'not a percentage');
  const p = c.getAny('fill_pattern', 'sparse_infill_pattern');
  if (p) {
    const v = first(p.value)?.toLowerCase() ?? '';
    const id = INFILL[v] ?? ((PATTERN_IDS as readonly string[]).includes(v) ? (v as PatternId) : undefined);
    c.set('infillPattern', id, p.key, `pattern "${v}" has no Strata equivalent (${PATTERN_IDS.join(', ')})`);
  }
  const a = c.getAny('fill_angle', 'infill_direction');
  if (a) c.set('infillAngle', num(a.value), a.key, 'not an angle');
  const o = c.getAny('infill_overlap', 'infill_wall_overlap');
  if (o) {
    const v = numOrPercent(o.value);
    const w = c.settings.lineWidth ?? null;
    // a length in mm is turned into % of the line width
    const pct =
      v === undefined
        ? undefined
        : v.percent
          ? v.value
          : round((100 * v.value) / (w ?? c.settings.nozzleDiameter ?? (SCHEMA.nozzleDiameter.default as number)), 2);
    c.set('infillOverlap', pct, o.key, 'not a length or percentage');
  }
}

/** A speed in mm/s from a value that may be a percentage of `base`. */
function speed(raw: string | undefined, base: number | undefined): number | undefined {
  const v = numOrPercent(raw);
  if (!v || v.value <= 0) return undefined;
  if (!v.percent) return v.value;
  return base === undefined ? undefined : round((base * v.value) / 100, 2);
}

/**
 * Skin patterns and ironing. PrusaSlicer's top and bottom fill patterns (OrcaSlicer's top and bottom surface
 * patterns): rectilinear and its kin are lines, monotonic (and OrcaSlicer's monotonic line) monotonic,
 * concentric concentric. Ironing: PrusaSlicer's `ironing` turns it on and `ironing_type` says where
 * (top, topmost, solid: all); OrcaSlicer has the type alone, `no ironing` for off. The flow is a % of a full
 * line as wide as the ironing spacing in both, as in Strata. OrcaSlicer's `ironing_angle` is a fixed
 * direction, or -1 for its fill direction, which Strata's default (across the skin lines) stands for.
 */
function surfaces(c: ImportContext): void {
  for (const [side, setting] of [
    ['top', 'topSkinPattern'],
    ['bottom', 'bottomSkinPattern'],
  ] as const) {
    const p = c.getAny(`${side}_fill_pattern`, `${side}_surface_pattern`);
    if (!p) continue;
    const v = first(p.value)?.toLowerCase();
    c.set(
      setting,
      v === undefined ? undefined : SKIN_PATTERN[v],
      p.key,
      `pattern "${v}" has no Strata skin equivalent (lines, monotonic, concentric)`,
    );
  }
  // PrusaSlicer's bridge_flow_ratio, OrcaSlicer's bridge_flow: a ratio (1 = 100 %) of the same round bridge bead
  const bridgeFlow = c.getAny('bridge_flow_ratio', 'bridge_flow');
  if (bridgeFlow) {
    const p = numOrPercent(first(bridgeFlow.value));
    c.set(
      'bridgeFlow',
      p === undefined ? undefined : p.percent ? p.value : p.value * 100,
      bridgeFlow.key,
      'not a ratio',
    );
  }
  const on = c.getAny('ironing');
  if (on) c.set('ironingEnabled', bool(on.value), on.key, 'not 0 or 1');
  const type = c.getAny('ironing_type');
  const t = type ? first(type.value)?.toLowerCase() : undefined;
  if (type && (t === 'no ironing' || t === 'no_ironing')) {
    if (!on) c.set('ironingEnabled', false, type.key);
  } else if (type) {
    const id = t === undefined ? undefined : IRONING[t];
    c.set('ironingType', id, type.key, `ironing type "${t}" has no Strata equivalent (top, topmost, solid)`);
    if (!on && id) c.set('ironingEnabled', true, type.key);
  }
  const flow = c.getAny('ironing_flowrate', 'ironing_flow');
  if (flow) c.set('ironingFlow', percent(flow.value), flow.key, 'not a percentage');
  const spacing = c.getAny('ironing_spacing');
  if (spacing) c.set('ironingSpacing', num(spacing.value), spacing.key, 'not a distance');
  const ironingSpeed = c.getAny('ironing_speed');
  if (ironingSpeed) c.set('ironingSpeed', num(ironingSpeed.value), ironingSpeed.key, 'not a speed');
  const angle = c.getAny('ironing_angle');
  const a = angle ? num(angle.value) : undefined;
  if (angle && a !== -1) {
    c.set(
      'ironingAngle',
      a === undefined || a < 0 ? undefined : a > 180 ? a - 360 : a,
      angle.key,
      'not an angle from 0 to 360 (or -1)',
    );
  }
}

function speeds(c: ImportContext): void {
  const perimeter = c.getAny('perimeter_speed', 'inner_wall_speed');
  const perimeterSpeed = perimeter ? speed(perimeter.value, undefined) : undefined;
  if (perimeter) c.set('innerWallSpeed', perimeterSpeed, perimeter.key, 'not a speed');
  const external = c.getAny('external_perimeter_speed', 'outer_wall_speed');
  if (external)
    c.set(
      'perimeterSpeed',
      speed(external.value, perimeterSpeed),
      external.key,
      'not a speed (or a % without the perimeter speed)',
    );
  const inf = c.getAny('infill_speed', 'sparse_infill_speed');
  const infillSpeed = inf ? speed(inf.value, undefined) : undefined;
  if (inf) c.set('infillSpeed', infillSpeed, inf.key, 'not a speed');
  // skin is every top and bottom solid layer: solid infill speed, else the top surface one
  const solid = c.getAny('solid_infill_speed', 'internal_solid_infill_speed');
  const solidSpeed = solid ? speed(solid.value, infillSpeed) : undefined;
  const top = c.getAny('top_solid_infill_speed', 'top_surface_speed');
  const topSpeed = top ? speed(top.value, solidSpeed) : undefined;
  if (solidSpeed !== undefined) c.set('skinSpeed', solidSpeed, solid!.key);
  else if (topSpeed !== undefined) c.set('skinSpeed', topSpeed, top!.key);
  else if (solid) c.reject(solid.key, 'not a speed');
  const fl = c.getAny('first_layer_speed', 'initial_layer_speed');
  if (fl) c.set('firstLayerSpeed', speed(fl.value, perimeterSpeed), fl.key, 'not a speed');
  const travel = c.getAny('travel_speed');
  const travelSpeed = travel ? speed(travel.value, undefined) : undefined;
  if (travel) c.set('travelSpeed', travelSpeed, travel.key, 'not a speed');
  const flt = c.getAny('first_layer_travel_speed', 'initial_layer_travel_speed');
  if (flt) c.set('firstLayerTravelSpeed', speed(flt.value, travelSpeed), flt.key, 'not a speed');
  const max = c.getAny('max_print_speed');
  if (max && c.settings.maxSpeed === undefined) {
    const v = num(max.value);
    if (v !== undefined && v > 0) c.set('maxSpeed', v, max.key);
  }
}

/** Dynamic overhang speeds and fan, and extra perimeters on overhangs. */
function overhangs(c: ImportContext, flavor: Slic3rFlavor): void {
  const outer = c.settings.perimeterSpeed ?? (SCHEMA.perimeterSpeed.default as number);
  // a step's speed: mm/s or % of the outer wall's, 0 the wall's own (no slower than the outer wall)
  const stepSpeed = (raw: string): number | undefined => {
    const v = numOrPercent(raw);
    if (!v || v.value < 0) return undefined;
    return v.value === 0 ? outer : v.percent ? round((outer * v.value) / 100, 2) : v.value;
  };
  const take = (
    on: boolean,
    steps: readonly (readonly [
      string,
      'overhangSpeed25' | 'overhangSpeed50' | 'overhangSpeed75' | 'overhangWallSpeed',
    ])[],
  ) => {
    for (const [key, setting] of steps) {
      const raw = c.get(key);
      if (raw !== undefined && on) c.set(setting, stepSpeed(raw), key, 'not a speed');
    }
  };
  const prusa = c.getAny('enable_dynamic_overhang_speeds');
  if (prusa) {
    const on = bool(prusa.value);
    c.set('dynamicOverhangSpeeds', on, prusa.key, 'not 0 or 1');
    take(on === true, [
      ['overhang_speed_3', 'overhangSpeed25'],
      ['overhang_speed_2', 'overhangSpeed50'],
      ['overhang_speed_1', 'overhangSpeed75'],
      ['overhang_speed_0', 'overhangWallSpeed'],
    ]);
  }
  const orca = c.getAny('enable_overhang_speed');
  if (orca) {
    const on = bool(orca.value);
    c.set('dynamicOverhangSpeeds', on, orca.key, 'not 0 or 1');
    take(on === true, [
      ['overhang_2_4_speed', 'overhangSpeed25'],
      ['overhang_3_4_speed', 'overhangSpeed50'],
      ['overhang_4_4_speed', 'overhangSpeed75'],
    ]);
    const quarter = c.get('overhang_1_4_speed');
    if (on && quarter !== undefined && numOrPercent(quarter)?.value !== 0)
      c.reject('overhang_1_4_speed', 'Strata slows walls from a quarter of the line over nothing (overhangSpeed25)');
    // OrcaSlicer prints walls wholly over nothing at its bridge speed
    const bridge = on && flavor === 'orcaslicer' ? c.get('bridge_speed') : undefined;
    if (bridge !== undefined) c.set('overhangWallSpeed', stepSpeed(bridge), 'bridge_speed', 'not a speed');
  }
  // fan: OrcaSlicer's for overhangs and bridges alike
  const orcaFan = c.getAny('overhang_fan_speed');
  if (orcaFan) {
    const on = bool(c.get('enable_overhang_bridge_fan')) ?? true;
    const v = num(orcaFan.value);
    if (on) {
      c.set('overhangFanSpeed', v, orcaFan.key, 'not a fan speed');
      c.set('bridgeFanSpeed', v, orcaFan.key);
    }
    const threshold = first(c.get('overhang_fan_threshold'));
    // Strata's overhang fan runs from a quarter of the line over nothing with dynamic speeds, else on walls wholly over it
    const from = (c.settings.dynamicOverhangSpeeds ?? false) ? ['0%', '10%', '25%'] : ['95%'];
    if (on && threshold !== undefined && !from.includes(threshold)) {
      c.reject(
        'overhang_fan_threshold',
        `Strata runs the overhang fan on ${c.settings.dynamicOverhangSpeeds ? 'walls with a quarter of the line or more' : 'walls wholly'} over nothing`,
      );
    }
  }
  // PrusaSlicer raises the fan towards these at 0, 25, 50 and 75 % of the line over the layer below
  const dynamicFan = c.getAny('enable_dynamic_fan_speeds');
  const fans = ['overhang_fan_speed_0', 'overhang_fan_speed_1', 'overhang_fan_speed_2', 'overhang_fan_speed_3'].map(
    (k) => c.get(k),
  );
  if (dynamicFan && bool(dynamicFan.value)) {
    const values = fans.map(num).filter((v): v is number => v !== undefined);
    const top = values.length ? Math.max(...values) : undefined;
    if (top !== undefined && top > (c.settings.fanSpeed ?? 0)) {
      c.set('overhangFanSpeed', top, 'overhang_fan_speed_0');
      if (values.some((v) => v !== top))
        c.reject('overhang_fan_speed_1', `Strata runs one overhang fan speed (${top} %) on every overhanging wall`);
    }
  }
  const extra = c.getAny('extra_perimeters_on_overhangs');
  if (extra) c.set('extraPerimetersOnOverhangs', bool(extra.value), extra.key, 'not 0 or 1');
}

function temperatures(c: ImportContext): void {
  const t = c.getAny('temperature', 'nozzle_temperature');
  if (t) c.set('nozzleTemperature', num(t.value), t.key, 'not a temperature');
  const ft = c.getAny('first_layer_temperature', 'nozzle_temperature_initial_layer');
  if (ft) c.set('firstLayerNozzleTemperature', num(ft.value), ft.key, 'not a temperature');
  const b = c.getAny('bed_temperature');
  if (b) c.set('bedTemperature', num(b.value), b.key, 'not a temperature');
  const fb = c.getAny('first_layer_bed_temperature');
  if (fb) c.set('firstLayerBedTemperature', num(fb.value), fb.key, 'not a temperature');
  // OrcaSlicer: per plate type
  const plate = first(c.get('curr_bed_type'));
  const plateKey =
    (plate && PLATES[plate]) ??
    ['textured_plate_temp', 'hot_plate_temp', 'eng_plate_temp', 'cool_plate_temp'].find((k) => c.has(k));
  if (plateKey && c.has(plateKey) && !b) {
    c.set('bedTemperature', num(c.get(plateKey)), plateKey, 'not a temperature');
    const initial = c.get(`${plateKey}_initial_layer`);
    if (initial !== undefined)
      c.set('firstLayerBedTemperature', num(initial), `${plateKey}_initial_layer`, 'not a temperature');
  }
}

function cooling(c: ImportContext): void {
  const always = c.get('fan_always_on');
  const minFan = c.getAny('min_fan_speed');
  if (always !== undefined || minFan) {
    const on = bool(always) ?? true;
    c.set('fanSpeed', on ? num(minFan?.value) : 0, 'fan_always_on + min_fan_speed', 'no fan speed');
  }
  const orcaMin = c.getAny('fan_min_speed');
  const orcaMax = c.getAny('fan_max_speed');
  if (orcaMin || orcaMax) {
    const keepOn = bool(c.get('reduce_fan_stop_start_freq')) ?? true;
    const v = keepOn ? (num(orcaMin?.value) ?? num(orcaMax?.value)) : num(orcaMax?.value);
    c.set('fanSpeed', v, orcaMin?.key ?? orcaMax!.key, 'no fan speed');
  }
  const off = c.getAny('disable_fan_first_layers', 'close_fan_the_first_x_layers');
  if (off) {
    const n = num(off.value);
    const fan = c.settings.fanSpeed;
    c.set('firstLayerFanSpeed', n === undefined ? undefined : n >= 1 ? 0 : (fan ?? undefined), off.key, 'not a count');
    if (n !== undefined) c.set('fanOffLayers', Math.max(0, Math.round(n)), off.key);
  }
  const full = c.getAny('full_fan_speed_layer');
  if (full) c.set('fanFullLayer', num(full.value), full.key, 'not a layer number');
  // the fan rises from the min towards the max speed for layers shorter than this
  const below = c.getAny('fan_below_layer_time', 'fan_cooling_layer_time');
  if (below) c.set('fanBelowLayerTime', num(below.value), below.key, 'not a time');
  const maxFan = c.getAny('max_fan_speed', 'fan_max_speed');
  if (maxFan) c.set('maxFanSpeed', num(maxFan.value), maxFan.key, 'not a fan speed');
  const slow = c.getAny('slowdown_below_layer_time', 'slow_down_layer_time');
  if (slow) c.set('minLayerTime', num(slow.value), slow.key, 'not a time');
  const minSpeed = c.getAny('min_print_speed', 'slow_down_min_speed');
  if (minSpeed) c.set('minPrintSpeed', num(minSpeed.value), minSpeed.key, 'not a speed');
  const density = c.getAny('filament_density');
  if (density) c.set('filamentDensity', num(density.value), density.key, 'not a density');
  const flow = c.getAny('extrusion_multiplier', 'filament_flow_ratio');
  if (flow) {
    const v = num(flow.value);
    c.set('flowRate', v === undefined ? undefined : round(v * 100, 3), flow.key, 'not a ratio');
  }
  // pressure advance
  const enabled = c.get('enable_pressure_advance');
  const pa = c.getAny('pressure_advance');
  if (pa && bool(enabled) !== false) c.set('pressureAdvance', num(pa.value), pa.key, 'not a number');
  const startFilament = c.getAny('start_filament_gcode', 'filament_start_gcode');
  if (startFilament) {
    const m =
      /(?:^|\n)\s*(?:M900\s+K|M572\s+(?:D\d+\s+)?S|SET_PRESSURE_ADVANCE\s+(?:EXTRUDER=\S+\s+)?ADVANCE=)([\d.]+)/i.exec(
        text(startFilament.value) ?? '',
      );
    if (m) c.set('pressureAdvance', Number(m[1]), startFilament.key);
    else c.used.delete(startFilament.key);
  }
}

function retraction(c: ImportContext): void {
  // OrcaSlicer's filament overrides win over the printer's values
  const pick = (filament: string, ...printer: string[]) => {
    const f = c.get(filament);
    if (f !== undefined && first(f) !== undefined) return { key: filament, value: f };
    return c.getAny(...printer);
  };
  const len = pick('filament_retraction_length', 'retract_length', 'retraction_length');
  if (len) {
    const v = num(len.value);
    if (v === 0) c.set('retractionEnabled', false, len.key);
    else {
      c.set('retractionDistance', v, len.key, 'not a length');
      if (v !== undefined) c.set('retractionEnabled', true, len.key);
    }
  }
  const sp = pick('filament_retraction_speed', 'retract_speed', 'retraction_speed');
  if (sp) c.set('retractionSpeed', num(sp.value), sp.key, 'not a speed');
  const extra = pick('filament_retract_restart_extra', 'retract_restart_extra');
  if (extra) c.set('retractionExtraPrime', num(extra.value), extra.key, 'not a length');
  const minTravel = pick('filament_retraction_minimum_travel', 'retract_before_travel', 'retraction_minimum_travel');
  if (minTravel) c.set('retractionMinTravel', num(minTravel.value), minTravel.key, 'not a length');
  const layerChange = pick(
    'filament_retract_when_changing_layer',
    'retract_layer_change',
    'retract_when_changing_layer',
  );
  if (layerChange) c.set('retractOnLayerChange', bool(layerChange.value), layerChange.key, 'not 0 or 1');
  const lift = pick('filament_z_hop', 'retract_lift', 'z_hop');
  if (lift) c.set('zHop', num(lift.value), lift.key, 'not a length');
  // PrusaSlicer: no retraction for travels inside the infill that cross no perimeter; OrcaSlicer's is the same idea
  const crossing = pick(
    'filament_retract_only_when_crossing_perimeters',
    'only_retract_when_crossing_perimeters',
    'reduce_infill_retraction',
  );
  if (crossing) c.set('retractCrossingWallsOnly', bool(crossing.value), crossing.key, 'not 0 or 1');
  wipe(c, pick);
}

/**
 * Wipe: PrusaSlicer's `wipe` has no length of its own: the nozzle wipes for as long as the part of the
 * retraction left after `retract_before_wipe` takes at `retract_speed`, at 80 % of `travel_speed`
 * (its GCode Wipe); that length becomes wipeDistance. OrcaSlicer's (and its filament override's)
 * `wipe_distance` is the length itself.
 */
function wipe(
  c: ImportContext,
  pick: (filament: string, ...printer: string[]) => { key: string; value: string } | undefined,
): void {
  const on = pick('filament_wipe', 'wipe');
  const before = pick('filament_retract_before_wipe', 'retract_before_wipe');
  const beforePercent = before ? percent(first(before.value)) : 0;
  if (before) c.set('retractBeforeWipe', beforePercent, before.key, 'not a percentage');
  if (!on) return;
  const enabled = bool(on.value);
  if (enabled === undefined) return c.reject(on.key, 'not 0 or 1');
  if (!enabled) return c.set('wipeDistance', 0, on.key);
  const distance = pick('filament_wipe_distance', 'wipe_distance');
  if (distance) return c.set('wipeDistance', num(distance.value), distance.key, 'not a length');
  const length = c.settings.retractionDistance ?? (SCHEMA.retractionDistance.default as number);
  const speed = c.settings.retractionSpeed ?? (SCHEMA.retractionSpeed.default as number);
  const travel = c.settings.travelSpeed ?? (SCHEMA.travelSpeed.default as number);
  const share = 1 - Math.min(100, Math.max(0, beforePercent ?? 0)) / 100;
  c.set('wipeDistance', Math.min(20, round((length * share * travel * 0.8) / speed, 2)), on.key);
}

function adhesion(c: ImportContext): void {
  const brimWidth = c.getAny('brim_width');
  const brim = brimWidth ? num(brimWidth.value) : undefined;
  const type = first(c.get('brim_type'));
  const skirts = c.getAny('skirts', 'skirt_loops');
  const skirtCount = skirts ? num(skirts.value) : undefined;
  if (brim !== undefined && brim > 0 && type !== 'no_brim') {
    c.set('adhesionType', 'brim', brimWidth!.key);
    c.set('brimWidth', brim, brimWidth!.key);
  } else if (skirtCount !== undefined) {
    c.set('adhesionType', skirtCount > 0 ? 'skirt' : 'none', skirts!.key);
    if (skirtCount > 0) c.set('skirtLoops', skirtCount, skirts!.key);
  } else if (brimWidth) c.set('brimWidth', brim, brimWidth.key, 'not a width');
  const dist = c.getAny('skirt_distance');
  if (dist) c.set('skirtDistance', num(dist.value), dist.key, 'not a distance');
}

function output(c: ImportContext): void {
  const thumbs = c.getAny('thumbnails');
  if (thumbs) {
    const format = first(c.get('thumbnails_format'))?.toUpperCase();
    const items = thumbs.value
      .replace(/[[\]"]/g, '')
      .split(',')
      .map((s) => s.trim())
      .filter(Boolean)
      .map((s) => (s.includes('/') || !format ? s : `${s}/${format === 'JPEG' ? 'JPG' : format}`));
    c.set('thumbnails', items.join(','), thumbs.key, 'not a list of sizes');
  }
  const arc = c.getAny('arc_fitting', 'enable_arc_fitting');
  if (arc) {
    const v = first(arc.value) ?? '';
    c.set('arcFitting', v === 'emit_center' || v === 'emit_radius' || bool(v) === true, arc.key);
  }
  const labels = c.getAny('gcode_label_objects');
  const exclude = bool(c.get('exclude_object'));
  if (labels) {
    const v = first(labels.value) ?? '';
    const mode: Settings['labelObjects'] | undefined =
      v === 'firmware' || exclude
        ? 'firmware'
        : v === 'octoprint' || bool(v) === true
          ? 'comments'
          : v === 'disabled' || bool(v) === false
            ? 'off'
            : undefined;
    c.set('labelObjects', mode, labels.key, 'not disabled, octoprint or firmware');
  } else if (exclude !== undefined) c.set('labelObjects', exclude ? 'firmware' : 'off', 'exclude_object');
  const m73 = c.getAny('remaining_times');
  if (m73) c.set('progressM73', bool(m73.value), m73.key, 'not 0 or 1');
}

function sequential(c: ImportContext): void {
  const complete = c.getAny('complete_objects');
  const sequence = c.getAny('print_sequence');
  if (complete) c.set('sequentialPrinting', bool(complete.value), complete.key, 'not 0 or 1');
  else if (sequence) {
    const v = (first(sequence.value) ?? '').replace(/_/g, ' ');
    c.set(
      'sequentialPrinting',
      v === 'by object' ? true : v === 'by layer' ? false : undefined,
      sequence.key,
      `print sequence "${v}" has no Strata equivalent (by layer, by object)`,
    );
  }
  const radius = c.getAny('extruder_clearance_radius');
  if (radius) c.set('extruderClearanceRadius', num(radius.value), radius.key, 'not a length');
  const height = c.getAny('extruder_clearance_height', 'extruder_clearance_height_to_rod');
  if (height) c.set('extruderClearanceHeight', num(height.value), height.key, 'not a length');
}

const SUPPORT_PATTERN: Readonly<Record<string, Settings['supportPattern']>> = {
  rectilinear: 'lines',
  'rectilinear-grid': 'grid',
  default: 'zigzag',
};

function support(c: ImportContext, flavor: Slic3rFlavor, nozzle: number, layerHeight: number): void {
  const on = c.getAny('support_material', 'enable_support');
  if (on) c.set('supportEnabled', bool(on.value), on.key, 'not 0 or 1');
  const style = c.getAny('support_material_style', 'support_type', 'support_style');
  if (style) {
    const v = first(style.value) ?? '';
    const type: Settings['supportType'] | undefined =
      v === 'organic' || v.startsWith('tree')
        ? 'tree'
        : v === 'grid' || v === 'snug' || v.startsWith('normal') || v === 'default'
          ? 'normal'
          : undefined;
    c.set('supportType', type, style.key, `support style "${v}" has no Strata equivalent (normal, tree)`);
  }
  const plate = c.getAny('support_material_buildplate_only', 'support_on_build_plate_only');
  if (plate)
    c.set(
      'supportPlacement',
      bool(plate.value) === undefined ? undefined : bool(plate.value) ? 'buildPlate' : 'everywhere',
      plate.key,
      'not 0 or 1',
    );
  const threshold = c.getAny('support_material_threshold', 'support_threshold_angle');
  if (threshold) {
    const v = num(threshold.value);
    // 0 is automatic: Strata's default stands
    if (v !== 0) c.set('supportThreshold', v === undefined ? undefined : 90 - v, threshold.key, 'not an angle');
  }
  const top = c.getAny('support_material_contact_distance', 'support_top_z_distance');
  if (top) c.set('supportZGap', num(top.value), top.key, 'not a distance');
  const bottom = c.getAny('support_material_bottom_contact_distance', 'support_bottom_z_distance');
  if (bottom) {
    const v = num(bottom.value);
    if (v !== 0) c.set('supportBottomZGap', v, bottom.key, 'not a distance');
  }
  const roof = c.getAny('support_material_interface_layers', 'support_interface_top_layers');
  if (roof) c.set('supportInterfaceLayers', num(roof.value), roof.key, 'not a count');
  const floor = c.getAny('support_material_bottom_interface_layers', 'support_interface_bottom_layers');
  if (floor) {
    const v = num(floor.value);
    if (v === undefined || v >= 0) c.set('supportFloorLayers', v, floor.key, 'not a count');
  }
  const xy = c.getAny('support_material_xy_spacing', 'support_object_xy_distance');
  if (xy) {
    const v = numOrPercent(xy.value);
    c.set('supportXYGap', v && round(v.percent ? (nozzle * v.value) / 100 : v.value), xy.key, 'not a distance');
  }
  const pattern = c.getAny('support_material_pattern', 'support_base_pattern');
  if (pattern) {
    const v = first(pattern.value) ?? '';
    c.set(
      'supportPattern',
      SUPPORT_PATTERN[v],
      pattern.key,
      `support pattern "${v}" has no Strata equivalent (zigzag, lines, grid)`,
    );
  }
  // a width of 0 is automatic: Strata's default stands
  const lineWidth = c.getAny('support_material_extrusion_width', 'support_line_width');
  const w = lineWidth ? width(lineWidth.value, flavor, nozzle, layerHeight) : undefined;
  if (lineWidth && w !== undefined) c.set('supportLineWidth', w, lineWidth.key);
  const spacing = c.getAny('support_material_spacing', 'support_base_pattern_spacing');
  if (spacing) {
    // the gap between lines: density is a line's share of its pitch
    const v = num(spacing.value);
    const lw = c.settings.supportLineWidth ?? c.settings.lineWidth ?? nozzle;
    c.set(
      'supportDensity',
      v === undefined ? undefined : round((100 * lw) / (lw + v), 1),
      spacing.key,
      'not a distance',
    );
  }
  const angle = c.getAny('support_material_angle', 'support_angle');
  if (angle) c.set('supportAngle', num(angle.value), angle.key, 'not an angle');
  const body = c.getAny('support_material_speed', 'support_speed');
  const supportSpeed = body ? speed(body.value, undefined) : undefined;
  if (body) c.set('supportSpeed', supportSpeed, body.key, 'not a speed');
  const iface = c.getAny('support_material_interface_speed', 'support_interface_speed');
  if (iface)
    c.set(
      'supportInterfaceSpeed',
      speed(iface.value, supportSpeed ?? (SCHEMA.supportSpeed.default as number)),
      iface.key,
      'not a speed',
    );
  for (const [setting, keys] of [
    ['supportTreeBranchAngle', ['support_tree_angle', 'tree_support_branch_angle']],
    ['supportTreeBranchDiameter', ['support_tree_branch_diameter', 'tree_support_branch_diameter']],
    ['supportTreeTipDiameter', ['support_tree_tip_diameter', 'tree_support_tip_diameter']],
    ['supportTreeDiameterAngle', ['support_tree_branch_diameter_angle', 'tree_support_branch_diameter_angle']],
  ] as const) {
    const v = c.getAny(...keys);
    if (v) c.set(setting, num(v.value), v.key, 'not a number');
  }
  // branch density (PrusaSlicer's 15 %: 2.67 mm)
  const rate = c.getAny('support_tree_top_rate', 'tree_support_top_rate');
  if (rate) {
    const v = numOrPercent(rate.value);
    const lw = c.settings.supportLineWidth ?? c.settings.lineWidth ?? nozzle;
    c.set('supportTreeTipSpacing', v && tipSpacingOfDensity(lw, v.value), rate.key, 'not a density');
  }
  const bridges = c.getAny('dont_support_bridges');
  if (bridges && bool(bridges.value))
    c.reject(
      bridges.key,
      'Strata bridges spans up to supportSkipBridges mm instead (0, every overhang supported, by default)',
    );
  // raft
  const raft = c.getAny('raft_layers');
  const layers = raft ? num(raft.value) : undefined;
  if (raft && layers !== undefined && layers > 0) c.set('adhesionType', 'raft', raft.key);
  const gap = c.getAny('raft_contact_distance');
  if (gap) c.set('raftAirGap', num(gap.value), gap.key, 'not a distance');
  const margin = c.getAny('raft_expansion');
  if (margin) c.set('raftMargin', num(margin.value), margin.key, 'not a distance');
}

const FUZZY: Readonly<Record<string, Settings['fuzzySkin']>> = {
  none: 'off',
  external: 'outer',
  all: 'all',
  allwalls: 'all',
};

/** Scarf seams (PrusaSlicer 2.9, OrcaSlicer) and fuzzy skin. */
function seamsAndSurface(c: ImportContext, layerHeight: number): void {
  const placement = c.getAny('scarf_seam_placement', 'seam_slope_type');
  const inner = c.getAny('scarf_seam_on_inner_perimeters', 'seam_slope_inner_walls');
  const length = c.getAny('scarf_seam_length', 'seam_slope_min_length');
  const lengthMm = length ? num(length.value) : undefined;
  if (placement) {
    const v = first(placement.value) ?? '';
    const on = v === 'contours' || v === 'everywhere' || v === 'external' || v === 'all';
    const type: Settings['scarfSeam'] | undefined =
      v === 'nowhere' || v === 'none' || lengthMm === 0
        ? 'off'
        : on
          ? inner && bool(inner.value)
            ? 'all'
            : 'outer'
          : undefined;
    c.set('scarfSeam', type, placement.key, `scarf placement "${v}" has no Strata equivalent`);
  }
  if (length && lengthMm !== 0) c.set('scarfLength', lengthMm, length.key, 'not a length');
  const start = c.getAny('scarf_seam_start_height', 'seam_slope_start_height');
  if (start) {
    const v = numOrPercent(start.value);
    c.set(
      'scarfStartHeight',
      v && round(v.percent ? v.value : (100 * v.value) / layerHeight, 2),
      start.key,
      'not a height or percentage',
    );
  }
  const steps = c.getAny('seam_slope_steps');
  if (steps) c.set('scarfSteps', num(steps.value), steps.key, 'not a count');
  const segment = c.getAny('scarf_seam_max_segment_length');
  if (segment) {
    const v = num(segment.value);
    const over = c.settings.scarfLength ?? (SCHEMA.scarfLength.default as number);
    c.set(
      'scarfSteps',
      v && v > 0 ? Math.min(SCHEMA.scarfSteps.max, Math.max(1, Math.ceil(over / v - WHOLE_QUOTIENT_EPS))) : undefined,
      segment.key,
      'not a length',
    );
  }
  const smooth = c.getAny('scarf_seam_only_on_smooth', 'seam_slope_conditional');
  if (smooth) c.set('scarfConditional', bool(smooth.value), smooth.key, 'not 0 or 1');
  const whole = c.getAny('scarf_seam_entire_loop', 'seam_slope_entire_loop');
  if (whole && bool(whole.value) && c.settings.scarfSeam !== 'off')
    c.reject(whole.key, "Strata's scarf is scarfLength long, not round the entire loop");
  const angle = c.getAny('scarf_angle_threshold');
  if (angle && c.settings.scarfConditional && num(angle.value) !== 140) {
    c.reject(
      angle.key,
      'a conditional scarf in Strata leaves out seams in corners turning 40° or more (an angle of 140° or less)',
    );
  }
  // spiral vase: PrusaSlicer's and SuperSlicer's spiral_vase, OrcaSlicer's spiral_mode
  const vase = c.getAny('spiral_vase', 'spiral_mode');
  if (vase) c.set('spiralVase', bool(vase.value), vase.key, 'not 0 or 1');
  const fuzzy = c.getAny('fuzzy_skin');
  if (fuzzy) {
    const v = first(fuzzy.value) ?? '';
    c.set('fuzzySkin', FUZZY[v], fuzzy.key, `fuzzy skin "${v}" has no Strata equivalent (none, external, all)`);
  }
  const thickness = c.getAny('fuzzy_skin_thickness');
  if (thickness) c.set('fuzzySkinThickness', num(thickness.value), thickness.key, 'not a thickness');
  const dist = c.getAny('fuzzy_skin_point_dist', 'fuzzy_skin_point_distance');
  if (dist) c.set('fuzzySkinPointDistance', num(dist.value), dist.key, 'not a distance');
  const firstLayer = c.getAny('fuzzy_skin_first_layer');
  if (firstLayer && bool(firstLayer.value) && c.settings.fuzzySkin && c.settings.fuzzySkin !== 'off') {
    c.reject(firstLayer.key, "Strata's fuzzy skin leaves the first layer smooth");
  }
}
