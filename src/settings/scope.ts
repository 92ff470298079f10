/**
 * Where a setting may vary. A print has one value of every `print` setting (temperatures, flavour, bed,
 * travel, cooling, layer heights: what the planner and the G-code writer read); an `object` setting may
 * differ from object to object (its skin thickness, its support); a `region` setting may differ from
 * object to object, between ranges of an object's layers and inside a modifier volume (walls, skin,
 * infill and their speeds: what the regions and paths stages read per island). A `layer` setting is the
 * same for every object at one height but may differ between layer ranges: the layer height, since the
 * plate has one Z plan (a range's layerHeight sets the plate's layers in its Z range, print-setup.ts).
 *
 * The scope follows from the stage a setting affects (schema.ts), with the exceptions listed here, each for
 * a reason: whoever reads the setting reads it once per print, or once per object.
 */
import { StrataError } from '../errors.js';
import { SCHEMA, SETTING_KEYS, type SettingKey, type Stage } from './schema.js';

export type Scope = 'print' | 'layer' | 'object' | 'region';

/** Settings of `region` stages that are read once per print or per object, not per island. */
const EXCEPTIONS: Partial<Record<SettingKey, Scope>> = {
  // one Z plan for the plate: a layer range may set the height of the plate's layers in its range
  layerHeight: 'layer',
  // the layer's line width sets its plan (LayerPaths.lineWidthMm, the skirt, the first layer)
  lineWidth: 'print',
  firstLayerLineWidth: 'print',
  // read by the planner for every loop of the layer
  wallOrder: 'print',
  seamPosition: 'print',
  randomSeed: 'print',
  firstLayerSpeed: 'print',
  // top and bottom skin read a window of the object's layers above and below
  shellSkinThickness: 'object',
  topSkinThickness: 'object',
  bottomSkinThickness: 'object',
  // the pattern's origin is the object's centre or the bed's
  infillPatternCentering: 'object',
  // a custom infill replaces the pattern of the whole print
  infillImagePixelSize: 'print',
  infillShaderResolution: 'print',
  // travel between support areas is the planner's
  supportLimitRetractions: 'print',
  // the planner spirals the whole layer, every object's walls in one turn
  spiralVase: 'print',
};

const BY_STAGE: Record<Stage, Scope> = {
  machine: 'print',
  mesh: 'print',
  slice: 'print',
  walls: 'region',
  skin: 'region',
  infill: 'region',
  support: 'object',
  adhesion: 'print',
  travel: 'print',
  cooling: 'print',
  gcode: 'print',
  runtime: 'print',
};

/** Every setting's scope. */
export const SETTING_SCOPE: Readonly<Record<SettingKey, Scope>> = Object.freeze(
  Object.fromEntries(SETTING_KEYS.map((k) => [k, EXCEPTIONS[k] ?? BY_STAGE[SCHEMA[k].stage]])) as Record<
    SettingKey,
    Scope
  >,
);

/** Where settings were given, for the scope check and its message. */
export type ScopeUse = 'object' | 'layer range' | 'modifier';

const ALLOWED: Record<ScopeUse, readonly Scope[]> = {
  object: ['object', 'region'],
  'layer range': ['region', 'layer'],
  modifier: ['region'],
};

/**
 * Throw (naming the key, where it was given and why) if a setting may not vary there: e.g. a nozzle
 * temperature given to one object, or a skin thickness given to a modifier.
 */
export function checkScope(key: SettingKey, use: ScopeUse, where: string): void {
  const scope = SETTING_SCOPE[key];
  if (ALLOWED[use].includes(scope)) return;
  const what =
    scope === 'print'
      ? 'is the same for the whole print'
      : scope === 'layer'
        ? 'is the same for every object at one height'
        : 'may vary per object but not inside one';
  const instead = scope === 'print' ? 'the print' : scope === 'layer' ? 'the print or a layer range' : 'the object';
  throw new StrataError(
    'BAD_SETTING',
    `${where}: ${key} ${what}, so it cannot be set for ${use === 'object' ? 'an' : 'a'} ${use}; set it for ${instead} instead`,
  );
}
