/**
 * The library's public API, shared by the Node entry (index.ts) and the browser entry (browser.ts).
 */
export { Slicer, prepareModel, settingsSchema } from './api/slicer.js';
export type {
  SliceResult,
  SliceStats,
  SliceCallOptions,
  PreparedModel,
  ObjectOptions,
  SaveProjectOptions,
} from './api/slicer.js';
export { StrataError } from './errors.js';
export type { ErrorCode } from './errors.js';
export { SCHEMA, SETTING_KEYS } from './settings/schema.js';
export type { Settings, SliceOptions, SettingKey, SettingDef } from './settings/schema.js';
export { SETTING_SCOPE } from './settings/scope.js';
export type { Scope } from './settings/scope.js';
export { resolveConfig } from './settings/resolve.js';
// checking settings one at a time, as a settings editor does
export {
  checkSettingKey,
  validateSetting,
  checkSettingScope,
  resolveScopedConfig,
} from './api/settings.js';
export type { ScopeUse, ScopedSettingsLayer } from './api/settings.js';
export { importProfile, settingsFromSource } from './profiles/index.js';
export type { ImportedProfile, ProfileFormat, ObjectSettings } from './profiles/index.js';
export type { RejectedValue } from './profiles/context.js';
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
  loadModelFile,
  mergeObjects,
  prepareMesh,
} from './mesh/index.js';
export type { LoadedFile, LoadOptions } from './mesh/index.js';
// placing objects on the bed as the slicer does, for a plate editor
export {
  IDENTITY_LINEAR,
  axisRotation,
  linearBounds,
  multiplyLinear,
  placeObjects,
  placementAffine,
  rotationBetween,
  transformMesh,
  ARRANGE_GAP_MM,
  arrange,
  findSpot,
  footprintsOverlap,
} from './api/placement.js';
export type { Affine, Box, Placement, Bed, Footprint, PlacedFootprint } from './api/placement.js';
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
export type { PrintPlan, LayerPlan, PlanStep, FeatureType, PlanEstimate } from './plan/types.js';
export { estimatePlan } from './plan/estimate.js';
export type { EstimateSettings } from './plan/estimate.js';
export type { Progress } from './pipeline/run.js';
export { VERSION } from './pipeline/run.js';
// streaming G-code to a Marlin printer over a serial line (Web Serial in a page, a serial port in Node)
export { MarlinSender, gcodeCommands, numberedLine, CANCEL_GCODE } from './send/marlin-serial.js';
export type { MarlinOptions } from './send/marlin-serial.js';
export { loadCustomInfill } from './infill/registry.js';
export type { CustomInfillSpec, CustomDensity } from './infill/patterns/custom.js';
export { describeCustomInfill } from './api/custom-infill-info.js';
export type { CustomInfillInfo } from './api/custom-infill-info.js';
export { FEATURE_TYPES } from './plan/types.js';
export { TYPE_MARKERS } from './gcode/writer.js';
export {
  planToArrays,
  transferList as previewTransferList,
  SEGMENT_STRIDE,
  TRAVEL_STRIDE,
  RETRACTION_STRIDE,
} from './preview/plan-arrays.js';
export type { PreviewArrays } from './preview/plan-arrays.js';
export { FEATURE_COLOURS } from './preview/svg.js';
