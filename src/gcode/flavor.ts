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
 *
 * Pressure advance: Marlin's linear advance `M900 K`, Klipper's `SET_PRESSURE_ADVANCE ADVANCE=`,
 * RepRapFirmware's `M572 D0 S` (all in seconds of pressure per mm/s of flow).
 * Colour change and pause (the defaults of colorChangeGcode and pauseGcode): Marlin M600 (filament change,
 * ADVANCED_PAUSE_FEATURE) and M601 (pause print); RepRapFirmware M600 (runs sys/filament-change.g, else
 * pause.g) and M226 (a pause from within the file being printed: M25 is for other sources of commands);
 * Klipper has neither M600 nor M601 of its own, but its pause_resume module's PAUSE (which a printer's
 * macros usually extend to park the head), so both are PAUSE there: a printer whose Klipper config defines
 * an M600 macro sets colorChangeGcode to M600, as PrusaSlicer and OrcaSlicer write it.
 * Machine limits: Marlin `M201` (max acceleration per axis, mm/s²), `M203` (max feed rate, mm/s),
 * `M204 P R T` (print, retract, travel acceleration), `M205 X Y` (jerk); RepRapFirmware the same
 * M-codes but `M203` in mm/min, and jerk as `M566` in mm/min; Klipper has one velocity and acceleration
 * limit and a square-corner velocity: `SET_VELOCITY_LIMIT VELOCITY= ACCEL= SQUARE_CORNER_VELOCITY=`.
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
  /** Pressure (linear) advance, s. */
  pressureAdvance(seconds: number): string;
  /** The machine limits of the settings as start-of-print commands. */
  machineLimits(s: LimitSettings): string[];
  /** Default colour change (filament change) command. */
  colorChange: string;
  /** Default pause command. */
  pause: string;
}

/** The settings the machine-limit commands are written from. */
export type LimitSettings = Pick<
  Settings,
  | 'acceleration'
  | 'cornerVelocity'
  | 'jerkX'
  | 'jerkY'
  | 'jerkZ'
  | 'jerkE'
  | 'junctionDeviation'
  | 'maxSpeed'
  | 'maxSpeedX'
  | 'maxSpeedY'
  | 'maxSpeedZ'
  | 'maxSpeedE'
  | 'maxAccelerationX'
  | 'maxAccelerationY'
  | 'maxAccelerationZ'
  | 'maxAccelerationE'
  | 'travelAcceleration'
  | 'retractAcceleration'
>;

/** `M<code> X… Y… Z… E…` with the axes that have a value (scaled), or nothing when none has. */
function axisLimits(code: string, values: Record<'X' | 'Y' | 'Z' | 'E', number | null>, scale = 1): string[] {
  const words = (Object.keys(values) as Array<keyof typeof values>)
    .filter((axis) => values[axis] !== null)
    .map((axis) => `${axis}${compact(values[axis]! * scale, 2)}`);
  return words.length ? [`${code} ${words.join(' ')}`] : [];
}

/**
 * The jerk words (X, Y: jerkX/jerkY, else cornerVelocity; Z, E when given), scaled, and J (junction
 * deviation, Marlin's M205 only) when given.
 */
function jerkWords(s: LimitSettings, scale: number, digits: number, withJ: boolean): string {
  const jx = s.jerkX ?? s.jerkY ?? s.cornerVelocity,
    jy = s.jerkY ?? s.jerkX ?? s.cornerVelocity;
  let out = `X${compact(jx * scale, digits)} Y${compact(jy * scale, digits)}`;
  if (s.jerkZ !== null) out += ` Z${compact(s.jerkZ * scale, digits)}`;
  if (s.jerkE !== null) out += ` E${compact(s.jerkE * scale, digits)}`;
  if (withJ && s.junctionDeviation !== null) out += ` J${compact(s.junctionDeviation, 3)}`;
  return out;
}

function m20xLimits(
  s: LimitSettings,
  feedScale: number,
  jerk: (s: LimitSettings) => string,
  retractWord: boolean,
): string[] {
  const travel = s.travelAcceleration ?? s.acceleration;
  const retract = s.retractAcceleration ?? s.maxAccelerationE ?? s.acceleration;
  return [
    ...axisLimits('M201', {
      X: s.maxAccelerationX,
      Y: s.maxAccelerationY,
      Z: s.maxAccelerationZ,
      E: s.maxAccelerationE,
    }),
    ...axisLimits('M203', { X: s.maxSpeedX, Y: s.maxSpeedY, Z: s.maxSpeedZ, E: s.maxSpeedE }, feedScale),
    `M204 P${accel(s.acceleration)}${retractWord ? ` R${accel(retract)}` : ''} T${accel(travel)}`,
    jerk(s),
  ];
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
  pressureAdvance: (k) => `M900 K${compact(k, 4)}`,
  machineLimits: (s) => m20xLimits(s, 1, (l) => `M205 ${jerkWords(l, 1, 2, true)}`, true),
  colorChange: 'M600',
  pause: 'M601',
};

const KLIPPER: FlavorCommands = {
  ...MARLIN,
  name: 'Klipper',
  acceleration: (a) => `M204 S${accel(a)}`,
  pressureAdvance: (k) => `SET_PRESSURE_ADVANCE ADVANCE=${compact(k, 4)}`,
  machineLimits: (s) => {
    const axes = [s.maxSpeedX, s.maxSpeedY].filter((v): v is number => v !== null);
    const velocity = axes.length ? Math.min(...axes) : s.maxSpeed;
    return [
      `SET_VELOCITY_LIMIT VELOCITY=${compact(velocity, 2)} ACCEL=${accel(s.acceleration)} SQUARE_CORNER_VELOCITY=${compact(s.cornerVelocity, 2)}`,
    ];
  },
  colorChange: 'PAUSE',
  pause: 'PAUSE',
};

const REPRAP: FlavorCommands = {
  name: 'RepRap',
  setNozzle: (c) => [`G10 P0 S${temp(c)} R${temp(c)}`],
  waitNozzle: (c) => [`G10 P0 S${temp(c)} R${temp(c)}`, 'T0', 'M116 P0'],
  setBed: (c) => `M140 S${temp(c)}`,
  waitBed: (c) => `M190 S${temp(c)}`,
  fan: (fraction) => `M106 S${compact(Math.min(1, Math.max(0, fraction)), 3)}`,
  acceleration: (a) => `M204 P${accel(a)} T${accel(a)}`,
  pressureAdvance: (k) => `M572 D0 S${compact(k, 4)}`,
  machineLimits: (s) => m20xLimits(s, 60, (l) => `M566 ${jerkWords(l, 60, 0, false)}`, false),
  colorChange: 'M600',
  pause: 'M226',
};

export const FLAVORS = { marlin: MARLIN, klipper: KLIPPER, reprap: REPRAP } as const satisfies Record<
  GcodeFlavor,
  FlavorCommands
>;
