/**
 * Branded filaments: a maker's spool of a material we have a generic preset for, printed at the maker's
 * recommended temperatures. Each takes everything else (cooling, density, retraction speed, minimum layer
 * time) from its generic preset, and keeps that preset's first-layer offsets (e.g. +5 °C on the nozzle).
 *
 * Temperatures are mid-range values of the makers' published ranges for a 0.4 mm nozzle (spool labels and
 * data sheets; PrusaSlicer's and Bambu Studio's filament profiles where the maker publishes one). Names are
 * the makers'; the aliases include the names other programs use (the seeds' library's `PrusamentPLA`, …).
 */
import type { Settings } from '../schema.js';

/** What filaments.ts builds a preset from (its Draft type, restated so that this file stands alone). */
export interface FilamentDraft {
  id: string;
  name: string;
  aliases: readonly string[];
  material: string;
  abrasive?: boolean;
  settings: Partial<Settings>;
}

interface Brand {
  id: string;
  name: string;
  aliases: string[];
  /** The generic preset it is a spool of. */
  base: string;
  /** Nozzle and bed temperature, °C. */
  nozzle: number;
  bed: number;
  /** Settings that differ from the generic preset beyond temperatures. */
  extra?: Partial<Settings>;
}

const BRANDS: readonly Brand[] = [
  // ── Prusa ────────────────────────────────────────────────────────────────────
  { id: 'prusament-pla', name: 'Prusament PLA', aliases: ['prusa-pla'], base: 'pla', nozzle: 215, bed: 60 },
  { id: 'prusament-petg', name: 'Prusament PETG', aliases: ['prusa-petg'], base: 'petg', nozzle: 250, bed: 85 },
  // ── Bambu Lab ────────────────────────────────────────────────────────────────
  {
    id: 'bambu-pla-basic',
    name: 'Bambu Lab PLA Basic',
    aliases: ['bambu-lab-pla-basic', 'bambu-pla'],
    base: 'pla',
    nozzle: 220,
    bed: 55,
  },
  {
    id: 'bambu-pla-matte',
    name: 'Bambu Lab PLA Matte',
    aliases: ['bambu-lab-pla-matte'],
    base: 'pla-matte',
    nozzle: 220,
    bed: 55,
  },
  {
    id: 'bambu-petg-hf',
    name: 'Bambu Lab PETG HF',
    aliases: ['bambu-lab-petg-hf'],
    base: 'petg-hf',
    nozzle: 245,
    bed: 70,
  },
  { id: 'bambu-abs', name: 'Bambu Lab ABS', aliases: ['bambu-lab-abs'], base: 'abs', nozzle: 260, bed: 90 },
  // ── Polymaker ────────────────────────────────────────────────────────────────
  {
    id: 'polymaker-polylite-pla',
    name: 'Polymaker PolyLite PLA',
    aliases: ['polylite-pla'],
    base: 'pla',
    nozzle: 210,
    bed: 55,
  },
  {
    id: 'polymaker-polyterra-pla',
    name: 'Polymaker PolyTerra PLA',
    aliases: ['polyterra-pla', 'polyterra'],
    base: 'pla-matte',
    nozzle: 210,
    bed: 55,
  },
  {
    id: 'polymaker-polymax-pla',
    name: 'Polymaker PolyMax PLA',
    aliases: ['polymax-pla', 'polymax-tough-pla'],
    base: 'pla',
    nozzle: 215,
    bed: 55,
  },
  {
    id: 'polymaker-polylite-petg',
    name: 'Polymaker PolyLite PETG',
    aliases: ['polylite-petg'],
    base: 'petg',
    nozzle: 235,
    bed: 75,
  },
  {
    id: 'polymaker-polyflex-tpu95',
    name: 'Polymaker PolyFlex TPU95',
    aliases: ['polyflex-tpu95', 'polyflex-tpu-95'],
    base: 'tpu-95a',
    nozzle: 220,
    bed: 50,
  },
  // ── Hatchbox, eSUN, Overture, SUNLU ─────────────────────────────────────────
  { id: 'hatchbox-pla', name: 'Hatchbox PLA', aliases: [], base: 'pla', nozzle: 205, bed: 60 },
  { id: 'hatchbox-petg', name: 'Hatchbox PETG', aliases: [], base: 'petg', nozzle: 240, bed: 85 },
  { id: 'hatchbox-abs', name: 'Hatchbox ABS', aliases: [], base: 'abs', nozzle: 235, bed: 100 },
  {
    id: 'esun-pla-plus',
    name: 'eSUN PLA+',
    aliases: ['esun-pla+', 'esunplaplus'],
    base: 'pla-plus',
    nozzle: 215,
    bed: 60,
  },
  { id: 'esun-petg', name: 'eSUN PETG', aliases: [], base: 'petg', nozzle: 240, bed: 80 },
  { id: 'esun-abs-plus', name: 'eSUN ABS+', aliases: ['esun-abs+', 'esunabsplus'], base: 'abs', nozzle: 245, bed: 100 },
  { id: 'overture-pla', name: 'Overture PLA', aliases: [], base: 'pla', nozzle: 205, bed: 60 },
  { id: 'overture-petg', name: 'Overture PETG', aliases: [], base: 'petg', nozzle: 240, bed: 80 },
  { id: 'sunlu-pla', name: 'SUNLU PLA', aliases: [], base: 'pla', nozzle: 210, bed: 60 },
  { id: 'sunlu-petg', name: 'SUNLU PETG', aliases: [], base: 'petg', nozzle: 240, bed: 75 },
  // ── colorFabb ───────────────────────────────────────────────────────────────
  { id: 'colorfabb-pla-pha', name: 'colorFabb PLA/PHA', aliases: ['colorfabb-pla'], base: 'pla', nozzle: 210, bed: 60 },
  { id: 'colorfabb-ngen', name: 'colorFabb nGen', aliases: ['ngen'], base: 'cpe', nozzle: 230, bed: 80 },
  // ── flexible ────────────────────────────────────────────────────────────────
  {
    id: 'ninjaflex',
    name: 'NinjaTek NinjaFlex',
    aliases: ['ninjaflex-tpu', 'ninjatek-ninjaflex'],
    base: 'tpu-85a',
    nozzle: 230,
    bed: 40,
  },
  { id: 'sainsmart-tpu', name: 'SainSmart TPU', aliases: [], base: 'tpu-95a', nozzle: 220, bed: 50 },
  // ── fibre-filled ────────────────────────────────────────────────────────────
  {
    id: '3dxtech-carbonx-pa-cf',
    name: '3DXTech CarbonX PA-CF',
    aliases: ['3dxtech-carbonx', 'carbonx'],
    base: 'pa-cf',
    nozzle: 260,
    bed: 80,
  },
  // ── UltiMaker (2.85 mm spools: the printer's filament diameter must match) ───
  { id: 'ultimaker-pla', name: 'UltiMaker PLA', aliases: [], base: 'pla', nozzle: 205, bed: 60 },
  { id: 'ultimaker-tough-pla', name: 'UltiMaker Tough PLA', aliases: [], base: 'pla', nozzle: 215, bed: 60 },
];

/** The branded presets, built over the generic drafts (which must include every `base`). */
export function brandFilaments(generic: readonly FilamentDraft[]): FilamentDraft[] {
  return BRANDS.map((b) => {
    const base = generic.find((g) => g.id === b.base);
    if (!base) throw new Error(`brand filament ${b.id}: no generic preset ${b.base}`);
    const s = base.settings;
    const offset = (first: number | null | undefined, main: number | undefined) => (first ?? main ?? 0) - (main ?? 0);
    return {
      id: b.id,
      name: b.name,
      aliases: b.aliases,
      material: base.material,
      abrasive: base.abrasive,
      settings: {
        ...s,
        nozzleTemperature: b.nozzle,
        firstLayerNozzleTemperature: b.nozzle + offset(s.firstLayerNozzleTemperature, s.nozzleTemperature),
        bedTemperature: b.bed,
        firstLayerBedTemperature: b.bed + offset(s.firstLayerBedTemperature, s.bedTemperature),
        ...b.extra,
      },
    };
  });
}
