/**
 * From the prepared model's objects to the plate the pipeline slices: each object's, volume's and layer
 * range's settings read into Strata's keys (another slicer's project keys mapped by profiles/ over
 * the project's print settings; those we do not use, and those that cannot vary there in Strata, named in
 * warnings), then resolved with their scopes into deduplicated configs. The caller's own settings (format
 * 'strata') that cannot vary where they are given are refused instead, one clear error each.
 */
import type { MeshObject, SettingsSource } from '../mesh/types.js';
import { plateSetup, type PlacedObject, type PlateSetup } from '../pipeline/print-setup.js';
import type { Config } from '../settings/resolve.js';
import type { SettingKey, SliceOptions } from '../settings/schema.js';
import type { ScopedSettings } from '../settings/scoped.js';
import { settingsFromSource } from '../profiles/object-settings.js';
import { SETTING_SCOPE, type ScopeUse } from '../settings/scope.js';

/** The plate of these objects over the print's options; `warnings` gets what was ignored or merged. */
export function plateOf(
  objects: readonly MeshObject[],
  options: SliceOptions,
  cfg: Config,
  warnings: string[],
  project?: SettingsSource,
): PlateSetup {
  const ignored = new Set<string>();
  const outOfScope = new Set<string>();
  const read = (src: SettingsSource | undefined, use: ScopeUse): ScopedSettings | undefined => {
    if (!src) return undefined;
    const mapped = settingsFromSource(src, project && project.format === src.format ? project : undefined);
    // the extruder of a single-extruder print says nothing (PrusaSlicer writes it into every layer range)
    for (const k of mapped.ignored)
      if (!(k === 'extruder' && /^[01]?$/.test(String(src.values[k] ?? '').trim()))) ignored.add(k);
    for (const r of mapped.rejected) warnings.push(`object settings: ${r.key} = ${r.value} not taken: ${r.reason}`);
    const settings: Record<string, unknown> = {};
    for (const [k, v] of Object.entries(mapped.settings)) {
      const scope = SETTING_SCOPE[k as SettingKey];
      // another slicer's project may vary what Strata keeps per print (or per object): left to the print
      // (the same value as the print's changes nothing: PrusaSlicer repeats the layer height in every range)
      const same = v === cfg.settings[k as SettingKey];
      if (
        src.format !== 'strata' &&
        (scope === 'print' || (scope === 'layer' && use !== 'layer range') || (scope === 'object' && use !== 'object'))
      ) {
        if (!same) outOfScope.add(k);
      } else if (!(src.format !== 'strata' && scope === 'layer' && same)) settings[k] = v;
    }
    return Object.keys(settings).length ? settings : undefined;
  };
  const placed = objects.map((o): PlacedObject => {
    const p: PlacedObject = { name: o.name, mesh: o.mesh };
    const settings = read(o.settings, 'object');
    if (settings) p.settings = settings;
    if (o.volumes?.length)
      p.volumes = o.volumes.map((v) => ({
        kind: v.kind,
        name: v.name,
        mesh: v.mesh,
        settings: read(v.settings, 'modifier'),
      }));
    if (o.layerHeightProfile) p.layerHeightProfile = o.layerHeightProfile;
    if (o.layerRanges?.length)
      p.layerRanges = o.layerRanges.map((r) => ({
        fromZ: r.fromZ,
        toZ: r.toZ,
        settings: read(r.settings, 'layer range') ?? {},
      }));
    return p;
  });
  if (ignored.size) warnings.push(`object settings not used by Strata, ignored: ${[...ignored].sort().join(', ')}`);
  if (outOfScope.size)
    warnings.push(
      `object settings that Strata keeps the same for the whole print (or object), ignored there: ${[...outOfScope].sort().join(', ')}`,
    );
  const plate = plateSetup(placed, options, cfg);
  warnings.push(...plate.warnings);
  return plate;
}
