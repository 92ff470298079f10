/**
 * Strata: a fast FFF slicer for Node and the browser.
 *
 *   import { Slicer } from 'strata-slicer';
 *   const { gcode, stats } = await new Slicer({ layerHeight: 0.2 }).slice(stlBytes);
 */
export { Slicer, prepareModel, settingsSchema } from './api/slicer.js';
export type { SliceResult, SliceStats, SliceCallOptions, PreparedModel } from './api/slicer.js';
export { StrataError } from './errors.js';
export type { ErrorCode } from './errors.js';
export { SCHEMA, SETTING_KEYS } from './settings/schema.js';
export type { Settings, SliceOptions, SettingKey, SettingDef } from './settings/schema.js';
export { resolveConfig } from './settings/resolve.js';
export { importProfile } from './settings/import/index.js';
export type { ImportedProfile, ProfileFormat } from './settings/import/index.js';
export type { Config } from './settings/resolve.js';
export { listPresets, findPrinter, findFilament, PRINTER_PRESETS, FILAMENT_PRESETS } from './settings/presets/index.js';
export { parseStl, parseObj, parse3mf, fromThree, fromArrays, toMeshObjects, loadModelBytes, prepareMesh } from './mesh/index.js';
export type { Mesh, MeshObject, MeshReport, RawMeshArrays } from './mesh/types.js';
export { PATTERN_IDS } from './infill/types.js';
export type { PatternId, InfillPattern } from './infill/types.js';
export type { PrintPlan, LayerPlan, PlanStep, FeatureType } from './plan/types.js';
export type { Progress } from './pipeline/run.js';
export { VERSION } from './pipeline/run.js';
