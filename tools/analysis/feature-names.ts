/**
 * Canonical feature types of extrusion moves and the mapping from the `;TYPE:` names that slicers write
 * (Cura, PrusaSlicer, Orca/Bambu) to them.
 */

/** Canonical feature names, indexed by the numeric code stored per segment. */
export const FEATURE_NAMES = [
  'UNKNOWN',
  'WALL-OUTER',
  'WALL-INNER',
  'SKIN',
  'FILL',
  'SUPPORT',
  'SKIRT',
  'PRIME-TOWER',
  'IRONING',
  'CUSTOM',
  'SUPPORT-INTERFACE',
  'RAFT',
] as const;

export type FeatureName = (typeof FEATURE_NAMES)[number];

/** Numeric feature codes (index into FEATURE_NAMES). */
export const Feature = {
  Unknown: 0,
  WallOuter: 1,
  WallInner: 2,
  Skin: 3,
  Fill: 4,
  Support: 5,
  Skirt: 6,
  PrimeTower: 7,
  Ironing: 8,
  Custom: 9,
  /** Dense support lines under the part (roof) or on it (floor). */
  SupportInterface: 10,
  /** Raft layers under the part (a raft written with support names is recognised by position, see model-z.ts). */
  Raft: 11,
} as const satisfies Record<string, number>;

export const FEATURE_COUNT = FEATURE_NAMES.length;

/**
 * Whether a feature is material of the part itself (judged against the model's sections). Support, support
 * interface, raft, skirt/brim, prime towers, ironing passes and custom (start/end) G-code are not. Untyped moves
 * count as part material. Bridges are part skin.
 */
export function isPartFeature(code: number): boolean {
  return code <= Feature.Fill;
}

/** Support body or support interface (roof / floor); raft is not support. */
export function isSupportFeature(code: number): boolean {
  return code === Feature.Support || code === Feature.SupportInterface;
}

/** Type names, lower-cased with everything but letters and digits removed, to canonical codes. */
const TYPE_ALIASES: ReadonlyMap<string, number> = new Map<string, number>([
  // Cura
  ['wallouter', Feature.WallOuter],
  ['wallinner', Feature.WallInner],
  ['skin', Feature.Skin],
  ['fill', Feature.Fill],
  ['support', Feature.Support],
  ['supportinterface', Feature.SupportInterface],
  ['supportinfill', Feature.Support],
  ['supportroof', Feature.SupportInterface],
  ['supportbottom', Feature.SupportInterface],
  ['supportfloor', Feature.SupportInterface],
  ['raft', Feature.Raft],
  ['raftbase', Feature.Raft],
  ['raftinterface', Feature.Raft],
  ['raftsurface', Feature.Raft],
  ['skirt', Feature.Skirt],
  ['primetower', Feature.PrimeTower],
  // PrusaSlicer / SuperSlicer
  ['externalperimeter', Feature.WallOuter],
  ['overhangperimeter', Feature.WallOuter],
  ['perimeter', Feature.WallInner],
  ['internalperimeter', Feature.WallInner],
  ['gapfill', Feature.WallInner],
  ['solidinfill', Feature.Skin],
  ['topsolidinfill', Feature.Skin],
  ['bridgeinfill', Feature.Skin],
  ['internalbridgeinfill', Feature.Skin],
  ['internalinfill', Feature.Fill],
  ['skirtbrim', Feature.Skirt],
  ['brim', Feature.Skirt],
  ['supportmaterial', Feature.Support],
  ['supportmaterialinterface', Feature.SupportInterface],
  ['wipetower', Feature.PrimeTower],
  ['ironing', Feature.Ironing],
  ['custom', Feature.Custom],
  // Orca / Bambu Studio
  ['outerwall', Feature.WallOuter],
  ['overhangwall', Feature.WallOuter],
  ['innerwall', Feature.WallInner],
  ['gapinfill', Feature.WallInner],
  ['sparseinfill', Feature.Fill],
  ['internalsolidinfill', Feature.Skin],
  ['topsurface', Feature.Skin],
  ['bottomsurface', Feature.Skin],
  ['bridge', Feature.Skin],
  ['internalbridge', Feature.Skin],
  ['supporttransition', Feature.Support],
  ['treesupport', Feature.Support],
]);

/** Canonical code of a `;TYPE:` name, or -1 when the name is not known (the caller treats it as UNKNOWN). */
export function featureCodeOf(typeName: string): number {
  let key = '';
  for (let i = 0; i < typeName.length; i++) {
    const c = typeName.charCodeAt(i) | 0x20;
    if ((c >= 97 && c <= 122) || (c >= 48 && c <= 57)) key += String.fromCharCode(c);
  }
  const code = TYPE_ALIASES.get(key);
  return code === undefined ? -1 : code;
}
