/**
 * The one settings schema. Each setting is declared once: key, type, unit, default, range, description
 * and the stage it affects. Options objects, CLI flags, JSON profiles and presets are all validated
 * against it and resolved once into a frozen typed config (see resolve.ts).
 * Key names follow the seeds' library where the concept is the same.
 */
import { PATTERN_IDS, SKIN_PATTERN_IDS } from '../infill/types.js';

export type Unit =
  | 'mm'
  | 'mm²'
  | 'mm³'
  | 'mm/s'
  | 'mm/s²'
  | '°C'
  | '%'
  | 's'
  | 'g/cm³'
  | '°'
  | 'count'
  | '×'
  | 'MiB'
  | '';
/** The stage a setting affects. `runtime` settings change how a slice runs, never the G-code it makes. */
export type Stage =
  | 'machine'
  | 'mesh'
  | 'slice'
  | 'walls'
  | 'skin'
  | 'infill'
  | 'support'
  | 'adhesion'
  | 'travel'
  | 'cooling'
  | 'gcode'
  | 'runtime';

/**
 * An input a setting needs before it can change the output, beyond other settings (`onlyWith`):
 * `several-models` (arranging models on the bed), `off-centre-model` (a model not at the bed centre),
 * `thin-walls` (a part whose layers are walls only, so one layer ends next to where the next starts),
 * `thin-features` (a part with fins and tapers thinner than its walls need, down to a fraction of a line),
 * `overhangs` (a part with overhangs: a bridge between two pillars, a cantilever over a ledge, a slope),
 * `custom-infill` (an IceSL shader or image infill: `customInfill`, `--infill-shader`,
 * `--infill-image`), `custom-image-infill` (an image infill), `several-tops` (a part with top surfaces at
 * more than one height: a step), `color-change` / `pause` (a colour change or pause at some height:
 * colorChangeAt, pauseAt), `template-placeholder` (a start G-code that writes the setting's placeholder).
 */
export type SettingNeed =
  | 'several-models'
  | 'off-centre-model'
  | 'thin-walls'
  | 'thin-features'
  | 'overhangs'
  | 'custom-infill'
  | 'custom-image-infill'
  | 'several-tops'
  | 'color-change'
  | 'pause'
  | 'template-placeholder'
  | 'fan-by-layer-time';

/**
 * A value `onlyWith` asks another setting for, or a list of values any of which will do, or (a number
 * setting whose 0 means off) any value above `above`; `example` is one such value, for UIs and the
 * every-flag test.
 */
export type OnlyWithValue =
  | string
  | number
  | boolean
  | readonly string[]
  | { readonly above: number; readonly example: number };

interface Base {
  unit: Unit;
  description: string;
  stage: Stage;
  /**
   * The setting matters only while these other settings have these values (e.g. brimWidth only with
   * `{ adhesionType: 'brim' }`; a list: any of its values). UIs show it only then; the every-flag CLI test
   * sets them first (a list's first value).
   */
  onlyWith?: Readonly<Record<string, OnlyWithValue>>;
  /** The setting matters only with this kind of input (see SettingNeed). */
  needs?: SettingNeed;
}
export interface NumberDef extends Base {
  type: 'number' | 'integer';
  default: number | null;
  min: number;
  max: number;
  /** When true the value may be null, meaning "derived": the description says from what. */
  nullable?: boolean;
}
export interface BooleanDef extends Base {
  type: 'boolean';
  default: boolean;
}
export interface EnumDef extends Base {
  type: 'enum';
  default: string;
  values: readonly string[];
}
export interface StringDef extends Base {
  type: 'string';
  default: string;
  /** Longest accepted value, characters. */
  maxLength: number;
  /** When set, a value must match it (the description says the form). */
  pattern?: RegExp;
  /** With a pattern: one valid value other than the default, for UIs and the every-flag test. */
  example?: string;
}
export type SettingDef = NumberDef | BooleanDef | EnumDef | StringDef;

const MARLIN_START = [
  'G90 ; absolute positioning',
  'M82 ; absolute extrusion (overridden below for relative E)',
  'M140 S{firstLayerBedTemperature} ; bed heat, no wait',
  'M104 S{firstLayerNozzleTemperature} ; nozzle heat, no wait',
  'G28 ; home all axes',
  'M190 S{firstLayerBedTemperature} ; wait for bed',
  'M109 S{firstLayerNozzleTemperature} ; wait for nozzle',
  'G92 E0',
  'G1 Z2.0 F3000',
  'G1 X0.1 Y20 Z0.3 F5000.0 ; prime line start',
  'G1 X0.1 Y200.0 Z0.3 F1500.0 E15',
  'G1 X0.4 Y200.0 Z0.3 F5000.0',
  'G1 X0.4 Y20 Z0.3 F1500.0 E30',
  'G92 E0',
  'G1 Z2.0 F3000',
].join('\n');

const MARLIN_END = [
  'G91 ; relative positioning',
  'G1 E-2 F2700 ; retract',
  'G1 Z10 F3000 ; lift',
  'G90 ; absolute positioning',
  'G1 X0 Y{buildPlateLength} F3000 ; present the print',
  'M106 S0 ; fan off',
  'M104 S0 ; nozzle off',
  'M140 S0 ; bed off',
  'M84 X Y E ; motors off',
].join('\n');

const num = (def: number, min: number, max: number, unit: Unit, stage: Stage, description: string) =>
  ({ type: 'number', default: def, min, max, unit, stage, description, nullable: false }) as NumberDef & {
    nullable: false;
  };
const int = (def: number, min: number, max: number, unit: Unit, stage: Stage, description: string) =>
  ({ type: 'integer', default: def, min, max, unit, stage, description, nullable: false }) as NumberDef & {
    nullable: false;
  };
/** A number whose empty (null) default is derived from other settings, as its description says. */
const optNum = (
  min: number,
  max: number,
  unit: Unit,
  stage: Stage,
  description: string,
  type: 'number' | 'integer' = 'number',
) => ({ type, default: null, min, max, unit, stage, description, nullable: true }) as NumberDef & { nullable: true };
const bool = (def: boolean, stage: Stage, description: string): BooleanDef => ({
  type: 'boolean',
  default: def,
  unit: '',
  stage,
  description,
});
const enm = <V extends readonly string[]>(values: V, def: V[number], stage: Stage, description: string) =>
  ({ type: 'enum', default: def, values, unit: '', stage, description }) as const;
const str = (def: string, stage: Stage, description: string, maxLength = 65536, pattern?: RegExp): StringDef => ({
  type: 'string',
  default: def,
  unit: '',
  stage,
  description,
  maxLength,
  ...(pattern ? { pattern } : {}),
});

/** A definition that matters only when `onlyWith` holds (and, optionally, with a `needs` input). */
const when = <D extends SettingDef>(
  def: D,
  onlyWith: Readonly<Record<string, OnlyWithValue>> | null,
  needs?: SettingNeed,
): D => ({
  ...def,
  ...(onlyWith ? { onlyWith } : {}),
  ...(needs ? { needs } : {}),
});

/** Up to 100 heights in mm (numbers from 0, at most 4 digits before the point and 6 after), separated by commas or spaces; empty for none. */
const HEIGHT_LIST =
  /^\s*(?:(?:\d{1,4}(?:\.\d{0,6})?|\.\d{1,6})(?:\s*[,;\s]\s*(?:\d{1,4}(?:\.\d{0,6})?|\.\d{1,6})){0,99})?\s*$/;

/** `WxH` or `WxH/FORMAT` (PNG, QOI, JPG), comma-separated; empty for none. Sizes 1..1024 px are checked later. */
const THUMBNAIL_LIST =
  /^\s*(?:\d{1,4}\s*x\s*\d{1,4}(?:\s*\/\s*(?:png|qoi|jpg|jpeg))?\s*(?:,\s*\d{1,4}\s*x\s*\d{1,4}(?:\s*\/\s*(?:png|qoi|jpg|jpeg))?\s*)*)?$/i;

export const SCHEMA = {
  // ── machine ──────────────────────────────────────────────────────────────────
  buildPlateWidth: num(220, 10, 2000, 'mm', 'machine', 'Build plate size in X.'),
  buildPlateLength: num(220, 10, 2000, 'mm', 'machine', 'Build plate size in Y.'),
  buildVolumeHeight: num(250, 10, 2000, 'mm', 'machine', 'Largest printable Z.'),
  originAtCenter: bool(
    false,
    'machine',
    'Bed coordinates have (0,0) at the plate centre (delta printers) instead of the front-left corner.',
  ),
  heatedBed: bool(true, 'machine', 'The printer has a heated bed (bed temperature commands are written).'),
  nozzleDiameter: num(0.4, 0.1, 2, 'mm', 'machine', 'Nozzle orifice diameter.'),
  filamentDiameter: num(1.75, 1, 3.5, 'mm', 'machine', 'Filament diameter.'),
  gcodeFlavor: enm(['marlin', 'klipper', 'reprap'] as const, 'marlin', 'gcode', 'G-code dialect.'),
  extruderMode: enm(
    ['absolute', 'relative'] as const,
    'absolute',
    'gcode',
    'Absolute (M82) or relative (M83) extrusion distances.',
  ),
  acceleration: num(
    500,
    10,
    100000,
    'mm/s²',
    'machine',
    'Print acceleration used by the time estimate (and written as M204 when set by a preset).',
  ),
  cornerVelocity: num(
    8,
    0.1,
    100,
    'mm/s',
    'machine',
    'Speed change allowed at a sharp corner without slowing (jerk / square-corner velocity), for the time estimate.',
  ),
  maxSpeed: num(
    300,
    5,
    2000,
    'mm/s',
    'machine',
    'Fastest XY feed rate the printer accepts; faster requested speeds are capped.',
  ),
  startGcode: str(
    MARLIN_START,
    'gcode',
    "G-code before the print, a template: {key} placeholders are replaced by setting values (e.g. {nozzleTemperature}); PrusaSlicer's and OrcaSlicer's [key], {key[0]}, arithmetic and {if …}…{else}…{endif}, and Cura's {key} (their names too: {first_layer_temperature[0]}, {material_bed_temperature}) are read as they write them.",
  ),
  endGcode: str(MARLIN_END, 'gcode', 'G-code after the print, a template like startGcode.'),
  layerChangeGcode: str(
    '',
    'gcode',
    "G-code after each layer change (after the move to the layer's height, before its first travel), a template like startGcode with {layer_num} (from 0) and {layer_z} (mm), e.g. `;AFTER_LAYER_CHANGE` or Klipper's `TIMELAPSE_TAKE_FRAME`. Every layer, the first too. Empty = none.",
  ),
  beforeLayerChangeGcode: str(
    '',
    'gcode',
    "G-code before each layer change (before the move to the layer's height), a template like layerChangeGcode. Empty = none.",
  ),
  colorChangeAt: {
    ...str(
      '',
      'gcode',
      'Heights (mm) at which to change filament, e.g. `5,10` (any order): colorChangeGcode is written before the first layer at or above each height, once (heights that fall on one layer give one change, heights above the print none). Empty = none.',
      1000,
      HEIGHT_LIST,
    ),
    example: '5',
  },
  pauseAt: {
    ...str(
      '',
      'gcode',
      'Heights (mm) at which to pause the print (to insert a nut or a magnet), e.g. `5,10`: pauseGcode is written before the first layer at or above each height. Empty = none. A pause adds nothing to the time estimate.',
      1000,
      HEIGHT_LIST,
    ),
    example: '5',
  },
  colorChangeGcode: when(
    str(
      '',
      'gcode',
      "G-code of a colour change (colorChangeAt), a template like startGcode. Empty = the flavour's: M600 (Marlin, RepRapFirmware), PAUSE (Klipper, which has an M600 only where the printer's config defines one).",
    ),
    null,
    'color-change',
  ),
  pauseGcode: when(
    str(
      '',
      'gcode',
      "G-code of a pause (pauseAt), a template like startGcode. Empty = the flavour's: M601 (Marlin), M226 (RepRapFirmware), PAUSE (Klipper).",
    ),
    null,
    'pause',
  ),
  filamentType: when(
    {
      ...str(
        'PLA',
        'gcode',
        "The filament's material (PLA, PETG, ABS, TPU…), set by the filament presets, for templates: {filamentType}, PrusaSlicer's {filament_type[0]}.",
        32,
        /^[A-Za-z0-9+._ -]*$/,
      ),
      example: 'PETG',
    },
    null,
    'template-placeholder',
  ),

  // ── layers and lines ─────────────────────────────────────────────────────────
  layerHeight: num(0.2, 0.02, 1.2, 'mm', 'slice', 'Thickness of every layer after the first.'),
  firstLayerHeight: num(
    0.2,
    0.02,
    1.2,
    'mm',
    'slice',
    'Thickness of the first layer, printed at Z = firstLayerHeight.',
  ),
  adaptiveLayerHeight: bool(
    false,
    'slice',
    "Vary the layer height with the model's surface (PrusaSlicer's variable layer height, Cura's adaptive layers): thin layers where the surface is near horizontal and curved (a dome's top, a sphere's poles), thick ones where it is vertical, each between minLayerHeight and maxLayerHeight, so the stair steps on sloping surfaces stay within the size adaptiveLayerQuality allows. Flat faces get a layer ending on them where the step limit allows. The first layer keeps firstLayerHeight; a layer range's layerHeight wins over it in its range.",
  ),
  minLayerHeight: when(
    optNum(
      0.02,
      1.2,
      'mm',
      'slice',
      'Thinnest layer adaptive layer height makes (at most layerHeight; also the lower bound of a layer height profile). Empty (null) = layerHeight or 17.5 % of nozzleDiameter, whichever is thinner (0.07 mm for a 0.4 mm nozzle).',
    ),
    { adaptiveLayerHeight: true },
    'overhangs',
  ),
  maxLayerHeight: when(
    optNum(
      0.02,
      1.2,
      'mm',
      'slice',
      'Thickest layer adaptive layer height makes (at least layerHeight, at most 85 % of nozzleDiameter; also the upper bound of a layer height profile). Empty (null) = layerHeight or 75 % of nozzleDiameter, whichever is thicker (0.3 mm for a 0.4 mm nozzle).',
    ),
    { adaptiveLayerHeight: true },
  ),
  adaptiveLayerQuality: when(
    num(
      0.5,
      0,
      1,
      '',
      'slice',
      "How closely adaptive layers follow sloping surfaces, 0 to 1. A layer of height h on a surface whose normal makes angle a with the vertical leaves a stair step (cusp) h·cos(a) deep; the deepest allowed goes from maxLayerHeight at 0 (every layer as thick as allowed) to half of minLayerHeight at 1, geometrically: at 0.5 with 0.07 and 0.3 mm it is 0.10 mm, so a near-flat surface gets 0.10 mm layers, a 45° slope 0.145 mm and one steeper than 70° 0.3 mm. (PrusaSlicer's quality slider, whose 0 is the finest, runs the other way.)",
    ),
    { adaptiveLayerHeight: true },
    'overhangs',
  ),
  adaptiveLayerStep: when(
    num(
      0.05,
      0.005,
      1,
      'mm',
      'slice',
      "Largest change of height between two neighbouring adaptive layers (Cura's adaptive_layer_height_variation_step), so the flow changes gradually.",
    ),
    { adaptiveLayerHeight: true },
  ),
  lineWidth: optNum(0.1, 3, 'mm', 'walls', 'Extrusion line width. Empty (null) = nozzleDiameter.'),
  firstLayerLineWidth: optNum(0.1, 3, 'mm', 'walls', 'Line width on the first layer. Empty (null) = lineWidth.'),
  meshTolerance: num(
    0.025,
    0.0005,
    0.5,
    'mm',
    'slice',
    'Outlines are simplified to this deviation before offsetting (CuraEngine uses the same 0.025 mm).',
  ),
  center: bool(
    true,
    'mesh',
    'Arrange the models on the bed around its centre; false keeps their own XY coordinates (a model that leaves the bed is an error).',
  ),

  // ── model placement and input limits ─────────────────────────────────────────
  upAxis: enm(
    ['z', 'y'] as const,
    'z',
    'mesh',
    'The axis that points up in the input: z (3D printing, CAD) or y (three.js scenes, many OBJ and glTF exports), turned Z-up before slicing.',
  ),
  rotateX: num(
    0,
    -360,
    360,
    '°',
    'mesh',
    'Turn each model about the X axis through its centre (right-handed, counter-clockwise looking down the axis), first.',
  ),
  rotateY: num(0, -360, 360, '°', 'mesh', 'Turn each model about the Y axis, after rotateX.'),
  rotateZ: num(0, -360, 360, '°', 'mesh', 'Turn each model about the vertical Z axis, after rotateX and rotateY.'),
  scale: num(
    1,
    0.001,
    1000,
    '×',
    'mesh',
    'Scale each model by this factor about its centre, after rotating (2 = twice the size).',
  ),
  scaleX: optNum(0.001, 1000, '×', 'mesh', 'Scale factor along the bed X axis. Empty (null) = scale.'),
  scaleY: optNum(0.001, 1000, '×', 'mesh', 'Scale factor along the bed Y axis. Empty (null) = scale.'),
  scaleZ: optNum(0.001, 1000, '×', 'mesh', 'Scale factor along the vertical Z axis. Empty (null) = scale.'),
  objectSpacing: when(
    num(6, 0, 100, 'mm', 'mesh', 'Gap between models arranged on the bed (a brim adds its width on each side).'),
    { center: true },
    'several-models',
  ),
  inflateBudget: int(
    512,
    1,
    65536,
    'MiB',
    'runtime',
    'Most data a 3MF archive (all the model parts it references) or an infill image may unpack to; bigger ones are refused before they are unpacked. Raise it for very large 3MF models.',
  ),

  // ── walls ────────────────────────────────────────────────────────────────────
  shellWallThickness: num(
    0.8,
    0,
    20,
    'mm',
    'walls',
    'Total wall thickness; the wall count is this over the line width, rounded.',
  ),
  wallCount: optNum(0, 50, 'count', 'walls', 'Number of walls; overrides shellWallThickness when set.', 'integer'),
  wallOrder: enm(
    ['inner-first', 'outer-first'] as const,
    'inner-first',
    'walls',
    'Print inner walls before the outer wall (better surface) or the outer wall first (better dimensions).',
  ),
  seamPosition: enm(
    ['aligned', 'nearest', 'rear', 'random'] as const,
    'aligned',
    'walls',
    'Where each wall loop starts: aligned on a sharp corner, nearest to the nozzle, at the rear, or random (seeded).',
  ),
  randomSeed: when(int(1, 0, 2147483647, '', 'walls', 'Seed for random seams: the same seed gives the same G-code.'), {
    seamPosition: 'random',
  }),
  wallGenerator: enm(
    ['variable', 'classic'] as const,
    'variable',
    'walls',
    "How walls are laid: variable (lines whose width follows the part, so thin features print and walls never overlap or leave slivers, as PrusaSlicer's and CuraEngine's Arachne walls) or classic (fixed-width loops, with thin gap loops between them).",
  ),
  minFeatureSize: when(
    num(
      25,
      1,
      100,
      '%',
      'walls',
      'Thinnest feature printed, % of the nozzle diameter: thinner parts of the model are left out (and reported). Thicker ones get a line at least minBeadWidth wide.',
    ),
    { wallGenerator: 'variable' },
    'thin-features',
  ),
  minBeadWidth: when(
    num(
      50,
      10,
      100,
      '%',
      'walls',
      'Narrowest line the variable walls lay, % of the nozzle diameter: a feature thinner than this (but at least minFeatureSize) gets a line this wide.',
    ),
    { wallGenerator: 'variable' },
    'thin-features',
  ),
  maxBeadWidth: when(
    num(
      200,
      100,
      300,
      '%',
      'walls',
      'Widest line the variable walls lay, % of the nozzle diameter: a strip up to this wide is one line, a wider one two or more.',
    ),
    { wallGenerator: 'variable' },
    'thin-features',
  ),
  wallTransitionLength: when(
    num(
      100,
      10,
      1000,
      '%',
      'walls',
      'Length over which the number of lines changes where the part widens or narrows, % of the nozzle diameter: a middle line shorter than this is not started.',
    ),
    { wallGenerator: 'variable' },
    'thin-features',
  ),
  wallTransitionAngle: when(
    num(
      10,
      1,
      59,
      '°',
      'walls',
      'A wedge or corner sharper than this angle gets a middle line running into it; a blunter one does not (its walls meet instead).',
    ),
    { wallGenerator: 'variable' },
    'thin-features',
  ),
  wallDistributionCount: when(
    int(
      1,
      1,
      20,
      'count',
      'walls',
      'How many lines, counted from the middle, share a change of width where the part is thinner than its walls need; the outer ones keep the line width.',
    ),
    { wallGenerator: 'variable' },
    'thin-features',
  ),

  // ── skin ─────────────────────────────────────────────────────────────────────
  shellSkinThickness: num(
    0.8,
    0,
    20,
    'mm',
    'skin',
    'Thickness of solid top and bottom skin; the layer count is this over the layer height, rounded up.',
  ),
  topSkinThickness: optNum(0, 20, 'mm', 'skin', 'Top skin thickness. Empty (null) = shellSkinThickness.'),
  bottomSkinThickness: optNum(0, 20, 'mm', 'skin', 'Bottom skin thickness. Empty (null) = shellSkinThickness.'),
  skinWall: bool(true, 'skin', 'Print one perimeter around each skin region before its lines.'),
  skinOverlap: num(25, 0, 100, '%', 'skin', 'How far skin lines reach into the innermost wall, % of the line width.'),
  skinAngle: num(45, -180, 180, '°', 'skin', 'Direction of skin lines on even layers; odd layers are turned 90°.'),
  topSkinPattern: enm(
    SKIN_PATTERN_IDS,
    'lines',
    'skin',
    'Pattern of the top skin (the skin exposed upward; where skin is exposed both ways, top): lines (joined where their ends meet along the edge, nearest first), monotonic (the same lines, each laid beside lines already printed on one side only, so no seam shows where two fronts of lines meet), or concentric (loops inwards from the edge).',
  ),
  bottomSkinPattern: enm(
    SKIN_PATTERN_IDS,
    'lines',
    'skin',
    'Pattern of the bottom skin (the rest of the skin): lines, monotonic or concentric, as topSkinPattern. Skin over air (a bridge) keeps its lines straight across, concentric or not.',
  ),

  // ── ironing ──────────────────────────────────────────────────────────────────
  ironingEnabled: bool(
    false,
    'skin',
    "Iron top surfaces: after a surface's skin, the nozzle passes over it again at the same height in lines ironingSpacing apart with a trickle of flow, melting its ridges flat. The pass keeps half a line width from the part's edges; skin over air (a bridge) is not ironed.",
  ),
  ironingType: when(
    enm(
      ['top', 'topmost', 'all'] as const,
      'top',
      'skin',
      'Which surfaces are ironed: every top surface (top), only the object\'s highest ones (topmost: its last layer), or every top surface and all other solid skin, top and bottom skin inside the part included, the whole layer where it is solid throughout (all, OrcaSlicer\'s "all solid").',
    ),
    { ironingEnabled: true },
    'several-tops',
  ),
  ironingFlow: when(
    num(
      15,
      1,
      100,
      '%',
      'skin',
      'Flow of the ironing lines, % of a full line as wide as ironingSpacing at the layer height (as PrusaSlicer counts it).',
    ),
    { ironingEnabled: true },
  ),
  ironingSpacing: when(num(0.1, 0.05, 1, 'mm', 'skin', 'Distance between ironing lines.'), { ironingEnabled: true }),
  ironingSpeed: when(num(15, 1, 1000, 'mm/s', 'skin', 'Speed of the ironing lines.'), { ironingEnabled: true }),
  ironingAngle: when(
    optNum(
      -180,
      180,
      '°',
      'skin',
      'Direction of the ironing lines. Empty (null) = across the skin lines of the layer (turned 90° from them, as Cura irons).',
    ),
    { ironingEnabled: true },
  ),

  // ── infill ───────────────────────────────────────────────────────────────────
  infillDensity: num(20, 0, 100, '%', 'infill', 'Sparse infill density: extruded area over region area.'),
  infillPattern: enm(PATTERN_IDS, 'grid', 'infill', 'Sparse infill pattern.'),
  infillPatternCentering: when(
    enm(['object', 'global'] as const, 'object', 'infill', 'Centre the pattern on each object or on the build plate.'),
    null,
    'off-centre-model',
  ),
  infillAngle: num(45, -180, 180, '°', 'infill', 'Base direction of the infill lines.'),
  infillOverlap: num(25, 0, 100, '%', 'infill', 'How far infill reaches into the innermost wall, % of the line width.'),
  infillImagePixelSize: when(
    num(
      0.1,
      0.001,
      10,
      'mm',
      'infill',
      "Size of one pixel of a custom infill image (cells.png), IceSL's labeling_mm_per_pixel.",
    ),
    null,
    'custom-image-infill',
  ),
  infillShaderResolution: when(
    optNum(
      0.005,
      2,
      'mm',
      'infill',
      'Grid spacing at which a custom infill shader is sampled before crossings are refined by bisection. Empty (null) = nozzleDiameter / 4 for shaders, one pixel for images.',
    ),
    null,
    'custom-infill',
  ),
  infillConnect: bool(true, 'infill', 'Join infill line ends along the region boundary where that avoids a travel.'),

  // ── speeds ───────────────────────────────────────────────────────────────────
  perimeterSpeed: num(30, 1, 1000, 'mm/s', 'walls', 'Outer wall speed.'),
  innerWallSpeed: num(50, 1, 1000, 'mm/s', 'walls', 'Inner wall speed.'),
  skinSpeed: num(40, 1, 1000, 'mm/s', 'skin', 'Top/bottom skin speed.'),
  infillSpeed: num(60, 1, 1000, 'mm/s', 'infill', 'Sparse infill speed.'),
  firstLayerSpeed: num(20, 1, 1000, 'mm/s', 'walls', 'Speed of every extrusion on the first layer.'),
  travelSpeed: num(150, 1, 2000, 'mm/s', 'travel', 'Travel speed.'),
  firstLayerTravelSpeed: num(100, 1, 2000, 'mm/s', 'travel', 'Travel speed on the first layer.'),

  // ── travel and retraction ────────────────────────────────────────────────────
  combing: bool(true, 'travel', 'Keep travels inside the current island, around holes, where possible.'),
  retractionEnabled: bool(true, 'travel', 'Retract filament before travels that leave the island or are long.'),
  retractionDistance: when(num(5, 0, 20, 'mm', 'travel', 'Filament pulled back per retraction.'), {
    retractionEnabled: true,
  }),
  retractionSpeed: when(num(45, 1, 200, 'mm/s', 'travel', 'Retraction and prime speed.'), { retractionEnabled: true }),
  retractionExtraPrime: when(num(0, 0, 5, 'mm', 'travel', 'Extra filament pushed after a retraction.'), {
    retractionEnabled: true,
  }),
  retractionMinTravel: when(
    num(1.5, 0, 100, 'mm', 'travel', 'Travels shorter than this inside one island do not retract.'),
    { retractionEnabled: true },
  ),
  retractCrossingWallsOnly: when(
    bool(
      true,
      'travel',
      "A travel that stays inside the innermost wall (over the island's own skin and infill, crossing no wall) does not retract, however long.",
    ),
    { retractionEnabled: true },
  ),
  combingMaxDistance: when(
    num(
      0,
      0,
      1000,
      'mm',
      'travel',
      'A travel inside the innermost wall longer than this retracts all the same (0 = no limit).',
    ),
    { retractionEnabled: true },
  ),
  retractOnLayerChange: when(
    bool(true, 'travel', 'Retract when moving to the next layer, even for a travel too short to retract otherwise.'),
    { retractionEnabled: true },
    'thin-walls',
  ),
  zHop: when(num(0, 0, 10, 'mm', 'travel', 'Lift the nozzle by this much during retracted travels (0 = off).'), {
    retractionEnabled: true,
  }),
  zHopSpeed: when(
    optNum(
      0.1,
      500,
      'mm/s',
      'travel',
      "Speed of the Z moves of a z-hop (the lift and the way back down): Cura's Z hop speed. Capped at maxSpeedZ when that is set. Empty (null) = the speed of other Z moves, 5 mm/s (or maxSpeedZ when slower).",
    ),
    { retractionEnabled: true, zHop: { above: 0, example: 0.4 } },
  ),
  zHopOnlyOverParts: when(
    bool(
      false,
      'travel',
      "Lift (zHop) only for a travel whose straight line passes over an island of this layer printed before, other than the ones it starts and ends in (Cura's z hop only over printed parts); other retracted travels stay at the layer's height.",
    ),
    { retractionEnabled: true, zHop: { above: 0, example: 0.4 } },
  ),
  wipeDistance: when(
    num(
      0,
      0,
      20,
      'mm',
      'travel',
      "On each retraction, move the nozzle back along the path it has just printed (so over the part) for this distance, retracting on the way: what retractBeforeWipe leaves of the retraction happens during the wipe, spread along it, and any the path was too short for after it (PrusaSlicer's and OrcaSlicer's wipe). The wipe moves at 80 % of the travel speed, slower where the retraction would otherwise go faster than retractionSpeed. With firmwareRetraction the wipe is a plain move before the G10. 0 = off.",
    ),
    { retractionEnabled: true },
  ),
  retractBeforeWipe: when(
    num(
      0,
      0,
      100,
      '%',
      'travel',
      'Share of the retraction made on the spot before the wipe starts; the rest happens during the wipe.',
    ),
    { retractionEnabled: true, wipeDistance: { above: 0, example: 2 } },
  ),
  coastingVolume: when(
    num(
      0,
      0,
      5,
      'mm³',
      'travel',
      "Before a retracted travel, print the end of the extrusion before it as a plain move (no extrusion) of this volume, so the pressure left in the nozzle lays it instead (Cura's coasting): a length of coastingVolume / (line width × layer height). Only on paths with at least coastingMinVolume, at least twice as long as the coasted length and without a Z per point (scarf, spiral turns). 0 = off.",
    ),
    { retractionEnabled: true },
  ),
  coastingMinVolume: when(
    num(
      0.8,
      0,
      100,
      'mm³',
      'travel',
      'Paths with less volume than this are not coasted (they have not built up the pressure that coasting relies on).',
    ),
    { retractionEnabled: true, coastingVolume: { above: 0, example: 0.1 } },
  ),
  retractionCountMax: when(
    int(
      0,
      0,
      1000,
      'count',
      'travel',
      "At most this many retractions within any retractionExtrusionWindow of extruded filament (Cura's maximum retraction count): further travels that stay inside the island travel unretracted; travels that leave it, and layer changes, always retract. 0 = no limit.",
    ),
    { retractionEnabled: true },
  ),
  retractionExtrusionWindow: when(
    optNum(
      0,
      100,
      'mm',
      'travel',
      'The length of extruded filament over which retractionCountMax counts. Empty (null) = retractionDistance (so one piece of filament is not ground by more than that many retractions).',
    ),
    { retractionEnabled: true, retractionCountMax: { above: 0, example: 1 } },
  ),

  // ── cooling and temperature ──────────────────────────────────────────────────
  fanSpeed: num(100, 0, 100, '%', 'cooling', 'Part-cooling fan from the second layer on.'),
  firstLayerFanSpeed: num(0, 0, 100, '%', 'cooling', 'Part-cooling fan on the first layer.'),
  minLayerTime: num(10, 0, 600, 's', 'cooling', 'Slow a layer down so it takes at least this long.'),
  minPrintSpeed: num(10, 1, 1000, 'mm/s', 'cooling', 'Never slow down below this for minimum layer time.'),
  fanOffLayers: int(
    1,
    0,
    1000,
    'count',
    'cooling',
    'The first layers of each object printed with firstLayerFanSpeed (0 = none; the first layer has its own fan only when this is at least 1).',
  ),
  fanFullLayer: int(
    0,
    0,
    1000,
    'count',
    'cooling',
    'The fan rises evenly from firstLayerFanSpeed after the fanOffLayers to its full speed at this layer (counted from 0); 0 or not above fanOffLayers = full at once.',
  ),
  fanBelowLayerTime: when(
    num(
      0,
      0,
      600,
      's',
      'cooling',
      'A layer shorter than this runs the fan above fanSpeed, up to maxFanSpeed for a layer at or below minLayerTime (0 = off).',
    ),
    null,
    'fan-by-layer-time',
  ),
  maxFanSpeed: when(
    num(100, 0, 100, '%', 'cooling', 'The fan for the shortest layers (fanBelowLayerTime).'),
    null,
    'fan-by-layer-time',
  ),
  nozzleTemperature: num(200, 0, 450, '°C', 'cooling', 'Nozzle temperature from the second layer on.'),
  firstLayerNozzleTemperature: optNum(
    0,
    450,
    '°C',
    'cooling',
    'Nozzle temperature on the first layer. Empty (null) = nozzleTemperature.',
  ),
  bedTemperature: num(60, 0, 150, '°C', 'cooling', 'Bed temperature from the second layer on.'),
  firstLayerBedTemperature: optNum(
    0,
    150,
    '°C',
    'cooling',
    'Bed temperature on the first layer. Empty (null) = bedTemperature.',
  ),

  // ── filament ─────────────────────────────────────────────────────────────────
  filamentDensity: num(1.24, 0.5, 5, 'g/cm³', 'gcode', 'Filament density, for the weight estimate.'),
  flowRate: num(100, 10, 300, '%', 'gcode', 'Extrusion multiplier.'),

  // ── progress, object labels, thumbnails ──────────────────────────────────────
  progressM73: bool(
    true,
    'gcode',
    'Write M73 P<percent> R<minutes left> from the time estimate at every layer start, and M73 P100 R0 after the last layer.',
  ),
  labelObjects: enm(
    ['auto', 'off', 'comments', 'firmware'] as const,
    'auto',
    'gcode',
    "Label each object's moves so a host or the firmware can cancel one mid-print: firmware = Klipper EXCLUDE_OBJECT_DEFINE/START/END, or M486 S/T (Marlin, RepRap) with the comments; comments = only `; printing object NAME` / `; stop printing object NAME` (OctoPrint Cancelobject); auto = firmware for Klipper, comments otherwise.",
  ),
  thumbnails: {
    ...str(
      '',
      'gcode',
      'Preview images of the plate written into the G-code, as `WxH` or `WxH/FORMAT` (PNG, QOI or JPG) separated by commas, e.g. `32x32,300x300` or `16x16/QOI,313x173/QOI,380x285/PNG`. Empty = none.',
      512,
      THUMBNAIL_LIST,
    ),
    example: '32x32,300x300',
  },

  // ── sequential printing ──────────────────────────────────────────────────────
  sequentialPrinting: when(
    bool(
      false,
      'gcode',
      "Print the objects one at a time, each to its full height before the next starts (PrusaSlicer's complete objects, Cura's one at a time): between objects the nozzle retracts, rises above everything printed so far, travels to the next object and comes down. Objects go in the order given, the tallest last when it is taller than extruderClearanceHeight. Refused before slicing when two objects' footprints are closer than extruderClearanceRadius, when an object other than the last is taller than extruderClearanceHeight, or with a raft; arranged models are spaced by extruderClearanceRadius. The skirt or brim is printed once, round every object, with the first object's first layer; layers are numbered on through the whole print, so Z goes down at each new object.",
    ),
    null,
    'several-models',
  ),
  extruderClearanceRadius: when(
    num(
      45,
      0,
      300,
      'mm',
      'gcode',
      "Sequential printing: radius round the nozzle that the print head (extruder, fan ducts) takes up and that must stay clear of the objects already printed; objects whose footprints come closer than this are refused (PrusaSlicer's extruder_clearance_radius).",
    ),
    { sequentialPrinting: true },
    'several-models',
  ),
  extruderClearanceHeight: when(
    num(
      20,
      0,
      2000,
      'mm',
      'gcode',
      "Sequential printing: height from the nozzle tip to the lowest part of the gantry (the X axis rods), which passes over the objects already printed; every object but the last must be at most this tall (PrusaSlicer's extruder_clearance_height, Cura's gantry_height).",
    ),
    { sequentialPrinting: true },
    'several-models',
  ),

  // ── arc fitting ──────────────────────────────────────────────────────────────
  arcFitting: bool(
    false,
    'gcode',
    'Replace runs of short segments along curves by G2/G3 arcs (the firmware must support arcs: Marlin ARC_SUPPORT, Klipper [gcode_arcs], RepRapFirmware, Prusa and Bambu firmware).',
  ),
  arcTolerance: when(
    num(
      0.01,
      0.001,
      0.2,
      'mm',
      'gcode',
      'Largest distance between an arc and the points of the path it replaces (the middle of each of its segments may be twice as far).',
    ),
    { arcFitting: true },
  ),

  // ── firmware retraction and pressure advance ─────────────────────────────────
  firmwareRetraction: bool(
    false,
    'travel',
    "Retract and prime with G10/G11, using the firmware's own lengths and speeds (Marlin FWRETRACT, Klipper [firmware_retraction], RepRapFirmware M207).",
  ),
  pressureAdvance: optNum(
    0,
    10,
    's',
    'gcode',
    "Pressure / linear advance for this filament: M900 K (Marlin), SET_PRESSURE_ADVANCE ADVANCE= (Klipper), M572 D0 S (RepRap). Empty (null) = keep the firmware's value.",
  ),

  // ── machine limits ───────────────────────────────────────────────────────────
  machineLimits: enm(
    ['estimate', 'write', 'ignore'] as const,
    'estimate',
    'machine',
    'How the limits below are used: by the time estimate only, also written at the start (M201/M203/M204/M205; Klipper SET_VELOCITY_LIMIT), or not at all.',
  ),
  maxSpeedX: optNum(
    1,
    2000,
    'mm/s',
    'machine',
    'Firmware feed-rate limit of the X axis (M203 X). Empty (null) = no limit.',
  ),
  maxSpeedY: optNum(
    1,
    2000,
    'mm/s',
    'machine',
    'Firmware feed-rate limit of the Y axis (M203 Y). Empty (null) = no limit.',
  ),
  maxSpeedZ: optNum(
    0.1,
    500,
    'mm/s',
    'machine',
    'Firmware feed-rate limit of the Z axis (M203 Z); Z moves are written at 5 mm/s or this, whichever is slower. Empty (null) = no limit.',
  ),
  maxSpeedE: optNum(
    0.1,
    500,
    'mm/s',
    'machine',
    'Firmware feed-rate limit of the extruder (M203 E), which caps retraction speed in the estimate. Empty (null) = no limit.',
  ),
  maxAccelerationX: optNum(
    10,
    100000,
    'mm/s²',
    'machine',
    'Firmware acceleration limit of the X axis (M201 X). Empty (null) = no limit.',
  ),
  maxAccelerationY: optNum(
    10,
    100000,
    'mm/s²',
    'machine',
    'Firmware acceleration limit of the Y axis (M201 Y). Empty (null) = no limit.',
  ),
  maxAccelerationZ: optNum(
    1,
    100000,
    'mm/s²',
    'machine',
    'Firmware acceleration limit of the Z axis (M201 Z). Empty (null) = acceleration.',
  ),
  maxAccelerationE: when(
    optNum(
      10,
      100000,
      'mm/s²',
      'machine',
      "Firmware acceleration limit of the extruder (M201 E; Klipper's max_extrude_only_accel, which limits retractions and primes). Empty (null) = no limit (Klipper: its default, acceleration × 4 nozzle² / filament cross-section).",
    ),
    { machineLimits: ['write', 'estimate'] },
  ),
  minimumCruiseRatio: when(
    num(
      0.5,
      0,
      0.99,
      '×',
      'machine',
      "Klipper's minimum_cruise_ratio ([printer] section, default 0.5): the time estimate of the Klipper flavour lowers the top speed of a short move so that at least this part of it is spent cruising. Older Klipper configs give max_accel_to_decel instead: the ratio is 1 − max_accel_to_decel / max_accel.",
    ),
    { gcodeFlavor: 'klipper' },
  ),
  travelAcceleration: optNum(
    10,
    100000,
    'mm/s²',
    'machine',
    'Acceleration of travel moves (M204 T). Empty (null) = acceleration.',
  ),
  retractAcceleration: optNum(
    10,
    100000,
    'mm/s²',
    'machine',
    'Acceleration of retractions and primes (M204 R). Empty (null) = maxAccelerationE, else acceleration.',
  ),
  jerkX: optNum(
    0.01,
    100,
    'mm/s',
    'machine',
    "Marlin's classic jerk of the X axis (M205 X; PrusaSlicer machine_max_jerk_x, Cura machine_max_jerk_xy): given any of jerkX–jerkE, the Marlin and RepRap time estimate takes junctions as classic-jerk firmware does, else by junction deviation (junctionDeviation). Empty (null) = jerkY, else cornerVelocity (when another jerk is given).",
  ),
  jerkY: optNum(
    0.01,
    100,
    'mm/s',
    'machine',
    "Marlin's classic jerk of the Y axis (M205 Y; machine_max_jerk_y, Cura machine_max_jerk_xy). Empty (null) = jerkX, else cornerVelocity (when another jerk is given).",
  ),
  jerkZ: optNum(
    0.01,
    100,
    'mm/s',
    'machine',
    "Marlin's classic jerk of the Z axis (M205 Z; machine_max_jerk_z; given, the estimate uses classic jerk). Empty (null) = Marlin's default, 0.3.",
  ),
  jerkE: optNum(
    0.01,
    100,
    'mm/s',
    'machine',
    "Marlin's classic jerk of the extruder (M205 E; machine_max_jerk_e; given, the estimate uses classic jerk). Empty (null) = Marlin's default, 5.",
  ),
  junctionDeviation: optNum(
    0.001,
    1,
    'mm',
    'machine',
    "Marlin's junction deviation (M205 J, junction_deviation_mm) for the Marlin and RepRap time estimate when no jerk is given. Empty (null) = from cornerVelocity: cornerVelocity² × (√2 − 1) / acceleration, so a 90° corner is taken at cornerVelocity (as Klipper's square-corner velocity).",
  ),

  // ── adhesion ─────────────────────────────────────────────────────────────────
  adhesionType: enm(
    ['skirt', 'brim', 'raft', 'none'] as const,
    'skirt',
    'adhesion',
    'First-layer helper: a skirt around the print, a brim attached to it, a raft under it, or none.',
  ),
  skirtLoops: when(int(1, 1, 20, 'count', 'adhesion', 'Skirt loops.'), { adhesionType: 'skirt' }),
  skirtDistance: when(num(3, 0, 50, 'mm', 'adhesion', 'Gap between the skirt and the print.'), {
    adhesionType: 'skirt',
  }),
  brimWidth: when(num(8, 0, 50, 'mm', 'adhesion', 'Brim width.'), { adhesionType: 'brim' }),

  // ── raft ─────────────────────────────────────────────────────────────────────
  raftMargin: when(
    num(3, 0, 50, 'mm', 'adhesion', 'How far the raft reaches beyond the first layer of the print (and its support).'),
    { adhesionType: 'raft' },
  ),
  raftBaseThickness: when(
    num(0.3, 0.05, 1.5, 'mm', 'adhesion', 'Thickness of the raft base layer (thick, wide lines on the bed).'),
    { adhesionType: 'raft' },
  ),
  raftBaseLineWidth: when(
    optNum(0.2, 3, 'mm', 'adhesion', 'Line width of the raft base. Empty (null) = 2 × nozzleDiameter.'),
    { adhesionType: 'raft' },
  ),
  raftBaseLineSpacing: when(
    optNum(0.2, 10, 'mm', 'adhesion', 'Distance between raft base lines. Empty (null) = 2 × the base line width.'),
    { adhesionType: 'raft' },
  ),
  raftInterfaceLayers: when(
    int(1, 0, 10, 'count', 'adhesion', 'Raft layers between the base and the surface, with lines across those below.'),
    { adhesionType: 'raft' },
  ),
  raftInterfaceLineSpacing: when(
    optNum(0.2, 10, 'mm', 'adhesion', 'Distance between raft interface lines. Empty (null) = 2.5 × lineWidth.'),
    { adhesionType: 'raft' },
  ),
  raftSurfaceLayers: when(int(2, 0, 10, 'count', 'adhesion', 'Solid raft layers the print stands on.'), {
    adhesionType: 'raft',
  }),
  raftAirGap: when(
    num(
      0.2,
      0,
      1,
      'mm',
      'adhesion',
      'Vertical gap between the raft surface and the first layer of the print, so the raft comes off.',
    ),
    { adhesionType: 'raft' },
  ),
  raftSpeed: when(
    num(20, 1, 1000, 'mm/s', 'adhesion', 'Speed of the raft base and interface layers (the surface uses skinSpeed).'),
    { adhesionType: 'raft' },
  ),

  // ── support ──────────────────────────────────────────────────────────────────
  supportEnabled: when(bool(false, 'support', 'Print support under overhangs.'), null, 'overhangs'),
  supportType: when(
    enm(
      ['normal', 'tree'] as const,
      'normal',
      'support',
      'Support shape: straight columns under each overhang (normal), or trees whose branches merge on their way down (less material, easier to remove).',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportPlacement: when(
    enm(
      ['everywhere', 'buildPlate'] as const,
      'everywhere',
      'support',
      'Where support may stand: anywhere (also on the part, with a floor), or only on the build plate.',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportThreshold: when(
    num(50, 0, 89, '°', 'support', 'Overhang angle from vertical beyond which a surface gets support.'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportMinArea: when(
    num(0.5, 0, 1000, 'mm²', 'support', 'Overhang areas smaller than this on a layer get no support (specks).'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportSkipBridges: when(
    num(
      0,
      0,
      500,
      'mm',
      'support',
      'Overhangs held at both sides by the layer below that span at most this far are bridged, not supported (0 = support every overhang).',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportPattern: when(
    enm(
      ['zigzag', 'lines', 'grid'] as const,
      'zigzag',
      'support',
      'Pattern of the support body: parallel lines joined at their ends (zigzag), separate lines, or a grid.',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportDensity: when(
    num(15, 1, 100, '%', 'support', 'Density of the support body.'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportAngle: when(
    num(0, -180, 180, '°', 'support', 'Direction of the support lines (the same on every layer, so they stack).'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportZGap: when(
    optNum(
      0,
      5,
      'mm',
      'support',
      'Vertical gap between the top of the support and the part above it, in whole layers. Empty (null) = one layer.',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportBottomZGap: when(
    optNum(
      0,
      5,
      'mm',
      'support',
      'Vertical gap between the part and support standing on it. Empty (null) = supportZGap.',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportXYGap: when(
    num(
      0.4,
      0,
      10,
      'mm',
      'support',
      'Horizontal gap between support and the part beside it (under an overhanging edge support comes closer, to half a support line width).',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportInterfaceLayers: when(
    int(2, 0, 20, 'count', 'support', 'Dense interface layers at the top of the support, under the part (roof).'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportFloorLayers: when(
    optNum(
      0,
      20,
      'count',
      'support',
      'Dense interface layers where support stands on the part (floor). Empty (null) = supportInterfaceLayers.',
      'integer',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportInterfaceDensity: when(
    num(70, 10, 100, '%', 'support', 'Density of the interface (roof and floor) lines.'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportWallCount: when(
    optNum(
      0,
      5,
      'count',
      'support',
      'Walls around the support body (roof and floor are dense lines without walls). Empty (null) = none for normal support, one for tree support.',
      'integer',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportLineWidth: when(
    optNum(0.1, 3, 'mm', 'support', 'Line width of support and its interface. Empty (null) = lineWidth.'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportSpeed: when(
    num(50, 1, 1000, 'mm/s', 'support', 'Speed of the support body.'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportLimitRetractions: when(
    bool(
      true,
      'support',
      'Travels from support to support on a layer do not retract, unless the straight line passes over the part (this layer or the one below): faster to print, with at most some strings inside the support.',
    ),
    { supportEnabled: true },
    'overhangs',
  ),
  supportInterfaceSpeed: when(
    num(35, 1, 1000, 'mm/s', 'support', 'Speed of the support interface (roof and floor).'),
    { supportEnabled: true },
    'overhangs',
  ),
  supportTreeBranchAngle: when(
    num(
      40,
      5,
      80,
      '°',
      'support',
      'Tree support: the steepest angle from vertical at which branches lean towards each other as they go down.',
    ),
    { supportEnabled: true, supportType: 'tree' },
    'overhangs',
  ),
  supportTreeTipDiameter: when(
    num(0.8, 0.2, 10, 'mm', 'support', 'Tree support: diameter of a branch tip under the part.'),
    { supportEnabled: true, supportType: 'tree' },
    'overhangs',
  ),
  supportTreeBranchDiameter: when(
    num(
      2,
      0.5,
      50,
      'mm',
      'support',
      'Tree support: diameter a branch grows to (trunks where branches merged grow further, by the diameter angle).',
    ),
    { supportEnabled: true, supportType: 'tree' },
    'overhangs',
  ),
  supportTreeDiameterAngle: when(
    num(
      5,
      0,
      30,
      '°',
      'support',
      'Tree support: how fast a merged branch thickens on its way down (angle of its sides from vertical).',
    ),
    { supportEnabled: true, supportType: 'tree' },
    'overhangs',
  ),
  supportTreeTipSpacing: when(
    optNum(
      0.5,
      20,
      'mm',
      'support',
      'Tree support: distance between branch tips (closer holds the part better, further apart uses less material). Empty (null) = 3 mm under a roof, 1.5 mm with no roof (supportInterfaceLayers 0), where the tips hold the part itself.',
    ),
    { supportEnabled: true, supportType: 'tree' },
    'overhangs',
  ),

  // ── bridges and overhangs ────────────────────────────────────────────────────
  bridgeSpeed: when(num(25, 1, 1000, 'mm/s', 'skin', 'Speed of skin printed over air (bridges).'), null, 'overhangs'),
  bridgeFlow: when(
    num(
      100,
      10,
      200,
      '%',
      'skin',
      "Flow of bridge lines: % of a round bead one nozzle diameter across (PrusaSlicer's bridge flow ratio with thick bridges), which sags into the gap below the layer as a strand does; skin-wall and other skin runs over air that are not bridge lines (over a cantilever) print at this % of their normal flow.",
    ),
    null,
    'overhangs',
  ),
  bridgeSpacing: when(
    optNum(
      0.1,
      5,
      'mm',
      'skin',
      "Distance between bridge lines. Empty (null) = nozzleDiameter + 0.05 mm (PrusaSlicer's spacing of its round bridge beads). Lines are spread evenly over each bridge, never further apart than this, so none is left narrower beside the walls.",
    ),
    null,
    'overhangs',
  ),
  bridgeAnchor: when(
    num(
      2,
      0,
      20,
      'mm',
      'skin',
      "How far bridges reach onto the part held by the layer below, mm: the bridge is grown by this much into the solid and sparse area round it, and its lines run across the gap in the bridge direction and end that far onto support on both sides (PrusaSlicer's bridge anchoring, Cura's bridge skin support). 0 = bridge lines stop where the air ends.",
    ),
    null,
    'overhangs',
  ),
  bridgeFanSpeed: when(num(100, 0, 100, '%', 'cooling', 'Part-cooling fan while printing bridges.'), null, 'overhangs'),
  overhangWallSpeed: when(
    num(15, 1, 1000, 'mm/s', 'walls', 'Speed of walls where they hang over nothing on the layer below.'),
    null,
    'overhangs',
  ),
  dynamicOverhangSpeeds: when(
    bool(
      false,
      'walls',
      "Slow walls down by how much of the line hangs over nothing on the layer below, in four steps: a quarter of the line width or more (overhangSpeed25), half (overhangSpeed50), three quarters (overhangSpeed75) and all of it (overhangWallSpeed), as PrusaSlicer's dynamic overhang speeds and OrcaSlicer's overhang speeds. Off: only walls wholly over nothing are slowed.",
    ),
    null,
    'overhangs',
  ),
  overhangSpeed25: when(
    num(
      25,
      1,
      1000,
      'mm/s',
      'walls',
      'Speed of walls with a quarter to half of the line width over nothing on the layer below (never faster than the wall itself).',
    ),
    { dynamicOverhangSpeeds: true },
    'overhangs',
  ),
  overhangSpeed50: when(
    num(
      20,
      1,
      1000,
      'mm/s',
      'walls',
      'Speed of walls with half to three quarters of the line width over nothing on the layer below.',
    ),
    { dynamicOverhangSpeeds: true },
    'overhangs',
  ),
  overhangSpeed75: when(
    num(
      15,
      1,
      1000,
      'mm/s',
      'walls',
      'Speed of walls with three quarters or more (not all) of the line width over nothing on the layer below.',
    ),
    { dynamicOverhangSpeeds: true },
    'overhangs',
  ),
  overhangFanSpeed: when(
    optNum(
      0,
      100,
      '%',
      'cooling',
      "Part-cooling fan while printing overhanging walls: the runs wholly over nothing and, with dynamicOverhangSpeeds, every run with a quarter of its width or more over nothing. Empty (null) = fanSpeed: the layer's fan, unchanged.",
    ),
    null,
    'overhangs',
  ),
  extraPerimetersOnOverhangs: when(
    bool(
      false,
      'walls',
      "Fill overhangs inside an island that cannot bridge (held on one side only, as a cantilever or a steep slope's inside) with extra walls instead of skin and infill: nested lines parallel to the island's walls, anchored in the part held by the layer below and printed from there outwards, each beside the one before, ahead of the walls (PrusaSlicer's extra perimeters on overhangs).",
    ),
    null,
    'overhangs',
  ),

  // ── scarf seams and fuzzy skin ───────────────────────────────────────────────
  scarfSeam: enm(
    ['off', 'outer', 'all'] as const,
    'off',
    'walls',
    "Scarf joint seams: a wall loop starts on a ramp, the nozzle rising from scarfStartHeight to the layer's height and the flow growing with it over scarfLength, and ends by printing over the ramp again at the layer's height with the flow shrinking to nothing, so the seam is a long slope instead of a blob. On the outer wall's loops (outer, holes included), on every wall loop (all), or nowhere (off). Never on the first layer; a loop shorter than scarfLength keeps a plain seam.",
  ),
  scarfLength: when(num(20, 0.5, 200, 'mm', 'walls', 'Length of the scarf ramp along the loop, from the seam.'), {
    scarfSeam: ['outer', 'all'],
  }),
  scarfStartHeight: when(
    num(
      10,
      0,
      90,
      '%',
      'walls',
      'Where the scarf ramp starts above the layer below, % of the layer height (the nozzle never comes closer than 0.02 mm to the layer below).',
    ),
    { scarfSeam: ['outer', 'all'] },
  ),
  scarfSteps: when(
    int(
      10,
      1,
      100,
      'count',
      'walls',
      'The scarf ramp is written as at least this many moves of equal length (more where the loop has corners within it), Z and flow rising along each.',
    ),
    { scarfSeam: ['outer', 'all'] },
  ),
  scarfConditional: when(
    bool(
      false,
      'walls',
      "Scarf only where the seam is not in a sharp corner (one turning 40° or more within a line width either side, where an aligned seam hides): a corner's seam stays plain.",
    ),
    { scarfSeam: ['outer', 'all'] },
  ),
  fuzzySkin: enm(
    ['off', 'outer', 'all'] as const,
    'off',
    'walls',
    "A rough, textured surface: the outer wall is redrawn through points about fuzzySkinPointDistance apart, each moved in or out across the wall by up to fuzzySkinThickness (seeded by the layer and the wall's shape, so the G-code is the same every run). On the part's outside (outer), on the outer wall of holes too (all), or nowhere (off). Inner walls stay smooth; never on the first layer.",
  ),
  fuzzySkinThickness: when(
    num(
      0.3,
      0.01,
      2,
      'mm',
      'walls',
      'How far fuzzy skin moves each point in or out of the wall, at most (the texture is twice this deep).',
    ),
    { fuzzySkin: ['outer', 'all'] },
  ),
  fuzzySkinPointDistance: when(
    num(0.8, 0.1, 10, 'mm', 'walls', 'Average distance between the points of a fuzzy wall (each gap ¾ to 1¼ of it).'),
    { fuzzySkin: ['outer', 'all'] },
  ),

  // ── spiral vase ──────────────────────────────────────────────────────────────
  spiralVase: bool(
    false,
    'walls',
    "Spiral vase mode: after the bottom layers (bottomSkinThickness, printed as set) every layer is one outer wall whose Z rises steadily round the turn from the layer below's height to its own, so the print is one continuous spiral with no seam, no layer-change travel and no retraction. Above the bottom there is one wall, no infill, no top skin, no support, no ironing and no scarf; settings that ask for those are reported as ignored. The first turn grows its flow from nothing and a last flat turn at the top shrinks it to nothing, so the spiral starts and ends level. Holes are dropped (a vase modelled hollow spirals on its outside) and specks under 1 mm² beside the main island left out; a layer that is still not one single loop (several islands of size) is printed flat, and reported.",
  ),

  // ── runtime ──────────────────────────────────────────────────────────────────
  threads: int(
    0,
    0,
    256,
    'count',
    'runtime',
    'Threads for the per-layer stages (0 = automatic: one per core above two cores, else one). The G-code is the same for any count.',
  ),
} as const satisfies Record<string, SettingDef>;

export type SettingKey = keyof typeof SCHEMA;
export const SETTING_KEYS = Object.keys(SCHEMA) as SettingKey[];

type ValueOfDef<D> = D extends { type: 'enum'; values: readonly (infer V)[] }
  ? V
  : D extends { type: 'boolean' }
    ? boolean
    : D extends { type: 'string' }
      ? string
      : D extends { nullable: true }
        ? number | null
        : number;

/** Every setting with its value type, as given by a user (before derivation). */
export type Settings = { -readonly [K in SettingKey]: ValueOfDef<(typeof SCHEMA)[K]> };

/** Options as a caller passes them: any subset, plus preset names. */
export type SliceOptions = Partial<Settings> & { printer?: string; filament?: string };
