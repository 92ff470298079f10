/**
 * The seeds' library's options, each either mapped onto a Strata setting (with the quantity that says
 * which unit option applies, and a conversion where the two differ) or kept: accepted, validated, read back
 * by its getter, with no effect on Strata's G-code (written by Strata's own writer and the printer preset's
 * start and end G-code: homing, wiping, the buzzer, the metadata header and the number precision are
 * theirs). README's "From three.js" section lists them.
 */
import type { PatternId } from '../infill/types.js';
import type { Config } from '../settings/resolve.js';
import type { SettingKey } from '../settings/schema.js';
import type { AngleUnit, LengthUnit, Quantity, SpeedUnit, TemperatureUnit, TimeUnit } from './units.js';

/** What the seeds' progress callback receives. */
export interface ProgressInfo {
  stage: 'initializing' | 'slicing' | 'post-print' | 'complete';
  /** 0–100 */
  percent: number;
  currentLayer: number | null;
  totalLayers: number | null;
  message: string | null;
}

/** Every option of the seeds' library with its value type (lengths, speeds, temperatures and angles in the caller's units). */
export interface PolysliceSettings {
  autohome: boolean;
  workspacePlane: 'XY' | 'XZ' | 'YZ';
  timeUnit: TimeUnit;
  lengthUnit: LengthUnit;
  speedUnit: SpeedUnit;
  temperatureUnit: TemperatureUnit;
  angleUnit: AngleUnit;
  nozzleTemperature: number;
  bedTemperature: number;
  fanSpeed: number;
  layerHeight: number;
  extrusionMultiplier: number;
  filamentDiameter: number;
  nozzleDiameter: number;
  perimeterSpeed: number;
  infillSpeed: number;
  travelSpeed: number;
  retractionDistance: number;
  retractionSpeed: number;
  buildPlateWidth: number;
  buildPlateLength: number;
  infillDensity: number;
  infillPattern: PatternId;
  infillPatternCentering: 'object' | 'global';
  shellSkinThickness: number;
  shellWallThickness: number;
  exposureDetection: boolean;
  exposureDetectionResolution: number;
  supportEnabled: boolean;
  supportType: 'normal' | 'tree';
  supportPlacement: 'buildPlate' | 'everywhere';
  supportThreshold: number;
  supportGap: number;
  supportDensity: number;
  supportRootsEnabled: boolean;
  supportRootCount: number;
  supportBranchAngle: number;
  supportTwigAngle: number;
  adhesionEnabled: boolean;
  adhesionType: 'skirt' | 'brim' | 'raft';
  skirtType: 'circular' | 'shape';
  skirtDistance: number;
  skirtLineCount: number;
  brimDistance: number;
  brimLineCount: number;
  raftMargin: number;
  raftBaseThickness: number;
  raftInterfaceLayers: number;
  raftInterfaceThickness: number;
  raftAirGap: number;
  raftLineSpacing: number;
  testStrip: boolean;
  metadata: boolean;
  verbose: boolean;
  metadataVersion: boolean;
  metadataTimestamp: boolean;
  metadataRepository: boolean;
  metadataPrinter: boolean;
  metadataFilament: boolean;
  metadataNozzleTemp: boolean;
  metadataBedTemp: boolean;
  metadataLayerHeight: boolean;
  metadataTotalLayers: boolean;
  metadataFilamentLength: boolean;
  metadataMaterialVolume: boolean;
  metadataMaterialWeight: boolean;
  metadataPrintTime: boolean;
  metadataFlavor: boolean;
  metadataInfillDensity: boolean;
  metadataInfillPattern: boolean;
  metadataWallCount: boolean;
  metadataSupport: boolean;
  metadataAdhesion: boolean;
  metadataSpeeds: boolean;
  metadataBoundingBox: boolean;
  coordinatePrecision: number;
  extrusionPrecision: number;
  feedratePrecision: number;
  meshPreprocessing: boolean;
  buzzer: boolean;
  wipeNozzle: boolean;
  smartWipeNozzle: boolean;
  positioningMode: 'absolute' | 'relative';
  extruderMode: 'absolute' | 'relative';
  progressCallback: ((info: ProgressInfo) => void) | null;
}

export type OptionName = keyof PolysliceSettings;

/** An option that is a Strata setting. `to`/`from` convert where the two differ (after/before the unit conversion). */
export interface MappedOption {
  kind: 'mapped';
  key: SettingKey;
  quantity: Quantity;
  to?: (value: number, cfg: Config) => number;
  from?: (cfg: Config) => number;
}

/** An option Strata takes and gives back, without effect on its G-code; `why` says what does that job instead. */
export interface KeptOption {
  kind: 'kept';
  quantity: Quantity;
  initial: unknown;
  /** The values it may take (else any value of the initial's type). */
  values?: readonly unknown[];
  why: string;
}

const mapped = (
  key: SettingKey,
  quantity: Quantity = 'plain',
  conv: Pick<MappedOption, 'to' | 'from'> = {},
): MappedOption => ({ kind: 'mapped', key, quantity, ...conv });
const kept = (
  initial: unknown,
  why: string,
  quantity: Quantity = 'plain',
  values?: readonly unknown[],
): KeptOption => ({ kind: 'kept', quantity, initial, why, ...(values ? { values } : {}) });

const HEADER = "Strata's G-code header always carries its metadata (what hosts read: see README)";
const PRECISION = "Strata's writer chooses the precision (3 decimals for XYZ, 5 for E, whole mm/min for F)";
const END = "the printer preset's end G-code";

/** The options with a Strata meaning or none; units, printer, filament, adhesion and the callback are handled apart. */
export const OPTIONS: Readonly<Partial<Record<OptionName, MappedOption | KeptOption>>> = {
  autohome: kept(true, "the printer preset's start G-code homes"),
  workspacePlane: kept('XY', 'Strata prints in the XY plane', 'plain', ['XY', 'XZ', 'YZ']),
  nozzleTemperature: mapped('nozzleTemperature', 'temperature'),
  bedTemperature: mapped('bedTemperature', 'temperature'),
  fanSpeed: mapped('fanSpeed'),
  layerHeight: mapped('layerHeight', 'length'),
  extrusionMultiplier: mapped('flowRate', 'plain', { to: (v) => v * 100, from: (c) => c.flowRate / 100 }),
  filamentDiameter: mapped('filamentDiameter', 'length'),
  nozzleDiameter: mapped('nozzleDiameter', 'length'),
  perimeterSpeed: mapped('perimeterSpeed', 'speed'),
  infillSpeed: mapped('infillSpeed', 'speed'),
  travelSpeed: mapped('travelSpeed', 'speed'),
  retractionDistance: mapped('retractionDistance', 'length'),
  retractionSpeed: mapped('retractionSpeed', 'speed'),
  buildPlateWidth: mapped('buildPlateWidth', 'length'),
  buildPlateLength: mapped('buildPlateLength', 'length'),
  infillDensity: mapped('infillDensity'),
  infillPattern: mapped('infillPattern'),
  infillPatternCentering: mapped('infillPatternCentering'),
  shellSkinThickness: mapped('shellSkinThickness', 'length'),
  shellWallThickness: mapped('shellWallThickness', 'length'),
  exposureDetection: kept(true, 'Strata finds exposed top and bottom skin exactly, layer against layer, always'),
  exposureDetectionResolution: kept(961, 'Strata compares whole layers, not a grid of samples'),
  supportEnabled: mapped('supportEnabled'),
  supportType: mapped('supportType'),
  supportPlacement: mapped('supportPlacement'),
  supportThreshold: mapped('supportThreshold', 'angle'),
  supportGap: mapped('supportXYGap', 'length'),
  supportDensity: mapped('supportDensity'),
  supportRootsEnabled: kept(
    true,
    "Strata's trees have no separate roots: merged trunks widen by supportTreeDiameterAngle",
  ),
  supportRootCount: kept(4, "Strata's trees have no separate roots: merged trunks widen by supportTreeDiameterAngle"),
  supportBranchAngle: mapped('supportTreeBranchAngle', 'angle'),
  supportTwigAngle: kept(45, "Strata's trees have one branch angle (supportBranchAngle)", 'angle'),
  skirtType: kept('circular', "Strata draws its skirt skirtDistance around the first layer's outline", 'plain', [
    'circular',
    'shape',
  ]),
  skirtDistance: mapped('skirtDistance', 'length'),
  skirtLineCount: mapped('skirtLoops'),
  brimDistance: kept(0, "Strata's brim touches the part (that is what holds it down)", 'length'),
  brimLineCount: mapped('brimWidth', 'plain', {
    to: (v, c) => v * c.lineWidthMm,
    from: (c) => Math.round(c.brimWidth / c.lineWidthMm),
  }),
  raftMargin: mapped('raftMargin', 'length'),
  raftBaseThickness: mapped('raftBaseThickness', 'length'),
  raftInterfaceLayers: mapped('raftInterfaceLayers'),
  raftInterfaceThickness: kept(0.2, "Strata's raft interface layers are layerHeight thick", 'length'),
  raftAirGap: mapped('raftAirGap', 'length'),
  raftLineSpacing: mapped('raftBaseLineSpacing', 'length', {
    from: (c) => c.raftBaseLineSpacingMm,
  }),
  testStrip: kept(false, "the printer preset's start G-code draws a prime line"),
  metadata: kept(true, HEADER),
  verbose: kept(true, "Strata's G-code always names each feature (;TYPE:) and layer"),
  metadataVersion: kept(true, HEADER),
  metadataTimestamp: kept(true, HEADER),
  metadataRepository: kept(true, HEADER),
  metadataPrinter: kept(true, HEADER),
  metadataFilament: kept(true, HEADER),
  metadataNozzleTemp: kept(true, HEADER),
  metadataBedTemp: kept(true, HEADER),
  metadataLayerHeight: kept(true, HEADER),
  metadataTotalLayers: kept(true, HEADER),
  metadataFilamentLength: kept(true, HEADER),
  metadataMaterialVolume: kept(true, HEADER),
  metadataMaterialWeight: kept(true, HEADER),
  metadataPrintTime: kept(true, HEADER),
  metadataFlavor: kept(true, HEADER),
  metadataInfillDensity: kept(true, HEADER),
  metadataInfillPattern: kept(true, HEADER),
  metadataWallCount: kept(true, HEADER),
  metadataSupport: kept(true, HEADER),
  metadataAdhesion: kept(true, HEADER),
  metadataSpeeds: kept(true, HEADER),
  metadataBoundingBox: kept(true, HEADER),
  coordinatePrecision: kept(3, PRECISION),
  extrusionPrecision: kept(5, PRECISION),
  feedratePrecision: kept(0, PRECISION),
  meshPreprocessing: kept(false, 'Strata slices the mesh as it is, however sparse'),
  buzzer: kept(true, END),
  wipeNozzle: kept(true, `${END} retracts and lifts`),
  smartWipeNozzle: kept(true, `${END} retracts and lifts`),
  positioningMode: kept('absolute', 'Strata writes absolute XYZ positions (relative positioning is refused)', 'plain', [
    'absolute',
  ]),
  extruderMode: mapped('extruderMode'),
};
