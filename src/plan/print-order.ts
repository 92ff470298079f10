/**
 * Print order and feature of every path role, as data: which entries of a group print first, which G-code
 * feature type each is, at what speed, and how the parts of it over air print. The planner reads these
 * tables and nothing else about roles.
 */
import type { PathEntry, PathRole } from '../paths/types.js';
import type { Config } from '../settings/resolve.js';
import type { FeatureType } from './types.js';

/** Within a group, entries print in this order (walls among themselves by the wallOrder setting). */
export const PRINT_ORDER: readonly PathRole[] = [
  'raft-base',
  'raft-interface',
  'raft-surface',
  'skirt',
  'brim',
  'support-floor',
  'support',
  'support-roof',
  'wall',
  'wall-gap',
  'infill',
  'skin-wall',
  'skin',
  'skin-gap',
];

/** Groups of a layer print in this order; islands among themselves nearest-first. */
export const GROUP_ORDER = ['adhesion', 'support', 'island'] as const;

interface RoleStyle {
  feature: FeatureType | ((entry: PathEntry) => FeatureType);
  speed: (cfg: Config) => number;
}

/** How runs over air (PathEntry.overAir) print. */
interface OverAirStyle {
  /** Without a feature of its own the run keeps the entry's and is only ever slowed down (never sped up). */
  feature?: FeatureType;
  speed: (cfg: Config) => number;
  flow?: (cfg: Config) => number;
  /** Part-cooling fan, 0..1. */
  fan?: (cfg: Config) => number;
}

export const ROLE_STYLE: Readonly<Record<PathRole, RoleStyle>> = {
  'raft-base': { feature: 'RAFT', speed: (c) => c.raftSpeed },
  'raft-interface': { feature: 'RAFT', speed: (c) => c.raftSpeed },
  'raft-surface': { feature: 'RAFT', speed: (c) => c.skinSpeed },
  skirt: { feature: 'SKIRT', speed: (c) => c.firstLayerSpeed },
  brim: { feature: 'BRIM', speed: (c) => c.firstLayerSpeed },
  'support-floor': { feature: 'SUPPORT-INTERFACE', speed: (c) => c.supportInterfaceSpeed },
  support: { feature: 'SUPPORT', speed: (c) => c.supportSpeed },
  'support-roof': { feature: 'SUPPORT-INTERFACE', speed: (c) => c.supportInterfaceSpeed },
  wall: { feature: (e) => (e.wall === 0 ? 'WALL-OUTER' : 'WALL-INNER'), speed: (c) => c.perimeterSpeed },
  'wall-gap': { feature: 'WALL-INNER', speed: (c) => c.innerWallSpeed },
  infill: { feature: 'FILL', speed: (c) => c.infillSpeed },
  'skin-wall': { feature: 'SKIN', speed: (c) => c.skinSpeed },
  skin: { feature: 'SKIN', speed: (c) => c.skinSpeed },
  'skin-gap': { feature: 'SKIN', speed: (c) => c.skinSpeed },
};

/** Inner walls print at their own speed. */
export function roleSpeed(entry: PathEntry, cfg: Config): number {
  if (entry.role === 'wall' && entry.wall !== 0) return cfg.innerWallSpeed;
  return ROLE_STYLE[entry.role].speed(cfg);
}

export function roleFeature(entry: PathEntry): FeatureType {
  const f = ROLE_STYLE[entry.role].feature;
  return typeof f === 'function' ? f(entry) : f;
}

const BRIDGE: OverAirStyle = {
  feature: 'BRIDGE',
  speed: (c) => c.bridgeSpeed,
  flow: (c) => c.bridgeFlow / 100,
  fan: (c) => c.bridgeFanSpeed / 100,
};
const OVERHANG_WALL: OverAirStyle = { speed: (c) => c.overhangWallSpeed };

/** The over-air style of a role (roles without one print their runs over air like the rest). */
export const OVER_AIR_STYLE: Readonly<Partial<Record<PathRole, OverAirStyle>>> = {
  wall: OVERHANG_WALL,
  skin: BRIDGE,
  'skin-wall': BRIDGE,
};

/** Whether the parts of a role's paths over air print any differently (else they are not marked at all). */
export function overAirMatters(role: PathRole, cfg: Config): boolean {
  const air = OVER_AIR_STYLE[role];
  if (!air) return false;
  if (air.feature) return true;
  // a run that keeps its feature only slows down
  return air.speed(cfg) < (role === 'wall' ? Math.max(cfg.perimeterSpeed, cfg.innerWallSpeed) : ROLE_STYLE[role].speed(cfg));
}

/** Sort a group's entries into print order (stable: entries of one role keep the builder's order). */
export function sortEntries(entries: readonly PathEntry[], wallOrder: Config['wallOrder']): PathEntry[] {
  if (entries.length < 2) return entries.slice();
  const rank = (e: PathEntry) => PRINT_ORDER.indexOf(e.role);
  const wallKey = (e: PathEntry) => (e.wall ?? 0) * (wallOrder === 'inner-first' ? -1 : 1);
  const before = (a: PathEntry, b: PathEntry) => rank(a) - rank(b) || (a.role === 'wall' && b.role === 'wall' ? wallKey(a) - wallKey(b) : 0);
  // most groups come in print order already (a tree branch's wall, then its line): the stable sort would keep them
  let sorted = true;
  for (let i = 1; i < entries.length && sorted; i++) sorted = before(entries[i - 1], entries[i]) <= 0;
  if (sorted) return entries.slice();
  return entries
    .map((e, i) => ({ e, i }))
    .sort((a, b) => before(a.e, b.e) || a.i - b.i)
    .map((x) => x.e);
}
