/**
 * Start and end G-code from other slicers: their placeholders translated to Strata's `{key}` ones.
 * PrusaSlicer and OrcaSlicer write `[key]`, `{key}`, `{key[0]}` or `{key[initial_extruder]}`; Cura
 * `{key}` or `{key, 0}`. A template whose placeholders are not all known here (conditionals, layer
 * counts, macros of the slicer's own language) cannot be kept: the caller keeps Strata's.
 */
import type { SettingKey } from '../schema.js';

/** Other slicers' placeholder names → the Strata setting (or derived value) that holds the same value. */
const PLACEHOLDERS: Readonly<Record<string, SettingKey | 'layerCount' | 'maxZ'>> = {
  // PrusaSlicer, SuperSlicer
  temperature: 'nozzleTemperature',
  first_layer_temperature: 'firstLayerNozzleTemperature',
  bed_temperature: 'bedTemperature',
  first_layer_bed_temperature: 'firstLayerBedTemperature',
  layer_height: 'layerHeight',
  first_layer_height: 'firstLayerHeight',
  nozzle_diameter: 'nozzleDiameter',
  filament_diameter: 'filamentDiameter',
  max_print_height: 'buildVolumeHeight',
  total_layer_count: 'layerCount',
  max_layer_z: 'maxZ',
  // OrcaSlicer, Bambu Studio
  nozzle_temperature: 'nozzleTemperature',
  nozzle_temperature_initial_layer: 'firstLayerNozzleTemperature',
  bed_temperature_initial_layer: 'firstLayerBedTemperature',
  bed_temperature_initial_layer_single: 'firstLayerBedTemperature',
  hot_plate_temp: 'bedTemperature',
  hot_plate_temp_initial_layer: 'firstLayerBedTemperature',
  initial_layer_print_height: 'firstLayerHeight',
  printable_height: 'buildVolumeHeight',
  // Cura
  material_print_temperature: 'nozzleTemperature',
  material_print_temperature_layer_0: 'firstLayerNozzleTemperature',
  material_initial_print_temperature: 'firstLayerNozzleTemperature',
  print_temperature: 'nozzleTemperature',
  material_bed_temperature: 'bedTemperature',
  material_bed_temperature_layer_0: 'firstLayerBedTemperature',
  print_bed_temperature: 'bedTemperature',
  machine_width: 'buildPlateWidth',
  machine_depth: 'buildPlateLength',
  machine_height: 'buildVolumeHeight',
  machine_nozzle_size: 'nozzleDiameter',
  material_diameter: 'filamentDiameter',
  layer_height_0: 'firstLayerHeight',
};

/** `[name]`, `{name}`, `{name[i]}`, `{name, i}` (i a number or an extruder variable). */
const PLACEHOLDER = /\[([A-Za-z_][A-Za-z0-9_]*)\]|\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[\s*(?:\d+|[A-Za-z_]+)\s*\]|,\s*\d+)?\s*\}/g;

/** The template in Strata's form, or the placeholders that cannot be translated. */
export function translateTemplate(template: string): { text: string } | { unknown: string[] } {
  const unknown = new Set<string>();
  const out = template.replace(PLACEHOLDER, (whole, square: string | undefined, curly: string | undefined) => {
    const name = (square ?? curly)!;
    const key = PLACEHOLDERS[name];
    if (key === undefined) {
      // square brackets around a word that is not a placeholder of theirs are plain text (comments)
      if (square !== undefined && !/^[a-z0-9_]+$/.test(name)) return whole;
      unknown.add(name);
      return whole;
    }
    return `{${key}}`;
  });
  // anything brace-delimited left over is their macro language ({if …}, {endif}, expressions)
  for (const m of out.matchAll(/\{([^{}]*)\}/g)) {
    if (!/^[A-Za-z][A-Za-z0-9]*$/.test(m[1]!)) unknown.add(m[0]);
  }
  return unknown.size ? { unknown: [...unknown] } : { text: out };
}
