/**
 * Validation and resolution of settings: defaults < printer preset < filament preset < caller options,
 * checked against the schema and resolved once into a frozen typed config with derived values.
 */
import { StrataError } from '../errors.js';
import { SCHEMA, SETTING_KEYS, type SettingDef, type SettingKey, type Settings, type SliceOptions } from './schema.js';
import { findFilament, findPrinter, listPresets, printerWithoutPreset } from './presets/index.js';
import { LAYER_SHARE_EPS, WHOLE_QUOTIENT_EPS } from '../geometry/tolerances.js';

/**
 * The settings whose empty (null) value is derived from others: the config holds each only resolved, under
 * the name Derived gives it (the same name where it says the unit already: wallCount, the first-layer
 * temperatures, supportFloorLayers, supportWallCount), never beside its empty form.
 */
const RESOLVED = [
  'lineWidth',
  'firstLayerLineWidth',
  'wallCount',
  'topSkinThickness',
  'bottomSkinThickness',
  'firstLayerNozzleTemperature',
  'firstLayerBedTemperature',
  'supportLineWidth',
  'supportFloorLayers',
  'supportWallCount',
  'supportTreeTipSpacing',
  'raftBaseLineWidth',
  'raftBaseLineSpacing',
  'raftInterfaceLineSpacing',
  'minLayerHeight',
  'maxLayerHeight',
] as const satisfies readonly SettingKey[];
type ResolvedKey = (typeof RESOLVED)[number];

/** Values computed once from the settings; algorithms read these rather than re-deriving them. */
export interface Derived {
  /** Line width (lineWidth, or the nozzle's diameter), mm. */
  lineWidthMm: number;
  /** The first layer's line width (firstLayerLineWidth, or lineWidthMm), mm. */
  firstLayerLineWidthMm: number;
  /** Walls round each island: wallCount, or as many line widths as make shellWallThickness. */
  wallCount: number;
  /** Top and bottom skin thickness (their own, or shellSkinThickness), mm. */
  topSkinThicknessMm: number;
  bottomSkinThicknessMm: number;
  /** Layers of the layer height that make the top and bottom skin thickness. */
  topLayers: number;
  bottomLayers: number;
  /** The first layer's temperatures (their own, or the other layers'), °C. */
  firstLayerNozzleTemperature: number;
  firstLayerBedTemperature: number;
  printerId: string;
  filamentId: string;
  /** Support line width, mm. */
  supportLineWidthMm: number;
  /** Layers left empty between the support's top and the part above / between the part and support on it. */
  supportTopGapLayers: number;
  supportBottomGapLayers: number;
  /** Dense layers where support stands on the part (supportFloorLayers, or supportInterfaceLayers). */
  supportFloorLayers: number;
  /** Walls round support (supportWallCount, or 1 round a tree's branches and 0 round normal support). */
  supportWallCount: number;
  /** Walls round straight support columns (normal support's, and a tree's under its pockets). */
  supportColumnWallCount: number;
  /** Distance between tree-support tips, mm. */
  supportTreeTipSpacingMm: number;
  /** Raft base line width and spacing, interface line spacing, mm. */
  raftBaseLineWidthMm: number;
  raftBaseLineSpacingMm: number;
  raftInterfaceLineSpacingMm: number;
  /** Adaptive layer height's limits (minLayerHeight, maxLayerHeight resolved), mm. */
  minLayerHeightMm: number;
  maxLayerHeightMm: number;
  /**
   * The settings as they were given (schema defaults, presets and options merged, empty ones still empty):
   * what is written back out as settings (G-code templates and the writer, project files, the API's getters).
   * The slicer's stages read the resolved fields, never these.
   */
  settings: Readonly<Settings>;
}

/** The resolved settings of a print, an object or a region: the settings less their empty forms, and Derived. */
export type Config = Readonly<Omit<Settings, ResolvedKey> & Derived>;

/** Tree-support tips this far apart hold a roof; with no roof they hold the part itself, closer together (CuraEngine 4.13: 1 mm; PrusaSlicer's 15 % tip density: about 2 mm). */
export const TREE_TIP_SPACING_UNDER_ROOF_MM = 3;
export const TREE_TIP_SPACING_NO_ROOF_MM = 1.5;

export const DEFAULT_PRINTER = 'creality-ender-3';
export const DEFAULT_FILAMENT = 'pla';

/** Levenshtein distance, for "did you mean" suggestions. */
function editDistance(a: string, b: string): number {
  const prev = new Array<number>(b.length + 1);
  for (let j = 0; j <= b.length; j++) prev[j] = j;
  for (let i = 1; i <= a.length; i++) {
    let diag = prev[0];
    prev[0] = i;
    for (let j = 1; j <= b.length; j++) {
      const tmp = prev[j];
      prev[j] = Math.min(prev[j] + 1, prev[j - 1] + 1, diag + (a[i - 1] === b[j - 1] ? 0 : 1));
      diag = tmp;
    }
  }
  return prev[b.length];
}

export function suggest(word: string, candidates: readonly string[]): string | undefined {
  let best: string | undefined;
  let bestD = Infinity;
  const w = word.toLowerCase();
  for (const c of candidates) {
    const d = editDistance(w, c.toLowerCase());
    if (d < bestD) {
      bestD = d;
      best = c;
    }
  }
  return best !== undefined && bestD <= Math.max(2, Math.floor(word.length / 3)) ? best : undefined;
}

function describeRange(def: SettingDef): string {
  switch (def.type) {
    case 'number':
    case 'integer':
      return `${def.type === 'integer' ? 'a whole number' : 'a number'} from ${def.min} to ${def.max}${def.unit ? ' ' + def.unit : ''}${def.nullable ? ' (or null)' : ''}`;
    case 'boolean':
      return 'true or false';
    case 'enum':
      return `one of ${def.values.join(', ')}`;
    case 'string':
      return def.pattern
        ? `text of at most ${def.maxLength} characters in the form the setting describes (${def.description})`
        : `text of at most ${def.maxLength} characters`;
  }
}

/** Check one value against its definition; returns the normalised value or throws naming the allowed values. */
export function validateValue(key: SettingKey, value: unknown, source = 'option'): unknown {
  const def: SettingDef = SCHEMA[key];
  const bad = (): never => {
    throw new StrataError(
      'BAD_SETTING',
      `${source} ${key} = ${JSON.stringify(value)} is not allowed: expected ${describeRange(def)}`,
    );
  };
  switch (def.type) {
    case 'number':
    case 'integer': {
      if (value === null) return def.nullable ? null : bad();
      if (typeof value !== 'number' || !Number.isFinite(value)) return bad();
      if (def.type === 'integer' && !Number.isInteger(value)) return bad();
      if (value < def.min || value > def.max) return bad();
      return value;
    }
    case 'boolean':
      return typeof value === 'boolean' ? value : bad();
    case 'enum':
      return typeof value === 'string' && def.values.includes(value) ? value : bad();
    case 'string':
      return typeof value === 'string' && value.length <= def.maxLength && (!def.pattern || def.pattern.test(value))
        ? value
        : bad();
  }
}

/** Decimal numbers only: `20`, `-0.5`, `.5`, `1e3`; not hex, octal or binary (`0x14` is not 20), nor `Infinity`. */
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;

/** The number a text writes in decimal (surrounding spaces allowed), or NaN. */
export function parseDecimal(text: string): number {
  const t = text.trim();
  return DECIMAL.test(t) ? Number(t) : NaN;
}

/** Parse a CLI/text value for a setting into the schema's type. */
export function parseSettingText(key: SettingKey, text: string): unknown {
  const def: SettingDef = SCHEMA[key];
  const t = text.trim();
  switch (def.type) {
    case 'number':
    case 'integer': {
      if (def.nullable && (t === '' || t === 'null' || t === 'auto')) return null;
      const n = parseDecimal(t.endsWith('%') && def.unit === '%' ? t.slice(0, -1) : t);
      return Number.isFinite(n) ? n : text;
    }
    case 'boolean':
      if (/^(true|yes|on|1)$/i.test(t)) return true;
      if (/^(false|no|off|0)$/i.test(t)) return false;
      return text;
    case 'enum':
      return t;
    case 'string':
      return text.replace(/\\n/g, '\n');
  }
}

/** Throw for a key that is not a setting, suggesting the closest one. */
export function checkKey(key: string, source = 'option'): SettingKey {
  if (Object.hasOwn(SCHEMA, key)) return key as SettingKey;
  const s = suggest(key, SETTING_KEYS);
  throw new StrataError(
    'UNKNOWN_SETTING',
    `unknown ${source} "${key}"${s ? ` (did you mean "${s}"?)` : ''}; \`strata settings\` lists them all`,
  );
}

function applyLayer(target: Record<string, unknown>, values: Readonly<Record<string, unknown>>, source: string): void {
  for (const [k, v] of Object.entries(values)) {
    if (v === undefined) continue;
    const key = checkKey(k, source);
    target[key] = validateValue(key, v, source);
  }
}

/**
 * Resolve options into a frozen config. Order: schema defaults, printer preset, filament preset, the
 * caller's options. The caller's object is never mutated.
 */
export function resolveConfig(options: SliceOptions = {}): Config {
  if (options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new StrataError('BAD_SETTING', 'options must be an object of settings');
  }
  const { printer: printerName, filament: filamentName, ...rest } = options as Record<string, unknown>;
  const printerId = typeof printerName === 'string' ? printerName : DEFAULT_PRINTER;
  const filamentId = typeof filamentName === 'string' ? filamentName : DEFAULT_FILAMENT;
  if (printerName !== undefined && typeof printerName !== 'string')
    throw new StrataError('UNKNOWN_PRESET', 'printer must be a preset name');
  if (filamentName !== undefined && typeof filamentName !== 'string')
    throw new StrataError('UNKNOWN_PRESET', 'filament must be a preset name');
  const printer = findPrinter(printerId);
  const presets = listPresets();
  if (!printer) {
    const gap = printerWithoutPreset(printerId);
    if (gap) {
      const [x, y, z] = gap.size;
      const size = `buildPlateWidth ${x}, buildPlateLength ${y}, buildVolumeHeight ${z}`;
      throw new StrataError(
        'UNKNOWN_PRESET',
        `no printer preset for ${gap.name} ("${printerId}"): ${gap.why}${gap.kind === 'g-code' ? `; a generic Marlin printer with its size (${size}) slices for it` : ''}`,
      );
    }
    const s = suggest(
      printerId,
      presets.printers.map((p) => p.id),
    );
    throw new StrataError(
      'UNKNOWN_PRESET',
      `unknown printer "${printerId}"${s ? ` (did you mean "${s}"?)` : ''}; \`strata presets\` lists them`,
    );
  }
  const filament = findFilament(filamentId);
  if (!filament) {
    const s = suggest(
      filamentId,
      presets.filaments.map((p) => p.id),
    );
    throw new StrataError(
      'UNKNOWN_PRESET',
      `unknown filament "${filamentId}"${s ? ` (did you mean "${s}"?)` : ''}; \`strata presets\` lists them`,
    );
  }

  const values: Record<string, unknown> = {};
  for (const key of SETTING_KEYS) values[key] = SCHEMA[key].default;
  applyLayer(values, printer.settings, `printer preset ${printer.id}:`);
  applyLayer(values, filament.settings, `filament preset ${filament.id}:`);
  const preset = { ...values } as Settings;
  applyLayer(values, rest, 'option');
  // A caller who sets the temperature but not the first-layer one means the first layer to follow it,
  // keeping the preset's first-layer offset (e.g. +5 °C).
  const follow = (
    main: 'nozzleTemperature' | 'bedTemperature',
    first: 'firstLayerNozzleTemperature' | 'firstLayerBedTemperature',
  ) => {
    if (rest[main] !== undefined && rest[first] === undefined && preset[first] !== null) {
      values[first] = Math.max(0, (values[main] as number) + ((preset[first] as number) - (preset[main] as number)));
    }
  };
  follow('nozzleTemperature', 'firstLayerNozzleTemperature');
  follow('bedTemperature', 'firstLayerBedTemperature');
  const s = values as Settings;

  const lineWidthMm = s.lineWidth ?? s.nozzleDiameter;
  const firstLayerLineWidthMm = s.firstLayerLineWidth ?? lineWidthMm;
  if (s.layerHeight > s.nozzleDiameter * 0.85) {
    throw new StrataError(
      'BAD_SETTING',
      `layerHeight ${s.layerHeight} mm is too thick for a ${s.nozzleDiameter} mm nozzle (at most 85% of it: ${round3(s.nozzleDiameter * 0.85)} mm)`,
    );
  }
  if (s.firstLayerHeight > s.nozzleDiameter * 0.9) {
    throw new StrataError(
      'BAD_SETTING',
      `firstLayerHeight ${s.firstLayerHeight} mm is too thick for a ${s.nozzleDiameter} mm nozzle (at most ${round3(s.nozzleDiameter * 0.9)} mm)`,
    );
  }
  if (lineWidthMm < s.nozzleDiameter * 0.6 || lineWidthMm > s.nozzleDiameter * 2.5) {
    throw new StrataError(
      'BAD_SETTING',
      `lineWidth ${lineWidthMm} mm does not suit a ${s.nozzleDiameter} mm nozzle (allowed ${round3(s.nozzleDiameter * 0.6)} to ${round3(s.nozzleDiameter * 2.5)} mm)`,
    );
  }
  const minLayerHeightMm = s.minLayerHeight ?? Math.min(s.layerHeight, round3(s.nozzleDiameter * 0.175));
  const maxLayerHeightMm = s.maxLayerHeight ?? Math.max(s.layerHeight, round3(s.nozzleDiameter * 0.75));
  if (s.adaptiveLayerHeight) checkAdaptiveLimits(minLayerHeightMm, maxLayerHeightMm, s);
  const wallCount = s.wallCount ?? Math.max(0, Math.round(s.shellWallThickness / lineWidthMm + WHOLE_QUOTIENT_EPS));
  const layersFor = (t: number) => (t <= 0 ? 0 : Math.max(1, Math.ceil(t / s.layerHeight - LAYER_SHARE_EPS)));
  const topSkinThicknessMm = s.topSkinThickness ?? s.shellSkinThickness;
  const bottomSkinThicknessMm = s.bottomSkinThickness ?? s.shellSkinThickness;
  const derived: Derived = {
    lineWidthMm,
    firstLayerLineWidthMm,
    wallCount,
    topSkinThicknessMm,
    bottomSkinThicknessMm,
    topLayers: layersFor(topSkinThicknessMm),
    bottomLayers: layersFor(bottomSkinThicknessMm),
    firstLayerNozzleTemperature: s.firstLayerNozzleTemperature ?? s.nozzleTemperature,
    firstLayerBedTemperature: s.firstLayerBedTemperature ?? s.bedTemperature,
    printerId: printer.id,
    filamentId: filament.id,
    supportLineWidthMm: s.supportLineWidth ?? lineWidthMm,
    supportTopGapLayers: gapLayers(s.supportZGap ?? s.layerHeight, s.layerHeight),
    supportBottomGapLayers: gapLayers(s.supportBottomZGap ?? s.supportZGap ?? s.layerHeight, s.layerHeight),
    supportFloorLayers: s.supportFloorLayers ?? s.supportInterfaceLayers,
    supportWallCount: s.supportWallCount ?? (s.supportType === 'tree' ? 1 : 0),
    supportColumnWallCount: s.supportWallCount ?? 0,
    supportTreeTipSpacingMm:
      s.supportTreeTipSpacing ??
      (s.supportInterfaceLayers > 0 ? TREE_TIP_SPACING_UNDER_ROOF_MM : TREE_TIP_SPACING_NO_ROOF_MM),
    raftBaseLineWidthMm: s.raftBaseLineWidth ?? 2 * s.nozzleDiameter,
    raftBaseLineSpacingMm: s.raftBaseLineSpacing ?? 2 * (s.raftBaseLineWidth ?? 2 * s.nozzleDiameter),
    raftInterfaceLineSpacingMm: s.raftInterfaceLineSpacing ?? 2.5 * lineWidthMm,
    minLayerHeightMm,
    maxLayerHeightMm,
    settings: Object.freeze({ ...s }),
  };
  const resolved: Record<string, unknown> = { ...s };
  for (const key of RESOLVED) delete resolved[key];
  return Object.freeze({ ...resolved, ...derived }) as Config;
}

/** Adaptive layer height's limits must hold layerHeight between them and suit the nozzle: one error naming what is wrong. */
function checkAdaptiveLimits(min: number, max: number, s: Settings): void {
  const bad = (why: string): never => {
    throw new StrataError('BAD_SETTING', `adaptiveLayerHeight: ${why}`);
  };
  if (min > max) bad(`minLayerHeight ${min} mm is above maxLayerHeight ${max} mm`);
  if (s.layerHeight < min || s.layerHeight > max)
    bad(`layerHeight ${s.layerHeight} mm must lie between minLayerHeight ${min} mm and maxLayerHeight ${max} mm`);
  if (max > s.nozzleDiameter * 0.85)
    bad(
      `maxLayerHeight ${max} mm is too thick for a ${s.nozzleDiameter} mm nozzle (at most 85% of it: ${round3(s.nozzleDiameter * 0.85)} mm)`,
    );
}

/** A gap in mm as whole layers (rounded to the nearest). */
function gapLayers(gapMm: number, layerHeight: number): number {
  return Math.max(0, Math.round(gapMm / layerHeight + WHOLE_QUOTIENT_EPS));
}

function round3(x: number): number {
  return Math.round(x * 1000) / 1000;
}
