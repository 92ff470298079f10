/**
 * The library's public API, shared by the Node entry (index.ts) and the browser entry (browser.ts).
 */
export { Slicer, prepareModel, settingsSchema } from './api/slicer.js';
export type { SliceResult, SliceStats, SliceCallOptions, PreparedModel, ObjectOptions } from './api/slicer.js';
export { StrataError } from './errors.js';
export type { ErrorCode } from './errors.js';
export { SCHEMA, SETTING_KEYS } from './settings/schema.js';
export type { Settings, SliceOptions, SettingKey, SettingDef } from './settings/schema.js';
export { SETTING_SCOPE } from './settings/scope.js';
export type { Scope } from './settings/scope.js';
export { resolveConfig } from './settings/resolve.js';
export { importProfile } from './profiles/index.js';
export type { ImportedProfile, ProfileFormat } from './profiles/index.js';
export type { Config } from './settings/resolve.js';
export { listPresets, findPrinter, findFilament, PRINTER_PRESETS, FILAMENT_PRESETS } from './settings/presets/index.js';
export {
  parseStl,
  parseObj,
  parse3mf,
  fromThree,
  fromArrays,
  toMeshObjects,
  loadModelBytes,
  prepareMesh,
} from './mesh/index.js';
export type {
  Mesh,
  MeshObject,
  MeshReport,
  RawMeshArrays,
  MeshVolume,
  VolumeKind,
  SettingsSource,
  LayerRangeSettings,
} from './mesh/types.js';
export { PATTERN_IDS } from './infill/types.js';
export type { PatternId, InfillPattern } from './infill/types.js';
export type { PrintPlan, LayerPlan, PlanStep, FeatureType } from './plan/types.js';
export type { Progress } from './pipeline/run.js';
export { VERSION } from './pipeline/run.js';
// streaming G-code to a Marlin printer over a serial line (Web Serial in a page, a serial port in Node)
export { MarlinSender, gcodeCommands, numberedLine, CANCEL_GCODE } from './send/marlin-serial.js';
export type { MarlinOptions } from './send/marlin-serial.js';
export { loadCustomInfill } from './infill/registry.js';
export type { CustomInfillSpec, CustomDensity } from './infill/patterns/custom.js';
export { FEATURE_TYPES } from './plan/types.js';
export { TYPE_MARKERS } from './gcode/writer.js';
export { planToArrays, SEGMENT_STRIDE, TRAVEL_STRIDE, RETRACTION_STRIDE } from './preview/plan-arrays.js';
export type { PreviewArrays } from './preview/plan-arrays.js';
