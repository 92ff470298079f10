/**
 * What the layer stages need to know about the plate, as plain data that crosses to the workers: the
 * meshes to slice (each object's parts, and its other volumes), which volume does what, and the
 * deduplicated configs with, per object, the config index of each layer range and modifier.
 *
 * Objects that overlap and have the same settings (and no volumes or layer ranges of their own) are
 * printed as one object, their union; objects that overlap with different settings are checked layer by
 * layer, and refused where they really share volume (`overlapPairs`).
 */
import { StrataError } from '../errors.js';
import { mergeObjects } from '../mesh/place.js';
import { positionBounds } from '../mesh/prepare.js';
import type { Mesh, VolumeKind } from '../mesh/types.js';
import { ConfigTable, type ScopedSettings } from '../settings/scoped.js';
import type { ObjectSetup, PrintSetup } from '../regions/objects.js';
import type { Config } from '../settings/resolve.js';
import type { SliceOptions } from '../settings/schema.js';
import { vaseWarning } from '../settings/vase.js';
import type { HeightRange } from '../slice/z-plan.js';

/** A volume of a placed object other than its parts. */
export interface PlacedVolume {
  kind: VolumeKind;
  name: string;
  mesh: Mesh;
  /** A modifier's settings (Strata keys). */
  settings?: ScopedSettings;
}

export interface PlacedObject {
  name: string;
  /** Every printed part, in bed coordinates, mm. */
  mesh: Mesh;
  volumes?: readonly PlacedVolume[];
  /** The object's own settings (Strata keys). */
  settings?: ScopedSettings;
  /** Settings of the layers whose Z lies in [fromZ, toZ), mm from the bed; a later range wins. */
  layerRanges?: ReadonlyArray<{ fromZ: number; toZ: number; settings: ScopedSettings }>;
  /** Variable layer height: z0, h0, z1, h1, … mm (mesh/types.ts MeshObject). */
  layerHeightProfile?: readonly number[];
}

/** The meshes the setup's indices point into, and the setup. */
export interface PlateSetup {
  setup: PrintSetup;
  meshes: Mesh[];
  /** The objects as printed (merged ones as one), for labels, thumbnails and infill origins. */
  objects: PlacedObject[];
  /** Notes for the caller (objects merged). */
  warnings: string[];
  /** Z ranges whose layers have their own height (a layer range's layerHeight), for the plate's Z plan. */
  heightRanges: HeightRange[];
  /** The layer height profile the plate's Z plan follows (the first object's that has one), or null. */
  heightProfile: readonly number[] | null;
}

/** Most (layer ranges + 1) × (modifiers + 1) of one object, each a config to resolve. */
const MAX_REGIONS = 4096;

type Box = { min: number[]; max: number[] };

function boxesOverlap(a: Box, b: Box): boolean {
  for (let k = 0; k < 3; k++) if (!(a.min[k] < b.max[k] && b.min[k] < a.max[k])) return false;
  return true;
}

/** Whether an object has nothing of its own beyond its settings (so merging it with a twin changes nothing). */
function plain(o: PlacedObject): boolean {
  return !o.volumes?.length && !o.layerRanges?.length && !o.layerHeightProfile;
}

/**
 * Resolve every object's, range's and modifier's settings (throwing one clear error per misuse: a key that
 * does not exist, a value out of range, a print setting given to an object) and lay out the plate.
 */
export function plateSetup(objects: readonly PlacedObject[], base: SliceOptions, print: Config): PlateSetup {
  const table = new ConfigTable(base, print);
  const objectConfig = objects.map((o) => table.resolve([objectLayer(o)]));
  const { groupOf, overlapPairs } = overlapGroups(objects, objectConfig);
  const warnings: string[] = [];
  const vase = print.spiralVase ? vaseSettingsWarning(objects, base, print) : null;
  if (vase) warnings.push(vase);
  const { printed, printedIndex, firsts } = printedObjects(objects, groupOf, warnings);
  const meshes: Mesh[] = [];
  const add = (m: Mesh) => meshes.push(m) - 1;
  const setups = printed.map((o, k) => objectSetup(o, objectConfig[firsts[k]], table, add));
  const heightRanges = layerHeightRanges(printed, setups, table.configs, print, warnings);
  // one Z plan: the first object's layer height profile
  const profiled = printed.filter((o) => o.layerHeightProfile);
  if (profiled.length > 1)
    warnings.push(
      `objects ${profiled.map((o) => `"${o.name}"`).join(', ')} have layer height profiles: the plate has one Z plan, so the first one's ("${profiled[0].name}") holds for every object`,
    );
  const heightProfile = profiled[0]?.layerHeightProfile ?? null;
  const pairs = overlapPairs
    .map(([a, b]): [number, number] => [printedIndex[a], printedIndex[b]])
    .filter(([a, b]) => a !== b);
  return {
    setup: { configs: table.configs, objects: setups, overlapPairs: pairs },
    meshes,
    objects: printed,
    warnings,
    heightRanges,
    heightProfile,
  };
}

/** An object's own settings, as the config table reads them. */
function objectLayer(o: PlacedObject) {
  return { settings: o.settings, use: 'object' as const, where: `object "${o.name}"` };
}

/**
 * Overlapping twins (objects whose bounds overlap, with the same settings and nothing else of their own) print
 * as one object: `groupOf[i]`, the first object of i's group. Objects that overlap otherwise are `overlapPairs`.
 */
function overlapGroups(
  objects: readonly PlacedObject[],
  objectConfig: readonly number[],
): { groupOf: number[]; overlapPairs: Array<[number, number]> } {
  // one object overlaps nothing: its bounds (a pass over every vertex) are not needed
  const boxes: Box[] = objects.length > 1 ? objects.map((o) => positionBounds(o.mesh.positions)) : [];
  const parent = objects.map((_, i) => i);
  const find = (i: number): number => (parent[i] === i ? i : (parent[i] = find(parent[i])));
  const overlapPairs: Array<[number, number]> = [];
  for (let i = 0; i < objects.length; i++) {
    for (let j = i + 1; j < objects.length; j++) {
      if (!boxesOverlap(boxes[i], boxes[j])) continue;
      if (plain(objects[i]) && plain(objects[j]) && objectConfig[i] === objectConfig[j]) {
        const a = find(i),
          b = find(j);
        if (a !== b) parent[Math.max(a, b)] = Math.min(a, b);
      } else overlapPairs.push([i, j]);
    }
  }
  return { groupOf: objects.map((_, i) => find(i)), overlapPairs };
}

/** Settings given a value the spiral vase sets aside, wherever they were given: one warning, or null. */
function vaseSettingsWarning(objects: readonly PlacedObject[], base: SliceOptions, print: Config): string | null {
  return vaseWarning(
    [
      base,
      ...objects.flatMap((o) => [
        o.settings,
        ...(o.volumes ?? []).map((v) => v.settings),
        ...(o.layerRanges ?? []).map((r) => r.settings),
      ]),
    ],
    print,
  );
}

/**
 * The objects as printed, each group of twins as one (their union, with a warning); for each printed object
 * the first object of its group (`firsts`), and for each object the index of the printed object it is in.
 */
function printedObjects(
  objects: readonly PlacedObject[],
  groupOf: readonly number[],
  warnings: string[],
): { printed: PlacedObject[]; printedIndex: number[]; firsts: number[] } {
  const printed: PlacedObject[] = [];
  const printedIndex: number[] = [];
  const firsts: number[] = [];
  for (let i = 0; i < objects.length; i++) {
    if (groupOf[i] !== i) continue;
    const members = objects.map((_, j) => j).filter((j) => groupOf[j] === i);
    printedIndex[i] = printed.length;
    firsts.push(i);
    if (members.length === 1) printed.push(objects[i]);
    else {
      const names = members.map((j) => objects[j].name);
      warnings.push(
        `${names.join(', ')} overlap (their bounds do) and have the same settings: they print as one object (their union), "${names.join(' + ')}"`,
      );
      printed.push({
        name: names.join(' + '),
        mesh: mergeObjects(members.map((j) => ({ name: objects[j].name, mesh: objects[j].mesh }))),
        settings: objects[i].settings,
      });
    }
  }
  for (let i = 0; i < objects.length; i++) printedIndex[i] = printedIndex[groupOf[i]];
  return { printed, printedIndex, firsts };
}

/**
 * One printed object's setup: its meshes (added with `add`, which gives their index) and the config of each
 * of its regions, a layer range (0: none) by a modifier (0: none); `config` is the object's own.
 */
function objectSetup(o: PlacedObject, config: number, table: ConfigTable, add: (m: Mesh) => number): ObjectSetup {
  const volumes = o.volumes ?? [];
  const of = (kind: VolumeKind) => volumes.filter((v) => v.kind === kind);
  const modifiers = of('modifier');
  const ranges = (o.layerRanges ?? []).map((r) => ({ fromZ: r.fromZ, toZ: r.toZ }));
  if ((ranges.length + 1) * (modifiers.length + 1) > MAX_REGIONS) {
    throw new StrataError(
      'LIMIT_EXCEEDED',
      `object "${o.name}" has ${modifiers.length} modifiers and ${ranges.length} layer ranges: more than ${MAX_REGIONS} combinations of them to resolve`,
    );
  }
  const regions: number[][] = [];
  for (let r = 0; r <= ranges.length; r++) {
    const range = r === 0 ? null : o.layerRanges![r - 1];
    const rangeLayer = range
      ? [
          {
            settings: range.settings,
            use: 'layer range' as const,
            where: `object "${o.name}" layers ${range.fromZ}–${range.toZ} mm`,
          },
        ]
      : [];
    const row: number[] = [];
    for (let m = 0; m <= modifiers.length; m++) {
      if (r === 0 && m === 0) {
        row.push(config);
        continue;
      }
      const mod =
        m === 0
          ? []
          : [
              {
                settings: modifiers[m - 1].settings,
                use: 'modifier' as const,
                where: `modifier "${modifiers[m - 1].name}" of "${o.name}"`,
              },
            ];
      row.push(table.resolve([objectLayer(o), ...rangeLayer, ...mod]));
    }
    regions.push(row);
  }
  return {
    name: o.name,
    parts: add(o.mesh),
    negatives: of('negative').map((v) => add(v.mesh)),
    modifiers: modifiers.map((v) => add(v.mesh)),
    blockers: of('support-blocker').map((v) => add(v.mesh)),
    enforcers: of('support-enforcer').map((v) => add(v.mesh)),
    config,
    ranges,
    regions,
  };
}

/**
 * The layer ranges that set a layer height. The plate has one Z plan, so a range's height holds for every
 * object's layers in its Z range: the ranges of all objects in object order (a later one wins where they
 * overlap), with a warning when more than one object gives them. A range repeating the print's layerHeight
 * sets nothing unless adaptive layer height is on (there it keeps its range even).
 */
function layerHeightRanges(
  printed: readonly PlacedObject[],
  setups: readonly ObjectSetup[],
  configs: readonly Config[],
  print: Config,
  warnings: string[],
): HeightRange[] {
  const out: HeightRange[] = [];
  const givers: string[] = [];
  printed.forEach((o, k) => {
    let gives = false;
    (o.layerRanges ?? []).forEach((r, j) => {
      if (r.settings.layerHeight === undefined) return;
      const layerHeight = configs[setups[k].regions[j + 1][0]].layerHeight;
      if (layerHeight === print.layerHeight && !print.adaptiveLayerHeight) return;
      out.push({ fromZ: r.fromZ, toZ: r.toZ, layerHeight });
      gives = true;
    });
    if (gives) givers.push(`"${o.name}"`);
  });
  if (givers.length > 1)
    warnings.push(
      `objects ${givers.join(', ')} set layer heights in layer ranges: the plate has one Z plan, so each range's height holds for every object in its Z range (a later object's range wins where they overlap)`,
    );
  return out;
}
