/**
 * From the prepared model's objects to the plate the pipeline slices: each object's, volume's and layer
 * range's settings read into Strata's keys (another slicer's project keys mapped by settings/import,
 * those we do not use named in one warning), then resolved with their scopes into deduplicated configs.
 */
import type { MeshObject, SettingsSource } from '../mesh/types.js';
import { plateSetup, type PlacedObject, type PlateSetup } from '../pipeline/print-setup.js';
import type { Config } from '../settings/resolve.js';
import type { SliceOptions } from '../settings/schema.js';
import type { ScopedSettings } from '../settings/scoped.js';
// TEMP until settings/import/object-settings.ts lands
function settingsFromSource(src: SettingsSource): { settings: Record<string, unknown>; ignored: string[] } {
  return { settings: { ...src.values }, ignored: [] };
}

/** The plate of these objects over the print's options; `warnings` gets what was ignored or merged. */
export function plateOf(objects: readonly MeshObject[], options: SliceOptions, cfg: Config, warnings: string[]): PlateSetup {
  const ignored = new Set<string>();
  const read = (src: SettingsSource | undefined): ScopedSettings | undefined => {
    if (!src) return undefined;
    const { settings, ignored: skipped } = settingsFromSource(src);
    for (const k of skipped) ignored.add(k);
    return Object.keys(settings).length ? settings : undefined;
  };
  const placed = objects.map((o): PlacedObject => {
    const p: PlacedObject = { name: o.name, mesh: o.mesh };
    const settings = read(o.settings);
    if (settings) p.settings = settings;
    if (o.volumes?.length) p.volumes = o.volumes.map((v) => ({ kind: v.kind, name: v.name, mesh: v.mesh, settings: read(v.settings) }));
    if (o.layerRanges?.length) p.layerRanges = o.layerRanges.map((r) => ({ fromZ: r.fromZ, toZ: r.toZ, settings: read(r.settings) ?? {} }));
    return p;
  });
  if (ignored.size) warnings.push(`object settings not used by Strata, ignored: ${[...ignored].sort().join(', ')}`);
  const plate = plateSetup(placed, options, cfg);
  warnings.push(...plate.warnings);
  return plate;
}
