/**
 * Printer presets: machine facts (build volume, nozzle, filament, origin, G-code flavour, motion limits,
 * retraction for the printer's extruder type), speeds where the printer is known for them, and start/end
 * G-code templates. Values come from the makers' specifications and the vendors' own slicer profiles
 * (read for facts: bed sizes, limits, retraction, start commands).
 *
 * `maxSpeed` is the printer's XY feed-rate limit as sold (firmware limit or the maker's stated maximum);
 * `acceleration` is the print acceleration a profile for it uses, and is written as M204 by the writer.
 */
import type { Settings } from '../schema.js';
import {
  frontEdgePrime,
  klipperMacroEnd,
  klipperMacroStart,
  leftEdgePrime,
  marlinEnd,
  marlinStart,
  type PrimeLine,
} from './gcode-templates.js';
import { PRINTER_HOST_FEATURES } from './printer-host-features.js';

export type ExtruderKind = 'bowden' | 'direct';

export interface PrinterPreset {
  /** Lower-case, hyphenated, unique among printers. */
  readonly id: string;
  readonly name: string;
  /** Other names `findPrinter` accepts (lower-case); explicit, never derived. */
  readonly aliases: readonly string[];
  /** Bowden (long tube, ~3–6 mm retraction) or direct drive (~0.5–1 mm). */
  readonly extruder: ExtruderKind;
  readonly settings: Readonly<Partial<Settings>>;
}

type Draft = Omit<PrinterPreset, 'settings'> & { settings: Partial<Settings> };

/** Freezes a preset and its settings; a preset table is a constant. */
function freezePreset(d: Draft): PrinterPreset {
  return Object.freeze({
    id: d.id,
    name: d.name,
    aliases: Object.freeze([...d.aliases]),
    extruder: d.extruder,
    // Every printer here has a 0.4 mm nozzle, 1.75 mm filament and a heated bed as sold.
    settings: Object.freeze({
      nozzleDiameter: 0.4,
      filamentDiameter: 1.75,
      heatedBed: true,
      originAtCenter: false,
      ...PRINTER_HOST_FEATURES[d.id],
      ...d.settings,
    }),
  });
}

// ── shared pieces ──────────────────────────────────────────────────────────────
const CREALITY_PRIME = leftEdgePrime(20, 200);

/** Retraction of a Creality-style bowden extruder (~40 cm PTFE tube). */
const BOWDEN_5: Readonly<Partial<Settings>> = Object.freeze({ retractionDistance: 5, retractionSpeed: 45 });

const creality220Start = (afterHome: readonly string[] = []) => marlinStart({ afterHome, prime: CREALITY_PRIME });
const PRESENT_BED = marlinEnd({ present: 'bed-forward' });
const PARK_REAR = marlinEnd({ present: 'park-rear' });

/** Creality's K1-series Klipper macros (START_PRINT heats, homes and levels; END_PRINT parks and cools). */
const K1_START = (prime: PrimeLine) =>
  klipperMacroStart({
    macro: 'START_PRINT EXTRUDER_TEMP={firstLayerNozzleTemperature} BED_TEMP={firstLayerBedTemperature}',
    prime,
  });
const K1_END = klipperMacroEnd('END_PRINT');

/**
 * Voron's PRINT_START (the community macro the Voron slicer profiles call: home, quad-gantry level / Z tilt,
 * mesh). The stock macro does not heat, so the bed is heated first and the nozzle brought up after it.
 */
const VORON_START = klipperMacroStart({
  before: ['M190 S{firstLayerBedTemperature} ; wait for bed (the stock PRINT_START does not heat)', 'M104 S150 ; nozzle warm, not oozing'],
  macro: 'PRINT_START BED={firstLayerBedTemperature} EXTRUDER={firstLayerNozzleTemperature}',
  after: ['M109 S{firstLayerNozzleTemperature} ; wait for nozzle'],
  prime: frontEdgePrime(5, 20, 120),
});
const VORON_END = klipperMacroEnd('PRINT_END');

/** Bambu Lab printers take Marlin-style G-code; their long vendor start code is reduced to the essentials. */
const bambuStart = (prime: PrimeLine) => marlinStart({ afterHome: ['G29 ; automatic bed levelling'], prime });

/** Fast bed-slinger and CoreXY speeds used by the Bambu Lab and Creality K1 standard profiles. */
const FAST_500: Readonly<Partial<Settings>> = Object.freeze({
  perimeterSpeed: 200,
  innerWallSpeed: 300,
  skinSpeed: 200,
  infillSpeed: 270,
  firstLayerSpeed: 50,
  travelSpeed: 500,
  firstLayerTravelSpeed: 200,
});

/** Prusa MK3S-era speeds (PrusaSlicer 0.20 mm QUALITY). */
const PRUSA_MK3_SPEEDS: Readonly<Partial<Settings>> = Object.freeze({
  perimeterSpeed: 25,
  innerWallSpeed: 45,
  skinSpeed: 40,
  infillSpeed: 80,
  firstLayerSpeed: 20,
});

/** Prusa input-shaper-era speeds (MK4, XL). */
const PRUSA_IS_SPEEDS: Readonly<Partial<Settings>> = Object.freeze({
  perimeterSpeed: 120,
  innerWallSpeed: 170,
  skinSpeed: 150,
  infillSpeed: 200,
  firstLayerSpeed: 30,
  travelSpeed: 300,
  firstLayerTravelSpeed: 150,
});

const prusaPreamble = (model: string) => [`M862.3 P "${model}" ; printer model check`, 'M862.1 P{nozzleDiameter} ; nozzle diameter check'];

/** Every printer preset, in display order. */
export const PRINTERS: readonly PrinterPreset[] = Object.freeze(
  ([
  // ── Creality ───────────────────────────────────────────────────────────────
  {
    id: 'creality-ender-3',
    name: 'Creality Ender-3',
    aliases: ['ender-3', 'ender3', 'ender 3'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-ender-3-pro',
    name: 'Creality Ender-3 Pro',
    aliases: ['ender-3-pro', 'ender3pro', 'ender 3 pro'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-ender-3-v2',
    name: 'Creality Ender-3 V2',
    aliases: ['ender-3-v2', 'ender3v2', 'ender 3 v2'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-ender-3-s1',
    name: 'Creality Ender-3 S1',
    aliases: ['ender-3-s1', 'ender3s1', 'ender 3 s1'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 270,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      // "Sprite" direct-drive extruder.
      retractionDistance: 0.8, retractionSpeed: 30,
      startGcode: creality220Start(['M420 S1 ; use the saved CR Touch mesh']),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-ender-3-v3-se',
    name: 'Creality Ender-3 V3 SE',
    aliases: ['ender-3-v3-se', 'ender3v3se', 'ender 3 v3 se'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 2500, cornerVelocity: 8, maxSpeed: 250,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 180,
      firstLayerSpeed: 30, travelSpeed: 250, firstLayerTravelSpeed: 120,
      startGcode: creality220Start(['M420 S1 ; use the saved CR Touch mesh']),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-ender-5',
    name: 'Creality Ender-5',
    aliases: ['ender-5', 'ender5', 'ender 5'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 300,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      // The bed moves in Z: lower it to present the print.
      endGcode: marlinEnd({ present: 'lower-bed' }),
    },
  },
  {
    id: 'creality-cr-10',
    name: 'Creality CR-10',
    aliases: ['cr-10', 'cr10'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 400,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-k1',
    name: 'Creality K1',
    aliases: ['k1'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: K1_START(leftEdgePrime(20, 200, 1)),
      endGcode: K1_END,
    },
  },
  {
    id: 'creality-k1-max',
    name: 'Creality K1 Max',
    aliases: ['k1-max', 'k1max', 'k1 max'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 300,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: K1_START(leftEdgePrime(20, 280, 1)),
      endGcode: K1_END,
    },
  },

  // ── Prusa Research ─────────────────────────────────────────────────────────
  {
    id: 'prusa-i3-mk3s',
    name: 'Prusa i3 MK3S',
    aliases: ['mk3s', 'mk3s+', 'prusa-mk3s', 'original-prusa-i3-mk3s', 'prusa i3 mk3s+'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 250, buildPlateLength: 210, buildVolumeHeight: 210,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 1000, cornerVelocity: 8, maxSpeed: 200,
      retractionDistance: 0.8, retractionSpeed: 35, zHop: 0.4,
      ...PRUSA_MK3_SPEEDS, travelSpeed: 180,
      startGcode: marlinStart({
        preamble: prusaPreamble('MK3S'),
        home: 'G28 W ; home all axes without mesh bed levelling',
        afterHome: ['G80 ; mesh bed levelling'],
        prime: { points: [[0, -3], [100, -3]], z: 0.2, ePerMm: 0.12, feed: 1000 },
      }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'prusa-mk4',
    name: 'Prusa MK4',
    aliases: ['mk4', 'original-prusa-mk4', 'prusa-i3-mk4'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 250, buildPlateLength: 210, buildVolumeHeight: 220,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 2500, cornerVelocity: 8, maxSpeed: 300,
      retractionDistance: 0.7, retractionSpeed: 35, zHop: 0.2,
      ...PRUSA_IS_SPEEDS,
      startGcode: marlinStart({
        preamble: prusaPreamble('MK4'),
        probeNozzleTemperature: 170,
        afterHome: ['G29 ; mesh bed levelling (load cell)'],
        prime: { points: [[0, -4], [100, -4]], z: 0.2, ePerMm: 0.12, feed: 1000 },
      }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'prusa-mini',
    name: 'Prusa MINI',
    aliases: ['mini', 'mini+', 'prusa-mini+', 'original-prusa-mini'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 180, buildPlateLength: 180, buildVolumeHeight: 180,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 1250, cornerVelocity: 8, maxSpeed: 180,
      // Short bowden tube.
      retractionDistance: 3.2, retractionSpeed: 70,
      ...PRUSA_MK3_SPEEDS, travelSpeed: 150,
      startGcode: marlinStart({
        preamble: prusaPreamble('MINI'),
        probeNozzleTemperature: 170,
        afterHome: ['G29 ; mesh bed levelling'],
        prime: { points: [[170, -2], [40, -2]], z: 0.2, ePerMm: 0.14, feed: 900 },
      }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'prusa-xl',
    name: 'Prusa XL',
    aliases: ['original-prusa-xl', 'prusa-xl-single-tool'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 360, buildPlateLength: 360, buildVolumeHeight: 360,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 4000, cornerVelocity: 8, maxSpeed: 300,
      retractionDistance: 0.7, retractionSpeed: 35, zHop: 0.2,
      ...PRUSA_IS_SPEEDS,
      startGcode: marlinStart({
        preamble: prusaPreamble('XL'),
        probeNozzleTemperature: 170,
        afterHome: ['G29 ; mesh bed levelling (load cell)'],
        prime: frontEdgePrime(2, 10, 110, 0.2),
      }),
      endGcode: PARK_REAR,
    },
  },

  // ── Bambu Lab ──────────────────────────────────────────────────────────────
  {
    id: 'bambu-lab-a1',
    name: 'Bambu Lab A1',
    aliases: ['a1', 'bambu-a1'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 256, buildPlateLength: 256, buildVolumeHeight: 256,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 6000, cornerVelocity: 9, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 30, zHop: 0.4,
      ...FAST_500, infillSpeed: 250,
      startGcode: bambuStart(frontEdgePrime(1, 20, 120)),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'bambu-lab-a1-mini',
    name: 'Bambu Lab A1 mini',
    aliases: ['a1-mini', 'a1mini', 'a1 mini', 'bambu-a1-mini'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 180, buildPlateLength: 180, buildVolumeHeight: 180,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 6000, cornerVelocity: 9, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 30, zHop: 0.4,
      ...FAST_500, infillSpeed: 250,
      startGcode: bambuStart(frontEdgePrime(1, 10, 100)),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'bambu-lab-p1s',
    name: 'Bambu Lab P1S',
    aliases: ['p1s', 'bambu-p1s'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 256, buildPlateLength: 256, buildVolumeHeight: 256,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 9, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 30, zHop: 0.4,
      ...FAST_500,
      startGcode: bambuStart(frontEdgePrime(1, 20, 120)),
      endGcode: PARK_REAR,
    },
  },
  {
    id: 'bambu-lab-x1c',
    name: 'Bambu Lab X1C',
    aliases: ['x1c', 'x1-carbon', 'bambu-lab-x1-carbon', 'bambu-x1c'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 256, buildPlateLength: 256, buildVolumeHeight: 256,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 9, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 30, zHop: 0.4,
      ...FAST_500,
      startGcode: bambuStart(frontEdgePrime(1, 20, 120)),
      endGcode: PARK_REAR,
    },
  },

  // ── Voron ──────────────────────────────────────────────────────────────────
  {
    id: 'voron-2.4-350',
    name: 'Voron 2.4 (350)',
    aliases: ['voron-2.4', 'voron-v2.4', 'voron2.4', 'voron 2.4', 'v2.4'],
    extruder: 'direct',
    settings: {
      // 350 mm size class; the flying gantry leaves about 340 mm of Z.
      buildPlateWidth: 350, buildPlateLength: 350, buildVolumeHeight: 340,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 3000, cornerVelocity: 5, maxSpeed: 300,
      // Clockwork 2 / Stealthburner direct drive.
      retractionDistance: 0.5, retractionSpeed: 35,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 180,
      firstLayerSpeed: 30, travelSpeed: 300, firstLayerTravelSpeed: 150,
      startGcode: VORON_START,
      endGcode: VORON_END,
    },
  },
  {
    id: 'voron-trident-300',
    name: 'Voron Trident (300)',
    aliases: ['voron-trident', 'trident', 'voron trident'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 250,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 3000, cornerVelocity: 5, maxSpeed: 300,
      retractionDistance: 0.5, retractionSpeed: 35,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 180,
      firstLayerSpeed: 30, travelSpeed: 300, firstLayerTravelSpeed: 150,
      startGcode: VORON_START,
      endGcode: VORON_END,
    },
  },

  // ── Anycubic ───────────────────────────────────────────────────────────────
  {
    id: 'anycubic-kobra-2',
    name: 'Anycubic Kobra 2',
    aliases: ['kobra-2', 'kobra2', 'kobra 2'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 2500, cornerVelocity: 8, maxSpeed: 250,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 150,
      firstLayerSpeed: 30, travelSpeed: 250, firstLayerTravelSpeed: 120,
      startGcode: creality220Start(['M420 S1 ; use the saved LeviQ mesh']),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'anycubic-i3-mega',
    name: 'Anycubic i3 Mega',
    aliases: ['i3-mega', 'i3 mega', 'anycubic-mega'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 210, buildPlateLength: 210, buildVolumeHeight: 205,
      gcodeFlavor: 'marlin', acceleration: 1250, cornerVelocity: 10, maxSpeed: 500,
      retractionDistance: 6, retractionSpeed: 40,
      startGcode: marlinStart({ prime: frontEdgePrime(2, 5, 105) }),
      endGcode: PRESENT_BED,
    },
  },

  // ── Elegoo ─────────────────────────────────────────────────────────────────
  {
    id: 'elegoo-neptune-4',
    name: 'Elegoo Neptune 4',
    aliases: ['neptune-4', 'neptune4', 'neptune 4'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 225, buildPlateLength: 225, buildVolumeHeight: 265,
      gcodeFlavor: 'klipper', acceleration: 5000, cornerVelocity: 5, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 150, innerWallSpeed: 250, skinSpeed: 200, infillSpeed: 250,
      firstLayerSpeed: 40, travelSpeed: 400, firstLayerTravelSpeed: 150,
      startGcode: marlinStart({ afterHome: ['BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: CREALITY_PRIME }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'elegoo-neptune-3-pro',
    name: 'Elegoo Neptune 3 Pro',
    aliases: ['neptune-3-pro', 'neptune3pro', 'neptune 3 pro'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 225, buildPlateLength: 225, buildVolumeHeight: 280,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 180,
      retractionDistance: 0.8, retractionSpeed: 40,
      startGcode: creality220Start(['M420 S1 ; use the saved mesh']),
      endGcode: PRESENT_BED,
    },
  },

  // ── Artillery ──────────────────────────────────────────────────────────────
  {
    id: 'artillery-sidewinder-x2',
    name: 'Artillery Sidewinder X2',
    aliases: ['sidewinder-x2', 'sidewinder x2', 'sw-x2'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 400,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 10, maxSpeed: 150,
      // Titan-type direct drive.
      retractionDistance: 1, retractionSpeed: 35,
      startGcode: creality220Start(['M420 S1 ; use the saved BLTouch mesh']),
      endGcode: PRESENT_BED,
    },
  },

  // ── Sovol ──────────────────────────────────────────────────────────────────
  {
    id: 'sovol-sv06',
    name: 'Sovol SV06',
    aliases: ['sv06'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 180,
      retractionDistance: 0.8, retractionSpeed: 35,
      startGcode: marlinStart({ afterHome: ['G29 ; mesh bed levelling (inductive probe)'], prime: frontEdgePrime(1, 5, 105) }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'sovol-sv07',
    name: 'Sovol SV07',
    aliases: ['sv07'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'klipper', acceleration: 5000, cornerVelocity: 5, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 150, innerWallSpeed: 250, skinSpeed: 200, infillSpeed: 250,
      firstLayerSpeed: 40, travelSpeed: 400, firstLayerTravelSpeed: 150,
      startGcode: marlinStart({ afterHome: ['BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: CREALITY_PRIME }),
      endGcode: PRESENT_BED,
    },
  },

  // ── FLSUN (delta) ──────────────────────────────────────────────────────────
  {
    id: 'flsun-q5',
    name: 'FLSUN Q5',
    aliases: ['q5', 'flsun q5'],
    extruder: 'bowden',
    settings: {
      // Round bed, 200 mm across; (0,0) at its centre.
      buildPlateWidth: 200, buildPlateLength: 200, buildVolumeHeight: 200, originAtCenter: true,
      gcodeFlavor: 'marlin', acceleration: 1500, cornerVelocity: 5, maxSpeed: 200,
      retractionDistance: 3, retractionSpeed: 40, zHop: 0.3,
      startGcode: marlinStart({ prime: frontEdgePrime(-85, -40, 40) }),
      endGcode: marlinEnd({ present: 'home' }),
    },
  },

  // ── more printers (makers' specifications; start code from the same builders) ──
  {
    id: 'prusa-mk4s',
    name: 'Prusa MK4S',
    aliases: ['mk4s', 'original-prusa-mk4s'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 250, buildPlateLength: 210, buildVolumeHeight: 220,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 2500, cornerVelocity: 8, maxSpeed: 300,
      retractionDistance: 0.7, retractionSpeed: 35, zHop: 0.2,
      ...PRUSA_IS_SPEEDS,
      startGcode: marlinStart({
        preamble: prusaPreamble('MK4S'),
        probeNozzleTemperature: 170,
        afterHome: ['G29 ; mesh bed levelling (load cell)'],
        prime: { points: [[0, -4], [100, -4]], z: 0.2, ePerMm: 0.12, feed: 1000 },
      }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'prusa-core-one',
    name: 'Prusa CORE One',
    aliases: ['core-one', 'coreone', 'core one', 'prusa coreone'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 250, buildPlateLength: 220, buildVolumeHeight: 270,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 4000, cornerVelocity: 8, maxSpeed: 400,
      retractionDistance: 0.7, retractionSpeed: 35, zHop: 0.2,
      ...PRUSA_IS_SPEEDS,
      startGcode: marlinStart({
        preamble: prusaPreamble('COREONE'),
        probeNozzleTemperature: 170,
        afterHome: ['G29 ; mesh bed levelling (load cell)'],
        prime: { points: [[0, -4], [100, -4]], z: 0.2, ePerMm: 0.12, feed: 1000 },
      }),
      endGcode: PARK_REAR,
    },
  },
  {
    id: 'creality-ender-3-v3',
    name: 'Creality Ender-3 V3',
    aliases: ['ender-3-v3', 'ender3v3', 'ender 3 v3'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: K1_START(leftEdgePrime(20, 200, 1)),
      endGcode: K1_END,
    },
  },
  {
    id: 'creality-ender-3-v3-ke',
    name: 'Creality Ender-3 V3 KE',
    aliases: ['ender-3-v3-ke', 'ender3v3ke', 'ender 3 v3 ke'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 240,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 8000, cornerVelocity: 7, maxSpeed: 500,
      retractionDistance: 0.5, retractionSpeed: 30, zHop: 0.2,
      perimeterSpeed: 150, innerWallSpeed: 250, skinSpeed: 180, infillSpeed: 250,
      firstLayerSpeed: 40, travelSpeed: 500, firstLayerTravelSpeed: 150,
      startGcode: K1_START(leftEdgePrime(20, 200, 1)),
      endGcode: K1_END,
    },
  },
  {
    id: 'creality-k1c',
    name: 'Creality K1C',
    aliases: ['k1c'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: K1_START(leftEdgePrime(20, 200, 1)),
      endGcode: K1_END,
    },
  },
  {
    id: 'creality-ender-5-s1',
    name: 'Creality Ender-5 S1',
    aliases: ['ender-5-s1', 'ender5s1', 'ender 5 s1'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 280,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 250,
      // "Sprite" direct-drive extruder.
      retractionDistance: 0.8, retractionSpeed: 30,
      startGcode: creality220Start(['M420 S1 ; use the saved CR Touch mesh']),
      endGcode: marlinEnd({ present: 'lower-bed' }),
    },
  },
  {
    id: 'creality-ender-5-plus',
    name: 'Creality Ender-5 Plus',
    aliases: ['ender-5-plus', 'ender5plus', 'ender 5 plus'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 350, buildPlateLength: 350, buildVolumeHeight: 400,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: marlinStart({ afterHome: ['M420 S1 ; use the saved BLTouch mesh'], prime: leftEdgePrime(20, 300) }),
      endGcode: marlinEnd({ present: 'lower-bed' }),
    },
  },
  {
    id: 'creality-cr-10-se',
    name: 'Creality CR-10 SE',
    aliases: ['cr-10-se', 'cr10se', 'cr-10 se'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 265,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 8000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: K1_START(leftEdgePrime(20, 200, 1)),
      endGcode: K1_END,
    },
  },
  {
    id: 'creality-cr-6-se',
    name: 'Creality CR-6 SE',
    aliases: ['cr-6-se', 'cr6se', 'cr-6 se'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 235, buildPlateLength: 235, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: marlinStart({ afterHome: ['G29 ; strain-gauge bed levelling'], prime: CREALITY_PRIME }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'anycubic-kobra-2-max',
    name: 'Anycubic Kobra 2 Max',
    aliases: ['kobra-2-max', 'kobra2max', 'kobra 2 max'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 420, buildPlateLength: 420, buildVolumeHeight: 500,
      gcodeFlavor: 'marlin', acceleration: 2500, cornerVelocity: 8, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 150,
      firstLayerSpeed: 30, travelSpeed: 250, firstLayerTravelSpeed: 120,
      startGcode: marlinStart({ afterHome: ['M420 S1 ; use the saved LeviQ mesh'], prime: leftEdgePrime(20, 300) }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'elegoo-neptune-4-pro',
    name: 'Elegoo Neptune 4 Pro',
    aliases: ['neptune-4-pro', 'neptune4pro', 'neptune 4 pro'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 225, buildPlateLength: 225, buildVolumeHeight: 265,
      gcodeFlavor: 'klipper', acceleration: 5000, cornerVelocity: 5, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 150, innerWallSpeed: 250, skinSpeed: 200, infillSpeed: 250,
      firstLayerSpeed: 40, travelSpeed: 400, firstLayerTravelSpeed: 150,
      startGcode: marlinStart({ afterHome: ['BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: CREALITY_PRIME }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'elegoo-neptune-4-max',
    name: 'Elegoo Neptune 4 Max',
    aliases: ['neptune-4-max', 'neptune4max', 'neptune 4 max'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 420, buildPlateLength: 420, buildVolumeHeight: 480,
      gcodeFlavor: 'klipper', acceleration: 3000, cornerVelocity: 5, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 40,
      perimeterSpeed: 120, innerWallSpeed: 200, skinSpeed: 150, infillSpeed: 200,
      firstLayerSpeed: 40, travelSpeed: 300, firstLayerTravelSpeed: 150,
      startGcode: marlinStart({ afterHome: ['BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: leftEdgePrime(20, 300) }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'sovol-sv08',
    name: 'Sovol SV08',
    aliases: ['sv08'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 350, buildPlateLength: 350, buildVolumeHeight: 345,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 700,
      retractionDistance: 0.5, retractionSpeed: 40,
      ...FAST_500,
      startGcode: marlinStart({ afterHome: ['QUAD_GANTRY_LEVEL', 'BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: frontEdgePrime(5, 20, 150) }),
      endGcode: PARK_REAR,
    },
  },
  {
    id: 'qidi-q1-pro',
    name: 'QIDI Q1 Pro',
    aliases: ['q1-pro', 'qidi q1 pro'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 245, buildPlateLength: 245, buildVolumeHeight: 240,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: marlinStart({ afterHome: ['BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: frontEdgePrime(2, 20, 120) }),
      endGcode: PARK_REAR,
    },
  },
  {
    id: 'qidi-x-plus-3',
    name: 'QIDI X-Plus 3',
    aliases: ['x-plus-3', 'xplus3', 'qidi x-plus 3'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 280, buildPlateLength: 280, buildVolumeHeight: 270,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 5, maxSpeed: 600,
      retractionDistance: 0.8, retractionSpeed: 40,
      ...FAST_500,
      startGcode: marlinStart({ afterHome: ['BED_MESH_CALIBRATE ; Klipper bed mesh'], prime: frontEdgePrime(2, 20, 150) }),
      endGcode: PARK_REAR,
    },
  },
  {
    id: 'voron-0.2',
    name: 'Voron 0.2',
    aliases: ['voron-0', 'voron 0.2', 'v0.2', 'v0'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 120, buildPlateLength: 120, buildVolumeHeight: 120,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 5000, cornerVelocity: 5, maxSpeed: 300,
      retractionDistance: 0.5, retractionSpeed: 35,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 180,
      firstLayerSpeed: 30, travelSpeed: 300, firstLayerTravelSpeed: 150,
      startGcode: klipperMacroStart({
        before: ['M190 S{firstLayerBedTemperature} ; wait for bed (the stock PRINT_START does not heat)', 'M104 S150 ; nozzle warm, not oozing'],
        macro: 'PRINT_START BED={firstLayerBedTemperature} EXTRUDER={firstLayerNozzleTemperature}',
        after: ['M109 S{firstLayerNozzleTemperature} ; wait for nozzle'],
        prime: frontEdgePrime(3, 10, 70),
      }),
      endGcode: VORON_END,
    },
  },
  {
    id: 'ratrig-v-core-3-300',
    name: 'RatRig V-Core 3 (300)',
    aliases: ['v-core-3', 'vcore3', 'ratrig v-core 3', 'ratrig-vcore-3-300'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 300,
      gcodeFlavor: 'klipper', extruderMode: 'relative', acceleration: 3000, cornerVelocity: 5, maxSpeed: 300,
      retractionDistance: 0.8, retractionSpeed: 35,
      perimeterSpeed: 100, innerWallSpeed: 150, skinSpeed: 120, infillSpeed: 180,
      firstLayerSpeed: 30, travelSpeed: 300, firstLayerTravelSpeed: 150,
      // RatOS's START_PRINT heats, homes, levels and primes.
      startGcode: klipperMacroStart({ macro: 'START_PRINT EXTRUDER_TEMP={firstLayerNozzleTemperature} BED_TEMP={firstLayerBedTemperature}', prime: null }),
      endGcode: klipperMacroEnd('END_PRINT'),
    },
  },
  {
    id: 'bambu-lab-p1p',
    name: 'Bambu Lab P1P',
    aliases: ['p1p', 'bambu-p1p'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 256, buildPlateLength: 256, buildVolumeHeight: 256,
      gcodeFlavor: 'marlin', extruderMode: 'relative', acceleration: 10000, cornerVelocity: 9, maxSpeed: 500,
      retractionDistance: 0.8, retractionSpeed: 30, zHop: 0.4,
      ...FAST_500,
      startGcode: bambuStart(frontEdgePrime(1, 20, 120)),
      endGcode: PARK_REAR,
    },
  },
  {
    id: 'artillery-sidewinder-x1',
    name: 'Artillery Sidewinder X1',
    aliases: ['sidewinder-x1', 'sidewinder x1', 'sw-x1'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 400,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 10, maxSpeed: 150,
      // Titan-type direct drive.
      retractionDistance: 1, retractionSpeed: 35,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },

  // ── printers the seeds' library (Polyslice) names, from the makers' specifications ──
  {
    id: 'creality-cr-10-s5',
    name: 'Creality CR-10 S5',
    aliases: ['cr-10-s5', 'cr10s5', 'cr-10 s5'],
    extruder: 'bowden',
    settings: {
      buildPlateWidth: 500, buildPlateLength: 500, buildVolumeHeight: 500,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 8, maxSpeed: 500,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'creality-ender-6',
    name: 'Creality Ender-6',
    aliases: ['ender-6', 'ender6', 'ender 6'],
    extruder: 'bowden',
    settings: {
      // CoreXY; the bed moves in Z.
      buildPlateWidth: 250, buildPlateLength: 250, buildVolumeHeight: 400,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 150,
      ...BOWDEN_5,
      startGcode: creality220Start(),
      endGcode: marlinEnd({ present: 'lower-bed' }),
    },
  },
  {
    id: 'anycubic-kobra',
    name: 'Anycubic Kobra',
    aliases: ['kobra'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 180,
      retractionDistance: 0.8, retractionSpeed: 40,
      startGcode: creality220Start(['M420 S1 ; use the saved LeviQ mesh']),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'elegoo-neptune-3',
    name: 'Elegoo Neptune 3',
    aliases: ['neptune-3', 'neptune3', 'neptune 3'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 280,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 180,
      retractionDistance: 0.8, retractionSpeed: 40,
      startGcode: creality220Start(['M420 S1 ; use the saved mesh']),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'artillery-genius',
    name: 'Artillery Genius',
    aliases: ['genius'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 220, buildPlateLength: 220, buildVolumeHeight: 250,
      gcodeFlavor: 'marlin', acceleration: 500, cornerVelocity: 10, maxSpeed: 150,
      // Titan-type direct drive.
      retractionDistance: 1, retractionSpeed: 35,
      startGcode: creality220Start(),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'sovol-sv06-plus',
    name: 'Sovol SV06 Plus',
    aliases: ['sv06-plus', 'sv06plus', 'sv06 plus'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 300, buildPlateLength: 300, buildVolumeHeight: 340,
      gcodeFlavor: 'marlin', acceleration: 1250, cornerVelocity: 8, maxSpeed: 180,
      retractionDistance: 0.5, retractionSpeed: 30,
      startGcode: marlinStart({ afterHome: ['G29 ; mesh bed levelling (inductive probe)'], prime: frontEdgePrime(1, 5, 145) }),
      endGcode: PRESENT_BED,
    },
  },
  {
    id: 'kingroon-kp3s',
    name: 'Kingroon KP3S',
    aliases: ['kp3s'],
    extruder: 'direct',
    settings: {
      buildPlateWidth: 180, buildPlateLength: 180, buildVolumeHeight: 180,
      gcodeFlavor: 'marlin', acceleration: 1000, cornerVelocity: 8, maxSpeed: 200,
      // Titan-type direct drive.
      retractionDistance: 1, retractionSpeed: 35,
      startGcode: marlinStart({ prime: frontEdgePrime(2, 5, 90) }),
      endGcode: PRESENT_BED,
    },
  },
  ] satisfies Draft[]).map(freezePreset),
);
