/**
 * What differs between the G-code dialects Strata writes. Everything else (G0/G1 moves, G92, M82/M83,
 * M140/M190) is common to Marlin, Klipper and RepRapFirmware.
 *
 * - Marlin: M104/M109 nozzle set/wait, M140/M190 bed, M106 S0–255 / M107 fan, M204 P(print) T(travel).
 * - Klipper: implements the same M-codes (M109/M190 wait for the target); its M204 takes S (with P and
 *   T it would use the smaller), so `M204 S<a>`.
 * - RepRapFirmware: M104/M109 are deprecated there (M109 even selects a tool as a side effect); the
 *   native way is tool temperatures `G10 P0 S<active> R<standby>`, selecting tool 0 (`T0`) and `M116 P0`
 *   to wait. Bed: M140/M190 are native. M106 S is read as a fraction when ≤ 1 (S1 is full speed, not
 *   1/255), so the fan is written as a 0–1 fraction; M204 P/T as in Marlin.
 */
import type { Settings } from '../settings/schema.js';
import { compact } from './format.js';

export type GcodeFlavor = Settings['gcodeFlavor'];

export interface FlavorCommands {
  /** Value of the `;FLAVOR:` header line. */
  name: string;
  /** Set the nozzle temperature without waiting. */
  setNozzle(celsius: number): string[];
  /** Set the nozzle temperature and wait for it. */
  waitNozzle(celsius: number): string[];
  setBed(celsius: number): string;
  waitBed(celsius: number): string;
  /** Part-cooling fan, `fraction` 0..1. */
  fan(fraction: number): string;
  /** Print and travel acceleration, mm/s². */
  acceleration(mmPerS2: number): string;
}

const temp = (celsius: number): string => compact(celsius, 1);
const fan255 = (fraction: number): string => {
  const value = Math.round(Math.min(1, Math.max(0, fraction)) * 255);
  return value === 0 ? 'M107' : `M106 S${value}`;
};
const accel = (mmPerS2: number): string => compact(mmPerS2, 0);

const MARLIN: FlavorCommands = {
  name: 'Marlin',
  setNozzle: (c) => [`M104 S${temp(c)}`],
  waitNozzle: (c) => [`M109 S${temp(c)}`],
  setBed: (c) => `M140 S${temp(c)}`,
  waitBed: (c) => `M190 S${temp(c)}`,
  fan: fan255,
  acceleration: (a) => `M204 P${accel(a)} T${accel(a)}`,
};

const KLIPPER: FlavorCommands = {
  ...MARLIN,
  name: 'Klipper',
  acceleration: (a) => `M204 S${accel(a)}`,
};

const REPRAP: FlavorCommands = {
  name: 'RepRap',
  setNozzle: (c) => [`G10 P0 S${temp(c)} R${temp(c)}`],
  waitNozzle: (c) => [`G10 P0 S${temp(c)} R${temp(c)}`, 'T0', 'M116 P0'],
  setBed: (c) => `M140 S${temp(c)}`,
  waitBed: (c) => `M190 S${temp(c)}`,
  fan: (fraction) => `M106 S${compact(Math.min(1, Math.max(0, fraction)), 3)}`,
  acceleration: (a) => `M204 P${accel(a)} T${accel(a)}`,
};

export const FLAVORS = { marlin: MARLIN, klipper: KLIPPER, reprap: REPRAP } as const satisfies Record<GcodeFlavor, FlavorCommands>;
