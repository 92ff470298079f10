/**
 * Filament presets: temperatures, cooling, density and, where the material needs it, retraction and speed.
 * Retraction distance belongs to the printer (bowden vs direct drive) and is only set for flexible filament,
 * which must retract little whatever the extruder. Temperatures are mid-range values of the makers' data
 * sheets for a 0.4 mm brass (or, for the fibre-filled ones, hardened) nozzle.
 */
import type { Settings } from '../schema.js';
import { brandFilaments } from './brand-filaments.js';

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
    settings: Object.freeze({ filamentType: d.material, ...d.settings }),
  });
}

/** The generic materials, in display order. */
const GENERIC: readonly Draft[] = (
  [
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
    // ── more materials (mid-range values of the makers' data sheets) ──
    {
      id: 'pla-matte',
      name: 'Matte PLA',
      aliases: ['matte', 'pla matte', 'matte pla'],
      material: 'PLA',
      settings: {
        nozzleTemperature: 210, firstLayerNozzleTemperature: 215, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.32,
      },
    },
    {
      id: 'pla-glow',
      name: 'Glow-in-the-dark PLA',
      aliases: ['glow', 'pla glow', 'glow pla'],
      material: 'PLA',
      // the phosphorescent pigment wears brass nozzles
      abrasive: true,
      settings: {
        nozzleTemperature: 215, firstLayerNozzleTemperature: 220, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.3,
      },
    },
    {
      id: 'pctg',
      name: 'PCTG',
      aliases: ['generic-pctg'],
      material: 'PETG',
      settings: {
        nozzleTemperature: 250, firstLayerNozzleTemperature: 255, bedTemperature: 80, firstLayerBedTemperature: 80,
        fanSpeed: 30, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.23,
        retractionSpeed: 35,
      },
    },
    {
      id: 'petg-hf',
      name: 'High-Flow PETG',
      aliases: ['petg hf', 'hf-petg', 'high flow petg'],
      material: 'PETG',
      settings: {
        nozzleTemperature: 245, firstLayerNozzleTemperature: 250, bedTemperature: 75, firstLayerBedTemperature: 75,
        fanSpeed: 60, firstLayerFanSpeed: 0, minLayerTime: 12, filamentDensity: 1.27,
        retractionSpeed: 35,
      },
    },
    {
      id: 'cpe',
      name: 'CPE (co-polyester)',
      aliases: ['generic-cpe', 'co-polyester'],
      material: 'PETG',
      settings: {
        nozzleTemperature: 250, firstLayerNozzleTemperature: 250, bedTemperature: 75, firstLayerBedTemperature: 75,
        fanSpeed: 50, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.27,
        retractionSpeed: 35,
      },
    },
    {
      id: 'pet-cf',
      name: 'PET-CF',
      aliases: ['pet cf', 'carbon-fiber-pet'],
      material: 'PET',
      abrasive: true,
      settings: {
        nozzleTemperature: 270, firstLayerNozzleTemperature: 275, bedTemperature: 80, firstLayerBedTemperature: 80,
        fanSpeed: 20, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.29,
      },
    },
    {
      id: 'asa-cf',
      name: 'ASA-CF',
      aliases: ['asa cf', 'carbon-fiber-asa'],
      material: 'ASA',
      abrasive: true,
      settings: {
        nozzleTemperature: 260, firstLayerNozzleTemperature: 265, bedTemperature: 100, firstLayerBedTemperature: 100,
        fanSpeed: 15, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.12,
      },
    },
    {
      id: 'pc-abs',
      name: 'PC-ABS',
      aliases: ['pc abs', 'pc/abs'],
      material: 'PC',
      settings: {
        nozzleTemperature: 260, firstLayerNozzleTemperature: 265, bedTemperature: 100, firstLayerBedTemperature: 100,
        fanSpeed: 10, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.15,
      },
    },
    {
      id: 'pc-cf',
      name: 'PC-CF',
      aliases: ['pc cf', 'carbon-fiber-pc'],
      material: 'PC',
      abrasive: true,
      settings: {
        nozzleTemperature: 275, firstLayerNozzleTemperature: 280, bedTemperature: 110, firstLayerBedTemperature: 110,
        fanSpeed: 10, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.25,
      },
    },
    {
      id: 'pa-gf',
      name: 'PA-GF (glass fibre nylon)',
      aliases: ['pa gf', 'nylon-gf', 'pa6-gf', 'pa12-gf'],
      material: 'PA',
      abrasive: true,
      settings: {
        nozzleTemperature: 275, firstLayerNozzleTemperature: 280, bedTemperature: 90, firstLayerBedTemperature: 90,
        fanSpeed: 0, firstLayerFanSpeed: 0, minLayerTime: 15, filamentDensity: 1.34,
      },
    },
    {
      id: 'tpu-85a',
      name: 'TPU 85A',
      aliases: ['tpu85a', 'soft tpu'],
      material: 'TPU',
      settings: {
        nozzleTemperature: 225, firstLayerNozzleTemperature: 230, bedTemperature: 45, firstLayerBedTemperature: 45,
        fanSpeed: 60, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.19,
        // softer still than 95A: very short, slow retraction and slow printing
        retractionDistance: 0.5, retractionSpeed: 15,
        perimeterSpeed: 15, innerWallSpeed: 20, skinSpeed: 20, infillSpeed: 20, firstLayerSpeed: 12,
        minPrintSpeed: 5,
      },
    },
    {
      id: 'bvoh',
      name: 'BVOH',
      aliases: ['butenediol vinyl alcohol'],
      material: 'BVOH',
      settings: {
        // water-soluble support, dissolves faster than PVA; keep dry
        nozzleTemperature: 210, firstLayerNozzleTemperature: 215, bedTemperature: 60, firstLayerBedTemperature: 60,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.14,
      },
    },
    {
      id: 'pvb',
      name: 'PVB',
      aliases: ['polyvinyl butyral', 'polysmooth'],
      material: 'PVB',
      settings: {
        // smoothable with isopropyl alcohol
        nozzleTemperature: 210, firstLayerNozzleTemperature: 215, bedTemperature: 70, firstLayerBedTemperature: 70,
        fanSpeed: 100, firstLayerFanSpeed: 0, minLayerTime: 10, filamentDensity: 1.1,
      },
    },
    {
      id: 'peek',
      name: 'PEEK',
      aliases: ['polyether ether ketone'],
      material: 'PEEK',
      settings: {
        // needs an all-metal hot end above 400 °C, a 120 °C+ bed and a heated chamber
        nozzleTemperature: 400, firstLayerNozzleTemperature: 400, bedTemperature: 130, firstLayerBedTemperature: 130,
        fanSpeed: 0, firstLayerFanSpeed: 0, minLayerTime: 20, filamentDensity: 1.3,
      },
    },
  ] satisfies Draft[]
);

/** Every filament preset, in display order: the generic materials, then branded spools of them (brand-filaments.ts). */
export const FILAMENTS: readonly FilamentPreset[] = Object.freeze([...GENERIC, ...brandFilaments(GENERIC)].map(freezePreset));
