/**
 * Filament presets: temperatures, cooling, density and, where the material needs it, retraction and speed.
 * Retraction distance belongs to the printer (bowden vs direct drive) and is only set for flexible filament,
 * which must retract little whatever the extruder. Temperatures are mid-range values of the makers' data
 * sheets for a 0.4 mm brass (or, for the fibre-filled ones, hardened) nozzle.
 */
import type { Settings } from '../schema.js';

export interface FilamentPreset {
  /** Lower-case, hyphenated, unique among filaments. */
  readonly id: string;
  readonly name: string;
  /** Other names `findFilament` accepts (lower-case); explicit, never derived. */
  readonly aliases: readonly string[];
  /** Material family (PLA, PETG, PA…). */
  readonly material: string;
  /** Fibre-filled: wears a brass nozzle; use a hardened one. */
  readonly abrasive: boolean;
  readonly settings: Readonly<Partial<Settings>>;
}

type Draft = Omit<FilamentPreset, 'settings' | 'abrasive'> & { abrasive?: boolean; settings: Partial<Settings> };

function freezePreset(d: Draft): FilamentPreset {
  return Object.freeze({
    id: d.id,
    name: d.name,
    aliases: Object.freeze([...d.aliases]),
    material: d.material,
    abrasive: d.abrasive ?? false,
    settings: Object.freeze({ ...d.settings }),
  });
}

/** Every filament preset, in display order. */
export const FILAMENTS: readonly FilamentPreset[] = Object.freeze(
  ([
    {
      id: 'pla',
      name: 'Generic PLA',
      aliases: ['generic-pla'],
      material: 'PLA',
      settings: {
        nozzleTemperature: 210, firstLayerNozzleTemperature: 215, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.24,
      },
    },
    {
      id: 'pla-plus',
      name: 'PLA+',
      aliases: ['pla plus', 'plaplus', 'pla-pro'],
      material: 'PLA',
      settings: {
        nozzleTemperature: 215, firstLayerNozzleTemperature: 220, bedTemperature: 60, firstLayerBedTemperature: 65,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.23,
      },
    },
    {
      id: 'pla-high-speed',
      name: 'High-Speed PLA',
      aliases: ['hs-pla', 'pla-hs', 'hyper-pla', 'high speed pla'],
      material: 'PLA',
      settings: {
        // Made to melt fast: hotter, for the flow of 300+ mm/s printers.
        nozzleTemperature: 220, firstLayerNozzleTemperature: 225, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 8, filamentDensity: 1.24,
      },
    },
    {
      id: 'silk-pla',
      name: 'Silk PLA',
      aliases: ['silk', 'pla-silk', 'silk pla'],
      material: 'PLA',
      settings: {
        nozzleTemperature: 215, firstLayerNozzleTemperature: 220, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 80, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.24,
        // The sheen comes out best on a slow outer wall.
        perimeterSpeed: 30,
      },
    },
    {
      id: 'wood-pla',
      name: 'Wood PLA',
      aliases: ['wood', 'woodfill', 'pla-wood'],
      material: 'PLA',
      settings: {
        nozzleTemperature: 205, firstLayerNozzleTemperature: 210, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.15,
      },
    },
    {
      id: 'pla-cf',
      name: 'PLA-CF',
      aliases: ['pla cf', 'carbon-fiber-pla', 'carbon fibre pla'],
      material: 'PLA',
      abrasive: true,
      settings: {
        nozzleTemperature: 215, firstLayerNozzleTemperature: 220, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.29,
      },
    },
    {
      id: 'petg',
      name: 'Generic PETG',
      aliases: ['generic-petg', 'pet-g'],
      material: 'PETG',
      settings: {
        nozzleTemperature: 235, firstLayerNozzleTemperature: 240, bedTemperature: 80, firstLayerBedTemperature: 80,
        fanSpeed: 50, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.27,
        // Stringy and sticky: retract a little slower than PLA.
        retractionSpeed: 35,
      },
    },
    {
      id: 'petg-cf',
      name: 'PETG-CF',
      aliases: ['petg cf', 'carbon-fiber-petg'],
      material: 'PETG',
      abrasive: true,
      settings: {
        nozzleTemperature: 245, firstLayerNozzleTemperature: 250, bedTemperature: 80, firstLayerBedTemperature: 80,
        fanSpeed: 40, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.3,
        retractionSpeed: 35,
      },
    },
    {
      id: 'abs',
      name: 'Generic ABS',
      aliases: ['generic-abs'],
      material: 'ABS',
      settings: {
        // Warps: hot bed, little cooling, an enclosure helps.
        nozzleTemperature: 245, firstLayerNozzleTemperature: 250, bedTemperature: 100, firstLayerBedTemperature: 100,
        fanSpeed: 15, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.04,
      },
    },
    {
      id: 'asa',
      name: 'Generic ASA',
      aliases: ['generic-asa'],
      material: 'ASA',
      settings: {
        nozzleTemperature: 255, firstLayerNozzleTemperature: 260, bedTemperature: 100, firstLayerBedTemperature: 100,
        fanSpeed: 20, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.07,
      },
    },
    {
      id: 'hips',
      name: 'HIPS',
      aliases: ['high-impact-polystyrene'],
      material: 'HIPS',
      settings: {
        nozzleTemperature: 235, firstLayerNozzleTemperature: 240, bedTemperature: 100, firstLayerBedTemperature: 100,
        fanSpeed: 20, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.04,
      },
    },
    {
      id: 'pc',
      name: 'Polycarbonate (PC)',
      aliases: ['polycarbonate'],
      material: 'PC',
      settings: {
        nozzleTemperature: 270, firstLayerNozzleTemperature: 275, bedTemperature: 110, firstLayerBedTemperature: 110,
        fanSpeed: 10, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.2,
      },
    },
    {
      id: 'nylon',
      name: 'Nylon (PA)',
      aliases: ['pa', 'nylon-pa', 'pa6', 'pa12', 'polyamide'],
      material: 'PA',
      settings: {
        // Dry it first (hygroscopic); glue stick or a garolite sheet for adhesion.
        nozzleTemperature: 255, firstLayerNozzleTemperature: 260, bedTemperature: 80, firstLayerBedTemperature: 80,
        fanSpeed: 20, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.14,
      },
    },
    {
      id: 'pa-cf',
      name: 'PA-CF (carbon fibre nylon)',
      aliases: ['pa cf', 'nylon-cf', 'paht-cf', 'pa6-cf', 'pa12-cf'],
      material: 'PA',
      abrasive: true,
      settings: {
        nozzleTemperature: 275, firstLayerNozzleTemperature: 280, bedTemperature: 90, firstLayerBedTemperature: 90,
        fanSpeed: 0, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.21,
      },
    },
    {
      id: 'tpu-95a',
      name: 'TPU 95A',
      aliases: ['tpu', 'tpu95a', 'flex', 'flexible'],
      material: 'TPU',
      settings: {
        nozzleTemperature: 225, firstLayerNozzleTemperature: 230, bedTemperature: 50, firstLayerBedTemperature: 50,
        fanSpeed: 50, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.21,
        // Soft filament buckles under fast or long retraction and cannot be pushed fast.
        retractionDistance: 1, retractionSpeed: 20,
        perimeterSpeed: 20, innerWallSpeed: 25, skinSpeed: 25, infillSpeed: 25, firstLayerSpeed: 15,
        minPrintSpeed: 5,
      },
    },
    {
      id: 'pva',
      name: 'PVA',
      aliases: ['polyvinyl-alcohol'],
      material: 'PVA',
      settings: {
        // Water-soluble support material; keep dry.
        nozzleTemperature: 200, firstLayerNozzleTemperature: 205, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.23,
      },
    },
    {
      id: 'pp',
      name: 'Polypropylene (PP)',
      aliases: ['polypropylene'],
      material: 'PP',
      settings: {
        // Sticks only to PP (packing tape or a PP sheet) and warps: warm bed, little cooling.
        nozzleTemperature: 235, firstLayerNozzleTemperature: 240, bedTemperature: 85, firstLayerBedTemperature: 90,
        fanSpeed: 30, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 0.9,
      },
    },
  ] satisfies Draft[]).map(freezePreset),
);
