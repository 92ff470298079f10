/**
 * The one role table: for every kind of path, where it prints within its group, which G-code feature it
 * is, its speed and flow, how its runs over air print, and where its loops start. A path entry's style is
 * resolved from this table once, where the entry is made (`entryStyle`); the planner, the estimate and the
 * writer read the entry's style and never the role.
 */
import type { Config } from '../settings/resolve.js';

export const FEATURE_TYPES = [
  'WALL-OUTER',
  'WALL-INNER',
  'SKIN',
  'FILL',
  'BRIDGE',
  'SUPPORT',
  'SUPPORT-INTERFACE',
  'SKIRT',
  'BRIM',
  'RAFT',
  'IRONING',
] as const;
/** Feature types, named as Cura's `;TYPE:` markers so viewers understand them. */
export type FeatureType = (typeof FEATURE_TYPES)[number];

/** How runs over air (PathEntry.overAir) print. */
interface OverAirRule {
  /** Without a feature of its own the run keeps the entry's and is only ever slowed down (never sped up). */
  feature?: FeatureType;
  speed: (cfg: Config) => number;
  flow?: (cfg: Config) => number;
  /** Part-cooling fan, 0..1 (undefined: the layer's). */
  fan?: (cfg: Config) => number | undefined;
  /**
   * Runs partly over air, graded by how much of the line hangs over nothing: the speeds of the runs with a
   * quarter, half and three quarters of the line width or more over nothing (the fan as `fan`), or null when
   * the config does not grade them (then only runs wholly over air print their own way).
   */
  partial?: (cfg: Config) => readonly [number, number, number] | null;
}

interface RoleRule {
  /** Feature of the role; walls: of the outer wall (wall 0) and of the others. */
  feature: FeatureType;
  innerFeature?: FeatureType;
  speed: (cfg: Config) => number;
  innerSpeed?: (cfg: Config) => number;
  /** Flow multiplier of the role's lines (default 1). */
  flow?: (cfg: Config) => number;
  overAir?: OverAirRule;
  /** Loops start at the seam setting's place (`configured`) or wherever the nozzle is nearest. */
  seam: 'configured' | 'nearest';
  /** Closed loops may start on a scarf ramp (the scarfSeam setting says which walls). */
  scarf?: true;
}

const BRIDGE: OverAirRule = {
  feature: 'BRIDGE',
  speed: (c) => c.bridgeSpeed,
  flow: (c) => c.bridgeFlow / 100,
  fan: (c) => c.bridgeFanSpeed / 100,
};
const OVERHANG_WALL: OverAirRule = {
  speed: (c) => c.overhangWallSpeed,
  fan: (c) => (c.overhangFanSpeed === null ? undefined : c.overhangFanSpeed / 100),
  partial: (c) => (c.dynamicOverhangSpeeds ? [c.overhangSpeed25, c.overhangSpeed50, c.overhangSpeed75] : null),
};

/**
 * Every role, in print order within a group (walls among themselves by the wallOrder setting, then by
 * their index).
 */
export const ROLES = {
  'raft-base': { feature: 'RAFT', speed: (c) => c.raftSpeed, seam: 'nearest' },
  'raft-interface': { feature: 'RAFT', speed: (c) => c.raftSpeed, seam: 'nearest' },
  'raft-surface': { feature: 'RAFT', speed: (c) => c.skinSpeed, seam: 'nearest' },
  skirt: { feature: 'SKIRT', speed: (c) => c.firstLayerSpeed, seam: 'configured' },
  brim: { feature: 'BRIM', speed: (c) => c.firstLayerSpeed, seam: 'configured' },
  'support-floor': { feature: 'SUPPORT-INTERFACE', speed: (c) => c.supportInterfaceSpeed, seam: 'nearest' },
  support: { feature: 'SUPPORT', speed: (c) => c.supportSpeed, seam: 'nearest' },
  'support-roof': { feature: 'SUPPORT-INTERFACE', speed: (c) => c.supportInterfaceSpeed, seam: 'nearest' },
  // extra walls over an overhang inside an island (extraPerimetersOnOverhangs), before the island's walls
  'extra-wall': { feature: 'WALL-INNER', speed: (c) => c.innerWallSpeed, overAir: OVERHANG_WALL, seam: 'nearest' },
  wall: {
    feature: 'WALL-OUTER',
    innerFeature: 'WALL-INNER',
    speed: (c) => c.perimeterSpeed,
    innerSpeed: (c) => c.innerWallSpeed,
    overAir: OVERHANG_WALL,
    seam: 'configured',
    scarf: true,
  },
  'wall-gap': { feature: 'WALL-INNER', speed: (c) => c.innerWallSpeed, seam: 'nearest' },
  infill: { feature: 'FILL', speed: (c) => c.infillSpeed, seam: 'configured' },
  'skin-wall': { feature: 'SKIN', speed: (c) => c.skinSpeed, overAir: BRIDGE, seam: 'configured' },
  skin: { feature: 'SKIN', speed: (c) => c.skinSpeed, overAir: BRIDGE, seam: 'configured' },
  'skin-gap': { feature: 'SKIN', speed: (c) => c.skinSpeed, seam: 'nearest' },
  // a pass over the finished surface with a trickle of flow (ironing-paths.ts), after its skin
  ironing: { feature: 'IRONING', speed: (c) => c.ironingSpeed, flow: (c) => c.ironingFlow / 100, seam: 'nearest' },
} as const satisfies Record<string, RoleRule>;

/** What a path is for. */
export type PathRole = keyof typeof ROLES;
export const PATH_ROLES = Object.keys(ROLES) as PathRole[];
const RANK: Readonly<Record<PathRole, number>> = Object.fromEntries(PATH_ROLES.map((r, i) => [r, i])) as Record<
  PathRole,
  number
>;

/** How one run of extrusion prints. */
export interface ExtrusionStyle {
  feature: FeatureType;
  /** Feed rate, mm/s. */
  speed: number;
  /** Flow multiplier (1 = nominal). */
  flow: number;
  /** Part-cooling fan for the run, 0..1, when it differs from the layer's (bridges). */
  fan?: number;
}

/** A scarf seam, as the region's settings make it (the planner lays it: plan/scarf.ts). */
export interface ScarfStyle {
  /** Length of the ramp along the loop, mm. */
  length: number;
  /** Height above the layer below where the ramp starts, a fraction of the layer height. */
  startHeight: number;
  /** The ramp is at least this many moves. */
  steps: number;
  /** Only where the seam is not in a sharp corner. */
  conditional: boolean;
}

/** An entry's resolved style. */
export interface EntryStyle {
  normal: ExtrusionStyle;
  /** Runs over air; the same object as `normal` when they print no differently (then nothing is flagged). */
  overAir: ExtrusionStyle;
  /**
   * Walls graded by how much of the line hangs over nothing (dynamic overhang speeds): the style of each
   * over-air level, indexed by the edge's flag (0 `normal`; 1, 2, 3: a quarter, half, three quarters of the line
   * width or more over nothing; 4: all of it, as `overAir`). Absent: flags are 0 (`normal`) or 1 (`overAir`).
   */
  levels?: readonly ExtrusionStyle[];
  seam: 'configured' | 'nearest';
  /** Print order within a group (the role's rank). */
  rank: number;
  /** Closed loops start on a scarf ramp (absent: a plain seam). */
  scarf?: ScarfStyle;
}

/**
 * Styles made so far, by config: a memo of a pure function of the (frozen) config, so a slice that shares
 * a config with another gets the very styles it would make; held no longer than the config.
 */
const cache = new WeakMap<Config, Map<string, EntryStyle>>();

/** The style of a role's entries (walls: of wall `wall`), resolved once per config and shared. */
export function entryStyle(cfg: Config, role: PathRole, wall?: number): EntryStyle {
  let styles = cache.get(cfg);
  if (!styles) cache.set(cfg, (styles = new Map()));
  const key = wall === undefined ? role : role + wall;
  let s = styles.get(key);
  if (!s) styles.set(key, (s = makeStyle(cfg, role, wall)));
  return s;
}

function makeStyle(cfg: Config, role: PathRole, wall: number | undefined): EntryStyle {
  const rule: RoleRule = ROLES[role];
  const inner = wall !== undefined && wall > 0;
  const feature = inner && rule.innerFeature ? rule.innerFeature : rule.feature;
  const speed = (inner && rule.innerSpeed ? rule.innerSpeed : rule.speed)(cfg);
  const normal: ExtrusionStyle = { feature, speed, flow: rule.flow ? rule.flow(cfg) : 1 };
  let overAir = normal;
  let partial: readonly [number, number, number] | null = null;
  let levels: ExtrusionStyle[] | null = null;
  const air = rule.overAir;
  if (air) {
    const airSpeed = air.speed(cfg);
    const a: ExtrusionStyle = {
      feature: air.feature ?? feature,
      // a run that keeps its feature is only ever slowed down
      speed: air.feature ? airSpeed : Math.min(speed, airSpeed),
      flow: air.flow ? air.flow(cfg) : 1,
    };
    const fan = air.fan?.(cfg);
    if (fan !== undefined) a.fan = fan;
    const same =
      a.feature === normal.feature && a.speed === normal.speed && a.flow === normal.flow && a.fan === undefined;
    if (!same) overAir = a;
    partial = air.partial?.(cfg) ?? null;
    if (partial) levels = gradedLevels(normal, overAir, partial, fan);
  }
  const style: EntryStyle = { normal, overAir, seam: rule.seam, rank: RANK[role] };
  if (levels) style.levels = levels;
  const scarf = rule.scarf ? scarfOf(cfg, wall ?? 0) : undefined;
  if (scarf) style.scarf = scarf;
  return style;
}

/** The scarf seam of wall `wall`'s loops by the region's settings (none: undefined). */
function scarfOf(cfg: Config, wall: number): ScarfStyle | undefined {
  if (cfg.scarfSeam === 'off' || (cfg.scarfSeam === 'outer' && wall > 0)) return undefined;
  return {
    length: cfg.scarfLength,
    startHeight: cfg.scarfStartHeight / 100,
    steps: cfg.scarfSteps,
    conditional: cfg.scarfConditional,
  };
}

/**
 * The styles of the graded over-air levels of a wall (EntryStyle.levels): a run is only ever slowed down, and
 * levels that print alike share one style object (the planner joins runs of one style); null when every level
 * prints as the wall does.
 */
function gradedLevels(
  normal: ExtrusionStyle,
  overAir: ExtrusionStyle,
  speeds: readonly [number, number, number],
  fan: number | undefined,
): ExtrusionStyle[] | null {
  const levels: ExtrusionStyle[] = [normal];
  for (const s of speeds) {
    const speed = Math.min(normal.speed, s);
    const prev = levels[levels.length - 1];
    if (prev.speed === speed && prev.fan === fan) levels.push(prev);
    else if (speed === normal.speed && fan === undefined) levels.push(normal);
    else levels.push(fan === undefined ? { ...normal, speed } : { ...normal, speed, fan });
  }
  const last = levels[3];
  levels.push(
    last.speed === overAir.speed &&
      last.fan === overAir.fan &&
      last.feature === overAir.feature &&
      last.flow === overAir.flow
      ? last
      : overAir,
  );
  return levels.some((l) => l !== normal) ? levels : null;
}

/** Whether the parts of an entry's paths over air print any differently (else they are not marked at all). */
export function overAirMatters(style: EntryStyle): boolean {
  return style.overAir !== style.normal || style.levels !== undefined;
}

/** The style a run prints in by its edges' over-air flag (PathEntry.overAir). */
export function flagStyle(style: EntryStyle, flag: number): ExtrusionStyle {
  return style.levels ? style.levels[flag] : flag ? style.overAir : style.normal;
}

/** Groups of a layer print in this order; islands among themselves nearest-first. */
export const GROUP_ORDER = ['adhesion', 'support', 'island'] as const;
