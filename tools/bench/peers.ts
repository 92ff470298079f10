/**
 * The peer slicers the benchmark compares against: finding them and building their command lines for the
 * common profile (0.2 mm layers, 2 walls of 0.4 mm, 0.8 mm top/bottom, 20 % grid, 0.4 mm nozzle, 1.75 mm filament,
 * 220 × 220 × 250 mm Ender-3-like machine, skirt, no support).
 */
import { spawnSync } from 'node:child_process';
import { accessSync, constants, existsSync } from 'node:fs';
import { delimiter, join } from 'node:path';

export type PeerId = 'cura' | 'prusa';

export interface PeerCommand {
  command: string;
  args: string[];
}

/** The common profile, shared by both peers' command lines. */
export const COMMON_PROFILE = Object.freeze({
  layerHeightMm: 0.2,
  wallCount: 2,
  lineWidthMm: 0.4,
  topBottomMm: 0.8,
  topBottomLayers: 4,
  infillPercent: 20,
  nozzleMm: 0.4,
  filamentMm: 1.75,
  bedMm: Object.freeze([220, 220, 250] as const),
  nozzleC: 210,
  bedC: 60,
});

/** Executable name on PATH for each peer. */
export const PEER_EXECUTABLES = Object.freeze({ cura: 'CuraEngine', prusa: 'prusa-slicer' } as const);

/** Where CuraEngine's fdmprinter.def.json may be (Debian's `cura` package: /usr/share/cura/resources/definitions). */
export const CURA_DEFINITION_CANDIDATES = Object.freeze([
  '/usr/share/cura/resources/definitions/fdmprinter.def.json',
  '/usr/local/share/cura/resources/definitions/fdmprinter.def.json',
  '/usr/share/curaengine/resources/definitions/fdmprinter.def.json',
  '/opt/cura/resources/definitions/fdmprinter.def.json',
]);

/** File types each peer reads (lower-case extensions). CuraEngine's command line reads STL only. */
const PEER_FORMATS: Readonly<Record<PeerId, readonly string[]>> = Object.freeze({
  cura: Object.freeze(['.stl']),
  prusa: Object.freeze(['.stl', '.3mf', '.obj', '.amf']),
});

export function peerReads(peer: PeerId, modelPath: string): boolean {
  const lower = modelPath.toLowerCase();
  return PEER_FORMATS[peer].some((ext) => lower.endsWith(ext));
}

/** Full path of an executable found on PATH, or null. */
export function findOnPath(name: string, env: NodeJS.ProcessEnv = process.env): string | null {
  for (const dir of (env.PATH ?? '').split(delimiter)) {
    if (dir === '') continue;
    const candidate = join(dir, name);
    try {
      accessSync(candidate, constants.X_OK);
      return candidate;
    } catch {
      // not here
    }
  }
  return null;
}

/** fdmprinter.def.json: $CURA_FDMPRINTER if set, else the first candidate that exists. */
export function findCuraDefinitions(env: NodeJS.ProcessEnv = process.env): string | null {
  const fromEnv = env.CURA_FDMPRINTER;
  if (fromEnv && existsSync(fromEnv)) return fromEnv;
  return CURA_DEFINITION_CANDIDATES.find((p) => existsSync(p)) ?? null;
}

/** The version line a peer prints (e.g. "Cura_SteamEngine version 4.13.0"), or null. */
export function peerVersion(peer: PeerId, executable: string): string | null {
  const args = peer === 'cura' ? ['help'] : ['--help'];
  try {
    const r = spawnSync(executable, args, { encoding: 'utf8', timeout: 20_000 });
    const text = `${r.stdout ?? ''}\n${r.stderr ?? ''}`;
    const re = peer === 'cura' ? /Cura_SteamEngine version \S+/ : /PrusaSlicer-\S+/;
    return re.exec(text)?.[0] ?? null;
  } catch {
    return null;
  }
}

/** CuraEngine's `-s key=value` settings for the common profile (global, then extruder 0). */
export function curaSettings(): { global: readonly string[]; extruder: readonly string[] } {
  const p = COMMON_PROFILE;
  const global = [
    `machine_width=${p.bedMm[0]}`,
    `machine_depth=${p.bedMm[1]}`,
    `machine_height=${p.bedMm[2]}`,
    'machine_heated_bed=true',
    'machine_center_is_zero=false',
    'machine_gcode_flavor=RepRap (Marlin/Sprinter)',
    `machine_nozzle_size=${p.nozzleMm}`,
    `material_diameter=${p.filamentMm}`,
    `material_print_temperature=${p.nozzleC}`,
    `material_bed_temperature=${p.bedC}`,
    `layer_height=${p.layerHeightMm}`,
    `layer_height_0=${p.layerHeightMm}`,
    `line_width=${p.lineWidthMm}`,
    `wall_line_count=${p.wallCount}`,
    `wall_thickness=${p.wallCount * p.lineWidthMm}`,
    `top_bottom_thickness=${p.topBottomMm}`,
    `top_thickness=${p.topBottomMm}`,
    `bottom_thickness=${p.topBottomMm}`,
    `infill_sparse_density=${p.infillPercent}`,
    // CuraEngine on its own does not evaluate the definitions' formulas: give the derived values too
    `infill_line_distance=${+((p.lineWidthMm * 100 * 2) / p.infillPercent).toFixed(4)}`,
    `top_layers=${Math.ceil(p.topBottomMm / p.layerHeightMm - 1e-9)}`,
    `bottom_layers=${Math.ceil(p.topBottomMm / p.layerHeightMm - 1e-9)}`,
    'infill_pattern=grid',
    'adhesion_type=skirt',
    'support_enable=false',
  ];
  // The extruder train has its own copies of these (fdmextruder defaults to 2.85 mm filament).
  const extruder = [`material_diameter=${p.filamentMm}`, `machine_nozzle_size=${p.nozzleMm}`];
  return { global, extruder };
}

/**
 * `CuraEngine slice -mN -j fdmprinter.def.json -s … -e0 -s … -l MODEL -o OUT`.
 * fdmprinter.def.json alone (no machine definition) with the machine given by settings keeps the
 * run independent of which printer definitions the installed Cura ships.
 */
export function curaCommand(
  engine: string,
  fdmprinter: string,
  model: string,
  out: string,
  threads: number | null,
): PeerCommand {
  const { global, extruder } = curaSettings();
  const args = ['slice'];
  if (threads !== null) args.push(`-m${threads}`);
  args.push('-j', fdmprinter);
  for (const s of global) args.push('-s', s);
  args.push('-e0');
  for (const s of extruder) args.push('-s', s);
  args.push('-l', model, '-o', out);
  return { command: engine, args };
}

/**
 * `prusa-slicer --export-gcode … -o OUT MODEL`. `datadir` should be an empty temporary folder so that no user
 * configuration is loaded. PrusaSlicer 2.5 has no thread-count option (it uses every core through TBB).
 */
export function prusaCommand(executable: string, datadir: string, model: string, out: string): PeerCommand {
  const p = COMMON_PROFILE;
  const [w, d, h] = p.bedMm;
  const args = [
    '--datadir',
    datadir,
    '--loglevel',
    '1',
    '--export-gcode',
    '--gcode-flavor',
    'marlin2',
    '--bed-shape',
    `0x0,${w}x0,${w}x${d},0x${d}`,
    '--max-print-height',
    String(h),
    '--center',
    `${w / 2},${d / 2}`,
    '--nozzle-diameter',
    String(p.nozzleMm),
    '--filament-diameter',
    String(p.filamentMm),
    '--temperature',
    String(p.nozzleC),
    '--bed-temperature',
    String(p.bedC),
    '--layer-height',
    String(p.layerHeightMm),
    '--first-layer-height',
    String(p.layerHeightMm),
    '--extrusion-width',
    String(p.lineWidthMm),
    '--first-layer-extrusion-width',
    String(p.lineWidthMm),
    '--perimeters',
    String(p.wallCount),
    '--top-solid-layers',
    String(p.topBottomLayers),
    '--bottom-solid-layers',
    String(p.topBottomLayers),
    '--fill-density',
    `${p.infillPercent}%`,
    '--fill-pattern',
    'grid',
    '--skirts',
    '1',
    '-o',
    out,
    model,
  ];
  return { command: executable, args };
}
