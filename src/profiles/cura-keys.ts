/**
 * Cura profile values (`[values]` of `.cfg` / `.inst.cfg`) mapped onto Strata settings.
 *
 * A Cura value may be a formula (`=speed_print / 2`). Arithmetic over numbers and other keys is
 * evaluated (+ − × ÷, parentheses, min/max/round, math.ceil/floor); anything else (conditions, extruder
 * lookups) is not, and the key is reported. A key the profile does not set falls back as Cura's own
 * definitions do when its source is in the profile: wall speeds from `speed_wall`, which comes from
 * `speed_print`; widths from `line_width`; top and bottom thickness from `top_bottom_thickness`; the
 * first-layer temperatures from the others.
 *
 * Units: Cura's extra prime after a retraction is a volume (mm³), turned into filament length; its fuzzy skin
 * point density (points per mm) into a distance; its scarf split distance into a count of steps.
 *
 * Walls: Cura 5 always lays variable-width (Arachne) walls; a profile with its Arachne keys is Strata's
 * variable walls. Its minimum feature size, minimum thin wall line width and transition length are mm,
 * turned into % of `machine_nozzle_size` (Strata's default nozzle when the profile has none). Cura 4
 * has none of these keys.
 */
import { PATTERN_IDS, type PatternId } from '../infill/types.js';
import type { Settings } from '../settings/schema.js';
import { SCHEMA } from '../settings/schema.js';
import type { ImportContext } from './context.js';
import { importTemplate } from './templates.js';
import { bool, percentOfNozzle, tipSpacingOfDensity } from './values.js';
import { WHOLE_QUOTIENT_EPS } from '../geometry/tolerances.js';

const INFILL: Readonly<Record<string, PatternId>> = {
  grid: 'grid',
  lines: 'lines',
  zigzag: 'lines',
  triangles: 'triangles',
  trihexagon: 'triangles',
  cubic: 'cubic',
  cubicsubdiv: 'cubic',
  tetrahedral: 'cubic',
  quarter_cubic: 'cubic',
  concentric: 'concentric',
  gyroid: 'gyroid',
  lightning: 'lightning',
  cross: 'grid',
  cross_3d: 'grid',
};
const CURA_SKIN: Readonly<Record<string, Settings['topSkinPattern']>> = {
  lines: 'lines',
  zigzag: 'lines',
  concentric: 'concentric',
};
const SUPPORT_PATTERN: Readonly<Record<string, Settings['supportPattern']>> = {
  zigzag: 'zigzag',
  lines: 'lines',
  grid: 'grid',
};
const SEAM: Readonly<Record<string, Settings['seamPosition']>> = {
  back: 'rear',
  shortest: 'nearest',
  random: 'random',
  sharpest_corner: 'aligned',
};
const FLAVOR: Readonly<Record<string, Settings['gcodeFlavor']>> = {
  'RepRap (Marlin/Sprinter)': 'marlin',
  'RepRap (Volumetric)': 'marlin',
  'RepRap (RepRap)': 'reprap',
  Repetier: 'marlin',
};

/** Keys a Cura key falls back to (Cura's `value` formulas that are plain copies or scalings). */
const FALLBACK: Readonly<Record<string, { from: string; scale?: number }>> = {
  speed_infill: { from: 'speed_print' },
  speed_wall: { from: 'speed_print', scale: 0.5 },
  speed_wall_0: { from: 'speed_wall' },
  speed_wall_x: { from: 'speed_wall', scale: 2 },
  speed_topbottom: { from: 'speed_print', scale: 0.5 },
  speed_layer_0: { from: 'speed_print', scale: 0.5 },
  speed_print_layer_0: { from: 'speed_layer_0' },
  wall_line_width: { from: 'line_width' },
  wall_line_width_0: { from: 'wall_line_width' },
  top_thickness: { from: 'top_bottom_thickness' },
  bottom_thickness: { from: 'top_bottom_thickness' },
  material_print_temperature: { from: 'default_material_print_temperature' },
  material_print_temperature_layer_0: { from: 'material_print_temperature' },
  material_bed_temperature: { from: 'default_material_bed_temperature' },
  material_bed_temperature_layer_0: { from: 'material_bed_temperature' },
  retraction_retract_speed: { from: 'retraction_speed' },
  cool_fan_speed_min: { from: 'cool_fan_speed' },
};

/** A tiny evaluator for Cura's arithmetic formulas; identifiers resolve through `lookup`. */
function evaluate(expr: string, lookup: (name: string) => number | undefined): number | undefined {
  const tokens = expr.match(/\d+\.?\d*(?:e[+-]?\d+)?|\.\d+|[A-Za-z_][A-Za-z0-9_.]*|\*\*|[-+*/(),]/g);
  if (!tokens || tokens.join('') !== expr.replace(/\s+/g, '')) return undefined;
  let i = 0;
  const peek = () => tokens[i];
  const expression = (): number | undefined => {
    let v = term();
    while (v !== undefined && (peek() === '+' || peek() === '-')) {
      const op = tokens[i++];
      const r = term();
      v = r === undefined ? undefined : op === '+' ? v + r : v - r;
    }
    return v;
  };
  const term = (): number | undefined => {
    let v = factor();
    while (v !== undefined && (peek() === '*' || peek() === '/')) {
      const op = tokens[i++];
      const r = factor();
      v = r === undefined ? undefined : op === '*' ? v * r : r === 0 ? undefined : v / r;
    }
    return v;
  };
  const FUNCTIONS: Record<string, (...a: number[]) => number> = {
    min: Math.min,
    max: Math.max,
    round: (x, d = 0) => Math.round(x * 10 ** d) / 10 ** d,
    'math.ceil': Math.ceil,
    'math.floor': Math.floor,
    abs: Math.abs,
  };
  const factor = (): number | undefined => {
    const t = tokens[i++];
    if (t === undefined) return undefined;
    if (t === '-') {
      const v = factor();
      return v === undefined ? undefined : -v;
    }
    if (t === '(') {
      const v = expression();
      return tokens[i++] === ')' ? v : undefined;
    }
    if (/^[\d.]/.test(t)) return Number(t);
    if (FUNCTIONS[t] && peek() === '(') {
      i++;
      const args: number[] = [];
      for (;;) {
        const a = expression();
        if (a === undefined) return undefined;
        args.push(a);
        const sep = tokens[i++];
        if (sep === ')') break;
        if (sep !== ',') return undefined;
      }
      return FUNCTIONS[t]!(...args);
    }
    if (/^[A-Za-z_]/.test(t)) return lookup(t);
    return undefined;
  };
  const v = expression();
  return i === tokens.length && v !== undefined && Number.isFinite(v) ? v : undefined;
}

/**
 * Cura's overhanging walls (`wall_overhang_angle`, 90° = off): a wall point whose overhang is steeper than
 * that angle prints at a share of its speed, the range up to 90° cut into equal steps of angle, one share each
 * (Cura 5.10's `wall_overhang_speed_factors`, a list; one share before, `wall_overhang_speed_factor`).
 * CuraEngine measures the angle of the outer wall's centreline against the layer below shrunk by half a
 * wall: a line with the share f of its width over nothing overhangs at atan(f × width / layer height). Each
 * of Strata's steps (a quarter, half, three quarters and all of the line over nothing) takes the speed Cura
 * gives the least overhanging line of that step, as a share of the outer wall's speed.
 */
function overhangSpeeds(
  c: ImportContext,
  str: (key: string) => string | undefined,
  value: (key: string) => number | undefined,
  layerHeight: number,
): void {
  const angle = value('wall_overhang_angle');
  const list = str('wall_overhang_speed_factors');
  const single = list === undefined ? value('wall_overhang_speed_factor') : undefined;
  const shares =
    list !== undefined
      ? (/^\[([\d.\s,]*)\]$/.exec(list)?.[1] ?? '')
          .split(',')
          .filter((v) => v.trim() !== '')
          .map(Number)
      : single !== undefined
        ? [single]
        : [];
  if (angle === undefined || angle >= 90) return;
  const from = c.has('wall_overhang_speed_factors') ? 'wall_overhang_speed_factors' : 'wall_overhang_speed_factor';
  if (shares.length === 0 || shares.some((v) => !(v > 0))) return c.reject(from, 'not a list of speed factors (%)');
  const outer = c.settings.perimeterSpeed ?? (SCHEMA.perimeterSpeed.default as number);
  const width = c.settings.lineWidth ?? c.settings.nozzleDiameter ?? (SCHEMA.nozzleDiameter.default as number);
  const step = (90 - angle) / shares.length;
  const speedAt = (share: number) => {
    const deg = (Math.atan((share * width) / layerHeight) * 180) / Math.PI;
    const f = deg < angle ? 100 : shares[Math.min(shares.length - 1, Math.floor((deg - angle) / step))]!;
    return Math.round(outer * f) / 100;
  };
  c.set('dynamicOverhangSpeeds', true, 'wall_overhang_angle');
  const key = `wall_overhang_angle + ${from}`;
  c.set('overhangSpeed25', speedAt(0.25), key);
  c.set('overhangSpeed50', speedAt(0.5), key);
  c.set('overhangSpeed75', speedAt(0.75), key);
  c.set('overhangWallSpeed', speedAt(1), key);
}

/** Round to `d` decimals. */
function round(v: number, d = 4): number {
  return Math.round(v * 10 ** d) / 10 ** d;
}

/**
 * A skin pattern: lines and zigzag are lines (monotonic with `monotonic` true), concentric concentric;
 * a pattern the profile does not give is lines.
 */
function skinPattern(
  pattern: string | undefined,
  monotonic: string | undefined,
): Settings['topSkinPattern'] | undefined {
  const id = CURA_SKIN[pattern ?? 'lines'];
  return id === 'lines' && bool(monotonic) ? 'monotonic' : id;
}

/** What every topic's mapping shares: the import and the ways to read its keys. */
interface CuraKeys {
  readonly c: ImportContext;
  /** The number a Cura key stands for: its value, its formula, or its fallback. */
  readonly value: (key: string) => number | undefined;
  /** The text of a key, unless it is a formula. */
  readonly str: (key: string) => string | undefined;
  /** Set `setting` from the first of `keys` that has a value (given or by fallback). */
  readonly take: <K extends keyof Settings>(setting: K, keys: string[], convert?: (v: number) => Settings[K]) => void;
}

/** The shared readers of the Cura keys of `c`. */
function curaKeys(c: ImportContext): CuraKeys {
  const resolving = new Set<string>();
  /** The number a Cura key stands for: its value, its formula, or its fallback. */
  const value = (key: string): number | undefined => {
    if (resolving.has(key)) return undefined;
    resolving.add(key);
    try {
      const raw = c.get(key);
      if (raw !== undefined) {
        const v = raw.trim();
        if (v.startsWith('=')) return evaluate(v.slice(1).trim(), value);
        if (/^(true|false)$/i.test(v)) return v.toLowerCase() === 'true' ? 1 : 0;
        const n = Number(v.replace(/%$/, ''));
        if (Number.isFinite(n) && v !== '') return n;
        const list = /^\[\s*(-?[\d.]+)/.exec(v); // e.g. infill_angles = [45, 135]
        return list ? Number(list[1]) : undefined;
      }
      const fb = FALLBACK[key];
      if (fb) {
        const v = value(fb.from);
        return v === undefined ? undefined : v * (fb.scale ?? 1);
      }
      return undefined;
    } finally {
      resolving.delete(key);
    }
  };
  const str = (key: string) => {
    const raw = c.get(key)?.trim();
    return raw === undefined || raw.startsWith('=') ? undefined : raw;
  };
  /** Set `setting` from the first of `keys` that has a value (given or by fallback). */
  const take = <K extends keyof Settings>(
    setting: K,
    keys: string[],
    convert: (v: number) => Settings[K] = (v) => v as Settings[K],
  ) => {
    for (const key of keys) {
      const present = c.has(key);
      const v = value(key);
      if (v !== undefined) return c.set(setting, convert(v), key);
      if (present) return c.reject(key, 'a formula Strata cannot evaluate');
    }
  };
  return { c, value, str, take };
}

/** The machine: bed, nozzle, filament, firmware switches, G-code flavour and start and end G-code. */
function mapMachine(m: CuraKeys): void {
  const { c, str, take } = m;
  take('buildPlateWidth', ['machine_width']);
  take('buildPlateLength', ['machine_depth']);
  take('buildVolumeHeight', ['machine_height']);
  take('nozzleDiameter', ['machine_nozzle_size']);
  take('filamentDiameter', ['material_diameter']);
  for (const [key, setting] of [
    ['machine_center_is_zero', 'originAtCenter'],
    ['machine_heated_bed', 'heatedBed'],
    ['machine_firmware_retract', 'firmwareRetraction'],
  ] as const) {
    const v = str(key);
    if (v !== undefined) c.set(setting, bool(v), key, 'not True or False');
  }
  const rel = str('relative_extrusion');
  if (rel !== undefined) c.set('extruderMode', bool(rel) ? 'relative' : 'absolute', 'relative_extrusion');
  const flavor = str('machine_gcode_flavor');
  if (flavor !== undefined)
    c.set('gcodeFlavor', FLAVOR[flavor], 'machine_gcode_flavor', `G-code flavour "${flavor}" has no Strata equivalent`);
  // templates, kept as written (templates.ts)
  for (const [key, setting] of [
    ['machine_start_gcode', 'startGcode'],
    ['machine_end_gcode', 'endGcode'],
  ] as const) {
    importTemplate(c, [key], setting, (v) => v.replace(/^"""|"""$/g, ''));
  }
}

/** The machine's limits: feed rates, accelerations and jerk, and the print acceleration. */
function mapMachineLimits(m: CuraKeys): void {
  const { c, str, take } = m;
  take('maxSpeedX', ['machine_max_feedrate_x']);
  take('maxSpeedY', ['machine_max_feedrate_y']);
  take('maxSpeedZ', ['machine_max_feedrate_z']);
  take('maxSpeedE', ['machine_max_feedrate_e']);
  take('maxAccelerationX', ['machine_max_acceleration_x']);
  take('maxAccelerationY', ['machine_max_acceleration_y']);
  take('maxAccelerationZ', ['machine_max_acceleration_z']);
  take('maxAccelerationE', ['machine_max_acceleration_e']);
  take('cornerVelocity', ['machine_max_jerk_xy']);
  take('jerkX', ['machine_max_jerk_xy']);
  take('jerkY', ['machine_max_jerk_xy']);
  take('jerkZ', ['machine_max_jerk_z']);
  take('jerkE', ['machine_max_jerk_e']);
  const accelOn = str('acceleration_enabled');
  if (accelOn !== undefined ? bool(accelOn) : c.has('acceleration_print')) take('acceleration', ['acceleration_print']);
  else take('acceleration', ['machine_acceleration']);
}

/** Layer heights and adaptive layers; returns the layer height the other mappings use. */
function mapLayers(m: CuraKeys): number {
  const { c, value, str, take } = m;
  take('layerHeight', ['layer_height']);
  take('firstLayerHeight', ['layer_height_0']);
  const layerHeight = c.settings.layerHeight ?? (SCHEMA.layerHeight.default as number);
  // adaptive layers: up to `variation` thinner or thicker than the layer height, changing by at most the step
  const adaptive = str('adaptive_layer_height_enabled');
  if (adaptive !== undefined)
    c.set('adaptiveLayerHeight', bool(adaptive), 'adaptive_layer_height_enabled', 'not true or false');
  const variation = value('adaptive_layer_height_variation');
  if (variation !== undefined) {
    c.set(
      'minLayerHeight',
      round(Math.max(0.02, layerHeight - variation)),
      'adaptive_layer_height_variation layer_height',
    );
    // (within what the nozzle allows: Cura does not cap it)
    const nozzle = c.settings.nozzleDiameter ?? (SCHEMA.nozzleDiameter.default as number);
    c.set(
      'maxLayerHeight',
      round(Math.min(layerHeight + variation, 0.85 * nozzle)),
      'adaptive_layer_height_variation layer_height',
    );
  }
  take('adaptiveLayerStep', ['adaptive_layer_height_variation_step']);
  // Cura's threshold is the horizontal distance between layer edges it aims for: no Strata equivalent
  if (c.has('adaptive_layer_height_threshold'))
    c.reject(
      'adaptive_layer_height_threshold',
      "Cura's target distance between layer edges has no Strata equivalent (adaptiveLayerQuality sets the stair-step depth)",
    );
  return layerHeight;
}

/** Line widths, wall count, top and bottom thickness, wall order, seam and skin overlap. */
function mapWallsAndSkins(m: CuraKeys, layerHeight: number): void {
  const { c, value, str, take } = m;
  take('lineWidth', ['line_width', 'wall_line_width', 'wall_line_width_0']);
  const factor = value('initial_layer_line_width_factor');
  if (factor !== undefined) {
    const w = c.settings.lineWidth ?? c.settings.nozzleDiameter ?? (SCHEMA.nozzleDiameter.default as number);
    c.set('firstLayerLineWidth', round((w * factor) / 100), 'initial_layer_line_width_factor');
  }
  if (c.has('wall_line_count')) take('wallCount', ['wall_line_count'], (v) => Math.round(v));
  else take('shellWallThickness', ['wall_thickness']);
  for (const [side, setting] of [
    ['top', 'topSkinThickness'],
    ['bottom', 'bottomSkinThickness'],
  ] as const) {
    if (c.has(`${side}_layers`)) take(setting, [`${side}_layers`], (n) => round(n * layerHeight));
    else take(setting, [`${side}_thickness`]);
  }
  const outerFirst = str('outer_inset_first');
  if (outerFirst !== undefined)
    c.set('wallOrder', bool(outerFirst) ? 'outer-first' : 'inner-first', 'outer_inset_first');
  const seam = str('z_seam_type');
  if (seam !== undefined) c.set('seamPosition', SEAM[seam], 'z_seam_type', `seam "${seam}" has no Strata equivalent`);
  take('skinOverlap', ['skin_overlap']);
}

/** Scarf seam, fuzzy skin and spiral vase. */
function mapSeamAndSurface(m: CuraKeys): void {
  const { c, value, str, take } = m;
  // scarf seam (Cura 5.9: the outer wall only; a length of 0 is none) and fuzzy skin
  const scarf = value('scarf_joint_seam_length');
  if (scarf !== undefined) {
    c.set('scarfSeam', scarf > 0 ? 'outer' : 'off', 'scarf_joint_seam_length');
    if (scarf > 0) c.set('scarfLength', scarf, 'scarf_joint_seam_length');
  }
  take('scarfStartHeight', ['scarf_joint_seam_start_height_ratio']);
  const split = value('scarf_split_distance');
  if (split !== undefined && split > 0) {
    const length = c.settings.scarfLength ?? (SCHEMA.scarfLength.default as number);
    c.set(
      'scarfSteps',
      Math.min(SCHEMA.scarfSteps.max, Math.max(1, Math.ceil(length / split - WHOLE_QUOTIENT_EPS))),
      'scarf_split_distance',
    );
  }
  const fuzzy = str('magic_fuzzy_skin_enabled');
  if (fuzzy !== undefined) {
    const outside = bool(str('magic_fuzzy_skin_outside_only'));
    c.set(
      'fuzzySkin',
      bool(fuzzy) === undefined ? undefined : bool(fuzzy) ? (outside ? 'outer' : 'all') : 'off',
      'magic_fuzzy_skin_enabled',
      'not True or False',
    );
  }
  // spiralize: Cura's spiral vase mode
  const spiral = str('magic_spiralize');
  if (spiral !== undefined) c.set('spiralVase', bool(spiral), 'magic_spiralize', 'not True or False');
  take('fuzzySkinThickness', ['magic_fuzzy_skin_thickness']);
  if (c.has('magic_fuzzy_skin_point_dist')) take('fuzzySkinPointDistance', ['magic_fuzzy_skin_point_dist']);
  else take('fuzzySkinPointDistance', ['magic_fuzzy_skin_point_density'], (perMm) => round(1 / perMm));
}

/** Cura 5's variable-width (Arachne) walls, its mm turned into % of the nozzle. */
function mapVariableWalls(m: CuraKeys): void {
  const { c, take } = m;
  const arachne = [
    'min_feature_size',
    'min_bead_width',
    'wall_transition_length',
    'wall_transition_angle',
    'wall_distribution_count',
  ].find((k) => c.has(k));
  if (arachne !== undefined) c.set('wallGenerator', 'variable', arachne);
  const nozzle = c.settings.nozzleDiameter ?? (SCHEMA.nozzleDiameter.default as number);
  take('minFeatureSize', ['min_feature_size'], (mm) => percentOfNozzle(mm, nozzle));
  take('minBeadWidth', ['min_bead_width'], (mm) => percentOfNozzle(mm, nozzle));
  take('wallTransitionLength', ['wall_transition_length'], (mm) => percentOfNozzle(mm, nozzle));
  take('wallTransitionAngle', ['wall_transition_angle']);
  take('wallDistributionCount', ['wall_distribution_count'], (v) => Math.round(v));
}

/** Infill density, pattern, angle and overlap. */
function mapInfill(m: CuraKeys): void {
  const { c, str, take } = m;
  take('infillDensity', ['infill_sparse_density']);
  const pattern = str('infill_pattern');
  if (pattern !== undefined) {
    const id =
      INFILL[pattern] ?? ((PATTERN_IDS as readonly string[]).includes(pattern) ? (pattern as PatternId) : undefined);
    c.set('infillPattern', id, 'infill_pattern', `pattern "${pattern}" has no Strata equivalent`);
  }
  take('infillAngle', ['infill_angles']);
  take('infillOverlap', ['infill_overlap']);
}

/** Skin patterns of the top (from the roofing) and bottom skins. */
function mapSkinPatterns(m: CuraKeys): void {
  const { c, value, str } = m;
  // the top skin takes the roofing's pattern (Cura's topmost skin layers) unless the profile has no roofing layers
  const bottomKey = ['top_bottom_pattern', 'skin_monotonic'].find((k) => c.has(k));
  const base = str('top_bottom_pattern'),
    monotonic = str('skin_monotonic');
  if (bottomKey)
    c.set(
      'bottomSkinPattern',
      skinPattern(base, monotonic),
      bottomKey,
      `pattern "${base}" has no Strata skin equivalent (lines, zigzag, concentric)`,
    );
  const roofKeys = ['roofing_pattern', 'roofing_monotonic'].filter((k) => c.has(k));
  const roofing = value('roofing_layer_count') !== 0;
  if (roofing && roofKeys.length) {
    const roof = str('roofing_pattern') ?? base;
    c.set(
      'topSkinPattern',
      skinPattern(roof, str('roofing_monotonic') ?? monotonic),
      roofKeys[0]!,
      `pattern "${roof}" has no Strata skin equivalent (lines, zigzag, concentric)`,
    );
  } else if (bottomKey) c.set('topSkinPattern', c.settings.bottomSkinPattern, bottomKey);
  for (const k of roofing ? [] : roofKeys) c.reject(k, 'roofing_layer_count is 0: no layer is roofing');
  const initial = str('top_bottom_pattern_0');
  if (
    initial !== undefined &&
    CURA_SKIN[initial] !==
      (c.settings.bottomSkinPattern === 'monotonic' ? 'lines' : (c.settings.bottomSkinPattern ?? 'lines'))
  ) {
    c.reject(
      'top_bottom_pattern_0',
      "Strata's bottom skin has one pattern on every layer (bottomSkinPattern, from top_bottom_pattern)",
    );
  }
}

/** Ironing: on or off, which layers, spacing, speed and flow. */
function mapIroning(m: CuraKeys): void {
  const { c, value, str, take } = m;
  // its flow is a share of a skin line's in Cura, of a line as wide as the ironing's spacing in Strata
  const ironing = str('ironing_enabled');
  if (ironing !== undefined) c.set('ironingEnabled', bool(ironing), 'ironing_enabled', 'not True or False');
  const highest = str('ironing_only_highest_layer');
  if (highest !== undefined)
    c.set(
      'ironingType',
      bool(highest) === undefined ? undefined : bool(highest) ? 'topmost' : 'top',
      'ironing_only_highest_layer',
      'not True or False',
    );
  take('ironingSpacing', ['ironing_line_spacing']);
  take('ironingSpeed', ['speed_ironing']);
  const ironingFlow = value('ironing_flow');
  if (ironingFlow !== undefined) {
    const skinWidth =
      value('skin_line_width') ??
      c.settings.lineWidth ??
      c.settings.nozzleDiameter ??
      (SCHEMA.nozzleDiameter.default as number);
    const spacing = c.settings.ironingSpacing ?? (SCHEMA.ironingSpacing.default as number);
    c.set('ironingFlow', round((ironingFlow * skinWidth) / spacing, 2), 'ironing_flow');
  } else if (c.has('ironing_flow')) c.reject('ironing_flow', 'a formula Strata cannot evaluate');
}

/** Print and travel speeds, and the overhanging walls' speeds. */
function mapSpeeds(m: CuraKeys, layerHeight: number): void {
  const { c, value, str, take } = m;
  take('perimeterSpeed', ['speed_wall_0']);
  take('innerWallSpeed', ['speed_wall_x']);
  take('skinSpeed', ['speed_topbottom']);
  take('infillSpeed', ['speed_infill']);
  take('firstLayerSpeed', ['speed_print_layer_0', 'speed_layer_0']);
  take('travelSpeed', ['speed_travel']);
  take('firstLayerTravelSpeed', ['speed_travel_layer_0']);
  overhangSpeeds(c, str, value, layerHeight);
}

/** Temperatures, fan and cooling, and flow. */
function mapTemperaturesAndCooling(m: CuraKeys): void {
  const { c, value, str, take } = m;
  take('nozzleTemperature', ['material_print_temperature']);
  if (c.has('material_print_temperature_layer_0'))
    take('firstLayerNozzleTemperature', ['material_print_temperature_layer_0']);
  else if (c.has('material_initial_print_temperature'))
    take('firstLayerNozzleTemperature', ['material_initial_print_temperature']);
  take('bedTemperature', ['material_bed_temperature']);
  if (c.has('material_bed_temperature_layer_0')) take('firstLayerBedTemperature', ['material_bed_temperature_layer_0']);
  const fanOn = str('cool_fan_enabled');
  if (fanOn !== undefined && bool(fanOn) === false) c.set('fanSpeed', 0, 'cool_fan_enabled');
  else take('fanSpeed', ['cool_fan_speed_min', 'cool_fan_speed']);
  take('firstLayerFanSpeed', ['cool_fan_speed_0']);
  // Cura numbers layers from 1 here: cool_fan_full_layer 2 is the second layer, index 1
  const fullLayer = value('cool_fan_full_layer');
  if (fullLayer !== undefined) c.set('fanFullLayer', Math.max(0, Math.round(fullLayer) - 1), 'cool_fan_full_layer');
  take('maxFanSpeed', ['cool_fan_speed_max']);
  take('fanBelowLayerTime', ['cool_min_layer_time_fan_speed_max']);
  take('minLayerTime', ['cool_min_layer_time']);
  take('minPrintSpeed', ['cool_min_speed']);
  take('flowRate', ['material_flow']);
}

/** Retraction, combing, retraction at layer change, z-hop and the retraction limits. */
function mapRetraction(m: CuraKeys): void {
  const { c, value, str, take } = m;
  const retract = str('retraction_enable');
  if (retract !== undefined) c.set('retractionEnabled', bool(retract), 'retraction_enable', 'not True or False');
  take('retractionDistance', ['retraction_amount']);
  take('retractionSpeed', ['retraction_retract_speed', 'retraction_speed']);
  const primeVolume = value('retraction_extra_prime_amount');
  if (primeVolume !== undefined) {
    const d = c.settings.filamentDiameter ?? (SCHEMA.filamentDiameter.default as number);
    c.set('retractionExtraPrime', round(primeVolume / (Math.PI * (d / 2) ** 2)), 'retraction_extra_prime_amount');
  }
  take('retractionMinTravel', ['retraction_min_travel']);
  // combing: 'off' travels straight and retracts by length; every other mode keeps travels inside without retracting
  const combingMode = str('retraction_combing');
  if (combingMode !== undefined) {
    const on = combingMode !== 'off';
    c.set('combing', on, 'retraction_combing');
    c.set('retractCrossingWallsOnly', on, 'retraction_combing');
  }
  take('combingMaxDistance', ['retraction_combing_max_distance']);
  const layerChange = str('retract_at_layer_change');
  if (layerChange !== undefined)
    c.set('retractOnLayerChange', bool(layerChange), 'retract_at_layer_change', 'not True or False');
  const hop = str('retraction_hop_enabled');
  if (hop !== undefined && bool(hop) === false) c.set('zHop', 0, 'retraction_hop_enabled');
  else if (hop !== undefined || c.has('retraction_hop')) take('zHop', ['retraction_hop']);
  take('zHopSpeed', ['speed_z_hop']);
  const hopOver = str('retraction_hop_only_when_collides');
  if (hopOver !== undefined)
    c.set('zHopOnlyOverParts', bool(hopOver), 'retraction_hop_only_when_collides', 'not True or False');
  // Cura's count 0 means no retraction but the forced ones; Strata's 0 means no limit
  const countMax = value('retraction_count_max');
  if (countMax === 0)
    c.reject(
      'retraction_count_max',
      'Cura retracts only where it must with 0; Strata has no such setting (its 0 is no limit)',
    );
  else if (countMax !== undefined) c.set('retractionCountMax', Math.round(countMax), 'retraction_count_max');
  else if (c.has('retraction_count_max')) c.reject('retraction_count_max', 'a formula Strata cannot evaluate');
  take('retractionExtrusionWindow', ['retraction_extrusion_window']);
}

/** Coasting: off unless coasting_enable. */
function mapCoasting(m: CuraKeys): void {
  const { c, str, take } = m;
  const coasting = str('coasting_enable');
  if (coasting !== undefined && bool(coasting) === false) c.set('coastingVolume', 0, 'coasting_enable');
  else if (coasting !== undefined) take('coastingVolume', ['coasting_volume']);
  take('coastingMinVolume', ['coasting_min_volume']);
}

/** Adhesion type, skirt, brim and raft margin. */
function mapAdhesion(m: CuraKeys): void {
  const { c, str, take } = m;
  const adhesion = str('adhesion_type');
  if (adhesion !== undefined) {
    const map: Record<string, Settings['adhesionType']> = { skirt: 'skirt', brim: 'brim', raft: 'raft', none: 'none' };
    c.set(
      'adhesionType',
      map[adhesion],
      'adhesion_type',
      `adhesion "${adhesion}" has no Strata equivalent (skirt, brim, raft, none)`,
    );
  }
  take('skirtLoops', ['skirt_line_count'], (v) => Math.round(v));
  take('skirtDistance', ['skirt_gap']);
  take('brimWidth', ['brim_width']);
  take('raftMargin', ['raft_margin']);
}

/** One at a time printing and the head's clearances, then the raft's air gap. */
function mapPrintSequence(m: CuraKeys): void {
  const { c, str, take } = m;
  // one at a time: Cura's gantry height as the clearance height; the print head's outline (with its fans,
  // round the nozzle) as the radius of the circle round the nozzle that holds it
  const sequence = str('print_sequence');
  if (sequence !== undefined) {
    const on = sequence === 'one_at_a_time' ? true : sequence === 'all_at_once' ? false : undefined;
    c.set(
      'sequentialPrinting',
      on,
      'print_sequence',
      `print sequence "${sequence}" has no Strata equivalent (all_at_once, one_at_a_time)`,
    );
  }
  take('extruderClearanceHeight', ['gantry_height']);
  const head = str('machine_head_with_fans_polygon');
  if (head !== undefined) {
    const corners = [...head.matchAll(/\[\s*(-?[\d.]+)\s*,\s*(-?[\d.]+)\s*\]/g)].map((corner) =>
      Math.hypot(Number(corner[1]), Number(corner[2])),
    );
    const reach = corners.length >= 3 && corners.every(Number.isFinite) ? round(Math.max(...corners), 2) : undefined;
    c.set('extruderClearanceRadius', reach, 'machine_head_with_fans_polygon', 'not a list of [x, y] corners');
  }
  take('raftAirGap', ['raft_airgap']);
}

/** Support: on or off, structure, placement, angle, pattern, density and gaps. */
function mapSupport(m: CuraKeys): void {
  const { c, str, take } = m;
  // support: Cura's overhang angle is measured from vertical, as Strata's; interface heights become layers
  flag(m, 'support_enable', 'supportEnabled');
  const structure = str('support_structure');
  if (structure !== undefined) {
    c.set(
      'supportType',
      structure === 'tree' || structure === 'normal' ? structure : undefined,
      'support_structure',
      `support structure "${structure}" has no Strata equivalent (normal, tree)`,
    );
  }
  const placement = str('support_type');
  if (placement !== undefined) {
    const map: Record<string, Settings['supportPlacement']> = { buildplate: 'buildPlate', everywhere: 'everywhere' };
    c.set(
      'supportPlacement',
      map[placement],
      'support_type',
      `support placement "${placement}" has no Strata equivalent (buildplate, everywhere)`,
    );
  }
  take('supportThreshold', ['support_angle']);
  const supportPattern = str('support_pattern');
  if (supportPattern !== undefined)
    c.set(
      'supportPattern',
      SUPPORT_PATTERN[supportPattern],
      'support_pattern',
      `support pattern "${supportPattern}" has no Strata equivalent (zigzag, lines, grid)`,
    );
  take('supportDensity', ['support_infill_rate']);
  take('supportZGap', ['support_top_distance', 'support_z_distance']);
  take('supportBottomZGap', ['support_bottom_distance']);
  take('supportXYGap', ['support_xy_distance']);
}

/** Support roofs and floors, interface density, line width, speeds, walls and minimum area. */
function mapSupportLayers(m: CuraKeys, layerHeight: number): void {
  const { c, str, take } = m;
  // roof and floor: on (Cura's default is off) for their height in layers, else none
  for (const [side, setting] of [
    ['roof', 'supportInterfaceLayers'],
    ['bottom', 'supportFloorLayers'],
  ] as const) {
    const key = c.has(`support_${side}_enable`) ? `support_${side}_enable` : 'support_interface_enable';
    const on = str(key);
    if (on !== undefined && bool(on) === false) c.set(setting, 0, key);
    else if (on !== undefined || c.has(`support_${side}_height`) || c.has('support_interface_height')) {
      take(setting, [`support_${side}_height`, 'support_interface_height'], (h) => Math.round(h / layerHeight));
    }
  }
  take('supportInterfaceDensity', ['support_roof_density', 'support_interface_density']);
  take('supportLineWidth', ['support_line_width']);
  take('supportSpeed', ['speed_support_infill', 'speed_support']);
  take('supportInterfaceSpeed', ['speed_support_roof', 'speed_support_interface']);
  take('supportWallCount', ['support_wall_count'], (v) => Math.round(v));
  take('supportMinArea', ['minimum_support_area']);
}

/** Tree support branches, then whether support travels limit retractions. */
function mapTreeSupport(m: CuraKeys): void {
  const { c, take } = m;
  take('supportTreeBranchAngle', ['support_tree_angle']);
  take('supportTreeBranchDiameter', ['support_tree_branch_diameter']);
  take('supportTreeTipDiameter', ['support_tree_tip_diameter']);
  take('supportTreeDiameterAngle', ['support_tree_branch_diameter_angle']);
  take('supportTreeTipSpacing', ['support_tree_branch_distance']);
  // Cura 5's branch density
  if (!c.has('support_tree_branch_distance')) {
    const lw = c.settings.supportLineWidth ?? c.settings.lineWidth ?? 0.4;
    take(
      'supportTreeTipSpacing',
      ['support_tree_top_rate'],
      (v) => tipSpacingOfDensity(lw, v) as Settings['supportTreeTipSpacing'],
    );
  }
  flag(m, 'limit_support_retractions', 'supportLimitRetractions');
}

/** Set a support switch from a True/False key. */
function flag(m: CuraKeys, key: string, setting: 'supportEnabled' | 'supportLimitRetractions'): void {
  const { c, str } = m;
  const v = str(key);
  if (v !== undefined) c.set(setting, bool(v), key, 'not True or False');
}

/** Map the Cura keys of `c` onto Strata settings (in this order: later mappings read earlier ones). */
export function mapCuraKeys(c: ImportContext): void {
  const m = curaKeys(c);
  mapMachine(m);
  mapMachineLimits(m);
  const layerHeight = mapLayers(m);
  mapWallsAndSkins(m, layerHeight);
  mapSeamAndSurface(m);
  mapVariableWalls(m);
  mapInfill(m);
  mapSkinPatterns(m);
  mapIroning(m);
  mapSpeeds(m, layerHeight);
  mapTemperaturesAndCooling(m);
  mapRetraction(m);
  mapCoasting(m);
  mapAdhesion(m);
  mapPrintSequence(m);
  mapSupport(m);
  mapSupportLayers(m, layerHeight);
  mapTreeSupport(m);
}
