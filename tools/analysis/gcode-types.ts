/** Plain-data result of parsing G-code: layers of extrusion and travel segments in typed arrays. */

/** Extrusion segments, one entry per index in every column. Coordinates in mm, E in mm of filament. */
export interface ExtrusionTable {
  count: number;
  x0: Float32Array;
  y0: Float32Array;
  x1: Float32Array;
  y1: Float32Array;
  /** Print Z of the segment (Z at its end). */
  z: Float32Array;
  /** Filament pushed along the segment (> 0). */
  e: Float32Array;
  /** Feedrate in mm/min. */
  feedrate: Float32Array;
  /** Feature code, an index into FEATURE_NAMES. */
  feature: Uint8Array;
}

/** Non-extruding moves (including wipes that retract while moving). */
export interface TravelTable {
  count: number;
  x0: Float32Array;
  y0: Float32Array;
  z0: Float32Array;
  x1: Float32Array;
  y1: Float32Array;
  z1: Float32Array;
}

/** Kinds of entries in a RetractionTable. */
export const RetractionKind = { Retract: 0, Prime: 1, FirmwareRetract: 2, FirmwarePrime: 3 } as const;

/**
 * Retractions (negative E), primes (positive E without XY motion while a retraction is pending), and G10/G11
 * firmware retractions.
 */
export interface RetractionTable {
  count: number;
  kind: Uint8Array;
  /** Filament length in mm (0 for firmware retractions, whose length lives in the firmware). */
  amount: Float32Array;
  /** 1-based line number in the G-code. */
  line: Uint32Array;
  /** Layer index, -1 for the preamble. */
  layer: Int32Array;
}

export interface GcodeLayer {
  /** 0-based position in the parsed layer list (sorted by Z). */
  index: number;
  /** Print Z: the Z carrying most of this layer's extrusion length. */
  z: number;
  /** Z minus the previous layer's Z (the first layer: its Z). */
  thickness: number;
  /** Smallest and largest Z of this layer's extrusion segments (differ only for non-planar or odd G-code). */
  zMin: number;
  zMax: number;
  /** The first `;LAYER:n` value (or `;LAYER_CHANGE` ordinal) merged into this layer, null without markers. */
  marker: number | null;
  /** The layer height the G-code declares for this layer (its first `;HEIGHT:`), null when it declares none. */
  declaredHeight: number | null;
  extrusions: ExtrusionTable;
  travels: TravelTable;
}

export type ExtrusionMode = 'absolute' | 'relative' | 'mixed';

/** Filament totals in mm. */
export interface ETotals {
  /** Mode(s) the G-code used for E while extruding. */
  mode: ExtrusionMode;
  /** Sum of E on moves that extrude (E > 0 with XY motion). */
  extruded: number;
  /** Sum of retraction lengths (negative E). */
  retracted: number;
  /** Sum of positive E without XY motion: primes after retractions and stationary purges. */
  primed: number;
  /** Net filament: extruded + primed - retracted. */
  net: number;
  /** Net filament if every E word were read as absolute, or as relative: a sanity view of the declared mode. */
  asIfAbsolute: number;
  asIfRelative: number;
}

export interface RetractionBalance {
  retractions: number;
  primes: number;
  firmwareRetractions: number;
  /** Extrusions that started while the filament was retracted or over-primed by more than the tolerance. */
  unbalanced: number;
  /** Line numbers of the first few unbalanced extrusion starts. */
  unbalancedLines: number[];
  /** Retraction still pending at the end of the file (normal: the end G-code retracts), mm. */
  trailingMm: number;
}

export interface GcodeExtents {
  min: [number, number, number];
  max: [number, number, number];
}

export interface ParsedGcode {
  layers: GcodeLayer[];
  /** Extrusions and travels before the first layer marker (start G-code, purge lines); empty without markers. */
  preamble: { extrusions: ExtrusionTable; travels: TravelTable };
  retractions: RetractionTable;
  e: ETotals;
  balance: RetractionBalance;
  hasLayerMarkers: boolean;
  hasTypeMarkers: boolean;
  /** `;TYPE:` names that are not recognised (treated as UNKNOWN). */
  unknownTypes: string[];
  lineCount: number;
  /** Extents of the layers' extrusion segments; null when nothing was extruded. */
  extents: GcodeExtents | null;
}
