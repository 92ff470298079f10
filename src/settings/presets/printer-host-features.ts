/**
 * What each printer's screen and host read, and the motion limits its firmware ships with, kept apart
 * from the machine tables so that they read as one list: thumbnail sizes and formats, arc support, and
 * machine limits. Merged under each preset's own settings (printers.ts).
 *
 * Sources (facts only): the printers' vendor profiles in PrusaSlicer (thumbnail lists, machine limits),
 * OrcaSlicer (Creality's Klipper printers: 96×96 and 300×300 PNG), Mainsail/Fluidd (Klipper hosts read
 * PrusaSlicer-style PNG thumbnails; 32×32 and 400×300 are what their file lists use).
 *
 * Arc fitting is on only where the stock firmware runs G2/G3: Prusa's firmware, Bambu Lab's, and
 * Creality's K1-series Klipper configuration ([gcode_arcs]). Klipper printers whose stock configuration
 * lacks [gcode_arcs], and Marlin builds without ARC_SUPPORT, keep it off.
 */
import type { Settings } from '../schema.js';

/** Prusa firmware screens read QOI; Prusa Connect and hosts the PNG (PrusaSlicer 2.9 profiles). */
const PRUSA_IS_THUMBS = '16x16/QOI,313x173/QOI,480x240/QOI,380x285/PNG';
const PRUSA_MINI_THUMBS = '16x16/QOI,220x124/QOI,200x240/QOI,380x285/PNG';
/** The MK3S has no thumbnail screen: one PNG for hosts (OctoPrint, Prusa Connect). */
const PRUSA_MK3_THUMBS = '160x120/PNG';
/** Creality's Klipper printers (K1 series, Ender-3 V3 family, CR-10 SE): their screens and Creality Print. */
const CREALITY_KLIPPER_THUMBS = '96x96/PNG,300x300/PNG';
/** Klipper hosts' file lists (Mainsail, Fluidd). */
const KLIPPER_HOST_THUMBS = '32x32/PNG,400x300/PNG';
/** PrusaSlicer's Voron and RatRig profiles. */
const VORON_THUMBS = '64x64/PNG,400x300/PNG';
const RATRIG_THUMBS = '16x16/PNG,220x220/PNG';

/** Machine limits of Prusa's MK3S firmware, which PrusaSlicer writes into its G-code (emit_to_gcode). */
const PRUSA_MK3_LIMITS: Partial<Settings> = {
  machineLimits: 'write',
  maxSpeedX: 200,
  maxSpeedY: 200,
  maxSpeedZ: 12,
  maxSpeedE: 120,
  maxAccelerationX: 1000,
  maxAccelerationY: 1000,
  maxAccelerationZ: 200,
  maxAccelerationE: 5000,
  retractAcceleration: 1250,
};
const PRUSA_MINI_LIMITS: Partial<Settings> = {
  machineLimits: 'write',
  maxSpeedX: 180,
  maxSpeedY: 180,
  maxSpeedZ: 12,
  maxSpeedE: 80,
  maxAccelerationX: 2500,
  maxAccelerationY: 2500,
  maxAccelerationZ: 400,
  maxAccelerationE: 5000,
  travelAcceleration: 2500,
  retractAcceleration: 1250,
};
/** Creality's stock Marlin (PrusaSlicer's Creality profiles). */
const CREALITY_MARLIN_LIMITS: Partial<Settings> = {
  maxSpeedX: 500,
  maxSpeedY: 500,
  maxSpeedZ: 10,
  maxSpeedE: 60,
  maxAccelerationX: 500,
  maxAccelerationY: 500,
  maxAccelerationZ: 100,
  maxAccelerationE: 5000,
  retractAcceleration: 1000,
};
const VORON_LIMITS: Partial<Settings> = {
  maxSpeedZ: 12,
  maxSpeedE: 120,
  maxAccelerationX: 9000,
  maxAccelerationY: 9000,
  maxAccelerationZ: 500,
  maxAccelerationE: 10000,
};
const RATRIG_LIMITS: Partial<Settings> = {
  maxSpeedZ: 10,
  maxSpeedE: 60,
  maxAccelerationX: 9000,
  maxAccelerationY: 9000,
  maxAccelerationZ: 100,
  maxAccelerationE: 5000,
  travelAcceleration: 9000,
};

const CREALITY_KLIPPER: Partial<Settings> = { thumbnails: CREALITY_KLIPPER_THUMBS };
const K1: Partial<Settings> = { thumbnails: CREALITY_KLIPPER_THUMBS, arcFitting: true };
const BAMBU: Partial<Settings> = { arcFitting: true };
const KLIPPER_HOST: Partial<Settings> = { thumbnails: KLIPPER_HOST_THUMBS };

/** Per printer id: host features and limits (a preset's own settings override these). */
export const PRINTER_HOST_FEATURES: Readonly<Record<string, Readonly<Partial<Settings>>>> = {
  'creality-ender-3': CREALITY_MARLIN_LIMITS,
  'creality-ender-3-pro': CREALITY_MARLIN_LIMITS,
  'creality-ender-3-v2': CREALITY_MARLIN_LIMITS,
  'creality-ender-3-s1': CREALITY_MARLIN_LIMITS,
  'creality-ender-5': CREALITY_MARLIN_LIMITS,
  'creality-ender-5-s1': CREALITY_MARLIN_LIMITS,
  'creality-ender-5-plus': CREALITY_MARLIN_LIMITS,
  'creality-cr-10': CREALITY_MARLIN_LIMITS,
  'creality-cr-10-s5': CREALITY_MARLIN_LIMITS,
  'creality-k1': K1,
  'creality-k1-max': K1,
  'creality-k1c': K1,
  'creality-ender-3-v3': CREALITY_KLIPPER,
  'creality-ender-3-v3-ke': CREALITY_KLIPPER,
  'creality-cr-10-se': CREALITY_KLIPPER,
  'prusa-i3-mk3s': { thumbnails: PRUSA_MK3_THUMBS, arcFitting: true, ...PRUSA_MK3_LIMITS },
  'prusa-mk4': { thumbnails: PRUSA_IS_THUMBS, arcFitting: true },
  'prusa-mk4s': { thumbnails: PRUSA_IS_THUMBS, arcFitting: true },
  'prusa-core-one': { thumbnails: PRUSA_IS_THUMBS, arcFitting: true },
  'prusa-xl': { thumbnails: PRUSA_IS_THUMBS, arcFitting: true },
  'prusa-mini': { thumbnails: PRUSA_MINI_THUMBS, arcFitting: true, ...PRUSA_MINI_LIMITS },
  'bambu-lab-a1': BAMBU,
  'bambu-lab-a1-mini': BAMBU,
  'bambu-lab-p1s': BAMBU,
  'bambu-lab-p1p': BAMBU,
  'bambu-lab-x1c': BAMBU,
  'voron-2.4-350': { thumbnails: VORON_THUMBS, ...VORON_LIMITS },
  'voron-trident-300': { thumbnails: VORON_THUMBS, ...VORON_LIMITS },
  'voron-0.2': { thumbnails: VORON_THUMBS, ...VORON_LIMITS },
  'ratrig-v-core-3-300': { thumbnails: RATRIG_THUMBS, ...RATRIG_LIMITS },
  'elegoo-neptune-4': KLIPPER_HOST,
  'elegoo-neptune-4-pro': KLIPPER_HOST,
  'elegoo-neptune-4-max': KLIPPER_HOST,
  'sovol-sv07': KLIPPER_HOST,
  'sovol-sv08': KLIPPER_HOST,
  'qidi-q1-pro': KLIPPER_HOST,
  'qidi-x-plus-3': KLIPPER_HOST,
};
