/**
 * Print time and filament estimate: a pass over the plan (through the same move expansion the G-code
 * writer uses), never over G-code text.
 *
 * Klipper flavour: Klipper's own look-ahead planner (klipper-planner.ts), with the printer's limits as
 * Klipper knows them (`klipperLimits`): one velocity and acceleration limit (Klipper has no per-axis limits
 * and ignores M201/M203; travels accelerate like prints, as the one `M204 S` written sets both),
 * square-corner velocity `cornerVelocity`, `minimumCruiseRatio`, max_z_velocity/max_z_accel
 * (`maxSpeedZ`/`maxAccelerationZ`), max_extrude_only_velocity/accel (`maxSpeedE`/`maxAccelerationE`, else
 * Klipper's defaults), and the extruder's instantaneous corner velocity (Klipper's default, 1 mm/s). Every
 * move is one queue as in the firmware: Z moves and layer changes are junctions like any other.
 *
 * Marlin and RepRapFirmware flavours: Marlin 2's look-ahead planner (marlin-planner.ts), with the limits
 * as the firmware has them when the print starts (`marlinLimits`): the settings' machine limits (unless
 * `machineLimits` is `ignore`), then the M201/M203/M204/M205 (RepRap: M566) with literal values in the start
 * G-code, then the ones Strata writes after it (`machineLimits` = `write`; else the `M204 P T` of an
 * `acceleration` set away from its default). Junctions by classic jerk when any of `jerkX`–`jerkE` (or the
 * start G-code's M205 X/Y/Z/E) is given, else by junction deviation: `junctionDeviation` (M205 J), else the one
 * that takes a 90° corner at `cornerVelocity` at the print acceleration, cornerVelocity² (√2 − 1) / a.
 * Retractions, primes, Z moves and layer changes are blocks like any other, as the firmware sees them.
 * Arcs are timed as the firmware runs them: chords of ARC_SEGMENT_MM (Marlin's MM_PER_ARC_SEGMENT and
 * Klipper's arc resolution both default to 1 mm).
 * Heating, homing and the start/end G-code are not estimated.
 *
 * Wipes (moves.ts) are travels in the chain (Marlin model: their speed cut so that the retraction on the
 * way stays within `maxSpeedE`; Klipper: moves with negative E, limited as Klipper limits them); coasted
 * ends are travels at the extrusion's speed.
 *
 * Filament: Σ E of the extrusions (width × height × length over the filament cross-section × flow ×
 * flowRate) plus the extra prime after each retraction; weight from `filamentDensity` (g/cm³).
 */
import { filamentAreaMm2, walkPlanSteps, type MoveSettings, type MoveSink } from './moves.js';
import { extrudeOnlyRatio, KlipperPlanner, type KlipperLimits } from './klipper-planner.js';
import { MarlinPlanner, type MarlinLimits } from './marlin-planner.js';
import { SCHEMA, type Settings } from '../settings/schema.js';
import type { PlanEstimate, PrintPlan } from './types.js';
import { hypot } from '../geometry/types.js';

/** The settings the estimate reads. */
export type EstimateSettings = MoveSettings &
  Pick<
    Settings,
    | 'acceleration'
    | 'cornerVelocity'
    | 'gcodeFlavor'
    | 'minimumCruiseRatio'
    | 'nozzleDiameter'
    | 'filamentDensity'
    | 'machineLimits'
    | 'maxSpeedX'
    | 'maxSpeedY'
    | 'maxSpeedE'
    | 'maxAccelerationX'
    | 'maxAccelerationY'
    | 'maxAccelerationZ'
    | 'maxAccelerationE'
    | 'travelAcceleration'
    | 'retractAcceleration'
    | 'maxSpeedZ'
    | 'jerkX'
    | 'jerkY'
    | 'jerkZ'
    | 'jerkE'
    | 'junctionDeviation'
    | 'startGcode'
  >;

/** Chord length firmware splits arcs into, mm (Marlin MM_PER_ARC_SEGMENT, Klipper gcode_arcs resolution). */
export const ARC_SEGMENT_MM = 1;

/** Marlin's defaults for the jerk of Z and E (DEFAULT_ZJERK, DEFAULT_EJERK), mm/s, when only X/Y are given. */
export const MARLIN_DEFAULT_JERK_Z = 0.3;
export const MARLIN_DEFAULT_JERK_E = 5;

/** The machine-limit M-codes with literal values in a start G-code template (placeholders are skipped). */
export interface StartLimits {
  M201: Partial<Record<'X' | 'Y' | 'Z' | 'E', number>>;
  M203: Partial<Record<'X' | 'Y' | 'Z' | 'E', number>>;
  M204: Partial<Record<'S' | 'P' | 'R' | 'T', number>>;
  M205: Partial<Record<'X' | 'Y' | 'Z' | 'E' | 'J', number>>;
  M566: Partial<Record<'X' | 'Y' | 'Z' | 'E', number>>;
}

/** The M201/M203/M204/M205/M566 words of a start G-code, the last of each word winning. */
export function startGcodeLimits(gcode: string): StartLimits {
  const out: StartLimits = { M201: {}, M203: {}, M204: {}, M205: {}, M566: {} };
  for (const raw of gcode.split('\n')) {
    const line = raw.replace(/;.*$/, '').trim().toUpperCase();
    const m = /^M(201|203|204|205|566)(\s.*)?$/.exec(line);
    if (!m) continue;
    const into = out[`M${m[1]}` as keyof StartLimits] as Record<string, number>;
    for (const word of (m[2] ?? '').trim().split(/\s+/)) {
      const w = /^([A-Z])(-?\d*\.?\d+)$/.exec(word);
      if (w) into[w[1]] = Number(w[2]);
    }
  }
  return out;
}

/** The limits Marlin (and RepRapFirmware, timed with Marlin's planner) plans with, from the settings. */
export function marlinLimits(s: EstimateSettings): MarlinLimits {
  const use = s.machineLimits !== 'ignore';
  const or = (v: number | null, fallback: number) => (use && v !== null ? v : fallback);
  const feed = [
    or(s.maxSpeedX, Infinity),
    or(s.maxSpeedY, Infinity),
    or(s.maxSpeedZ, Infinity),
    or(s.maxSpeedE, Infinity),
  ];
  const maxAccel = [
    or(s.maxAccelerationX, Infinity),
    or(s.maxAccelerationY, Infinity),
    or(s.maxAccelerationZ, Infinity),
    or(s.maxAccelerationE, Infinity),
  ];
  let print = s.acceleration;
  let travel = or(s.travelAcceleration, print);
  let retract = or(s.retractAcceleration, or(s.maxAccelerationE, print));
  let jx = use ? (s.jerkX ?? s.jerkY) : null;
  let jy = use ? (s.jerkY ?? s.jerkX) : null;
  let jz = use ? s.jerkZ : null;
  let je = use ? s.jerkE : null;
  let jd = use ? s.junctionDeviation : null;
  // the start G-code's literal limits
  const g = startGcodeLimits(s.startGcode);
  const reprap = s.gcodeFlavor === 'reprap';
  const axes = ['X', 'Y', 'Z', 'E'] as const;
  axes.forEach((a, i) => {
    if (g.M201[a] !== undefined) maxAccel[i] = g.M201[a]!;
    if (g.M203[a] !== undefined) feed[i] = g.M203[a]! / (reprap ? 60 : 1);
  });
  if (g.M204.S !== undefined) print = travel = g.M204.S;
  if (g.M204.P !== undefined) print = g.M204.P;
  if (g.M204.T !== undefined) travel = g.M204.T;
  if (g.M204.R !== undefined) retract = g.M204.R;
  const jerkWords = reprap ? g.M566 : g.M205;
  const scale = reprap ? 1 / 60 : 1;
  if (jerkWords.X !== undefined) jx = jerkWords.X * scale;
  if (jerkWords.Y !== undefined) jy = jerkWords.Y * scale;
  if (jerkWords.Z !== undefined) jz = jerkWords.Z * scale;
  if (jerkWords.E !== undefined) je = jerkWords.E * scale;
  if (!reprap && g.M205.J !== undefined) jd = g.M205.J;
  // what Strata writes after the start G-code (gcode/flavor.ts)
  if (s.machineLimits === 'write') {
    const set = (v: number | null, i: number, into: number[]) => {
      if (v !== null) into[i] = v;
    };
    [s.maxAccelerationX, s.maxAccelerationY, s.maxAccelerationZ, s.maxAccelerationE].forEach((v, i) =>
      set(v, i, maxAccel),
    );
    [s.maxSpeedX, s.maxSpeedY, s.maxSpeedZ, s.maxSpeedE].forEach((v, i) => set(v, i, feed));
    print = s.acceleration;
    travel = s.travelAcceleration ?? s.acceleration;
    if (!reprap) retract = s.retractAcceleration ?? s.maxAccelerationE ?? s.acceleration;
    // M205 X Y carries cornerVelocity when no jerk is set, which a junction-deviation Marlin does not take:
    // the jerk and junction deviation written count only where they are set
    if (s.jerkX !== null || s.jerkY !== null) {
      jx = s.jerkX ?? s.jerkY;
      jy = s.jerkY ?? s.jerkX;
    }
    if (s.jerkZ !== null) jz = s.jerkZ;
    if (s.jerkE !== null) je = s.jerkE;
    if (!reprap && s.junctionDeviation !== null) jd = s.junctionDeviation;
  } else if (s.acceleration !== SCHEMA.acceleration.default) print = travel = s.acceleration;
  // any jerk given says the firmware has classic jerk: X/Y default to cornerVelocity, Z/E to Marlin's
  const jerk: MarlinLimits['jerk'] =
    jx !== null || jy !== null || jz !== null || je !== null
      ? [
          jx ?? jy ?? s.cornerVelocity,
          jy ?? jx ?? s.cornerVelocity,
          jz ?? MARLIN_DEFAULT_JERK_Z,
          je ?? MARLIN_DEFAULT_JERK_E,
        ]
      : null;
  return {
    maxFeedrate: [feed[0], feed[1], feed[2], feed[3]],
    maxAccel: [maxAccel[0], maxAccel[1], maxAccel[2], maxAccel[3]],
    printAccel: print,
    travelAccel: travel,
    retractAccel: retract,
    jerk,
    junctionDeviation: jd ?? (s.cornerVelocity * s.cornerVelocity * (Math.SQRT2 - 1)) / print,
  };
}

/** Klipper's [extruder] instantaneous_corner_velocity default, mm/s. */
export const KLIPPER_EXTRUDER_CORNER_VELOCITY = 1;

/**
 * The limits Klipper plans with, from the settings: `maxSpeed` (or the slower of `maxSpeedX`/`maxSpeedY`,
 * as written in SET_VELOCITY_LIMIT) as max_velocity, `acceleration` as max_accel; Z and extrude-only limits
 * from the machine limits, else Klipper's defaults (max_velocity and max_accel; for the extruder those
 * times 4 nozzle² / filament cross-section).
 */
export function klipperLimits(s: EstimateSettings): KlipperLimits {
  const use = s.machineLimits !== 'ignore';
  const or = (v: number | null, fallback: number) => (use && v !== null ? v : fallback);
  const axes = [s.maxSpeedX, s.maxSpeedY].filter((v): v is number => v !== null);
  const maxVelocity = use && axes.length ? Math.min(s.maxSpeed, ...axes) : s.maxSpeed;
  const ratio = extrudeOnlyRatio(s.nozzleDiameter, s.filamentDiameter);
  return {
    maxVelocity,
    maxAccel: s.acceleration,
    minCruiseRatio: s.minimumCruiseRatio,
    squareCornerVelocity: s.cornerVelocity,
    maxZVelocity: or(s.maxSpeedZ, maxVelocity),
    maxZAccel: or(s.maxAccelerationZ, s.acceleration),
    maxExtrudeOnlyVelocity: or(s.maxSpeedE, maxVelocity * ratio),
    maxExtrudeOnlyAccel: or(s.maxAccelerationE, s.acceleration * ratio),
    instantCornerVelocity: KLIPPER_EXTRUDER_CORNER_VELOCITY,
  };
}

/**
 * Time of one trapezoidal segment of `length` mm: enter at speed v0, cruise at most at vc, leave at v1
 * (mm/s). Assumes v0 and v1 are reachable from each other within `length` (the lookahead guarantees it).
 */
export function segmentSeconds(length: number, v0: number, vc: number, v1: number, accel: number): number {
  const twoA = 2 * accel;
  const entry2 = v0 * v0;
  const exit2 = v1 * v1;
  const cruise2 = vc * vc;
  const accelDistance = (cruise2 - entry2) / twoA;
  const decelDistance = (cruise2 - exit2) / twoA;
  if (accelDistance + decelDistance <= length)
    return (2 * vc - v0 - v1) / accel + (length - accelDistance - decelDistance) / vc;
  const peak = Math.sqrt(accel * length + (entry2 + exit2) / 2);
  return (2 * peak - v0 - v1) / accel;
}

/** Time to move `distance` from rest to rest at cruise speed `speed` with acceleration `accel`. */
export function pointToPointSeconds(distance: number, speed: number, accel: number): number {
  return distance > 0 ? segmentSeconds(distance, 0, speed, 0, accel) : 0;
}

/** What the timer needs of a look-ahead planner (Klipper's and Marlin's both). */
interface TimedPlanner {
  /** The tag (layer) the next moves are timed into. */
  tag: number;
  /** Seconds by tag. */
  readonly seconds: number[];
  /** A move, relative mm, at a feed rate in mm/s. */
  move(dx: number, dy: number, dz: number, de: number, speed: number): void;
  /** Plan out every move queued (the head comes to rest). */
  flush(): void;
}

/**
 * The motion timer: the plan's moves, in mm, into the firmware's planner (klipper-planner.ts for Klipper,
 * marlin-planner.ts for Marlin and RepRapFirmware); each layer's moves timed into that layer. Arcs are split
 * into chords as the firmware splits them (`arcChords`: the count for an arc's length).
 */
class PlannerTimer implements MoveSink {
  /** Position: X, Y µm; Z mm (NaN until known). */
  private px = 0;
  private py = 0;
  private pz = NaN;
  private layers = 0;
  filament = 0;

  constructor(
    readonly planner: TimedPlanner,
    private readonly arcChords: (lengthMm: number) => number,
  ) {}

  layerSeconds(): number[] {
    this.planner.flush();
    const out = this.planner.seconds.slice(0, this.layers);
    while (out.length < this.layers) out.push(0);
    for (let i = 0; i < out.length; i++) out[i] = out[i] || 0;
    return out;
  }

  private xy(x: number, y: number, length: number, dz: number, filament: number, speed: number): void {
    // from an unknown position no time can be given: the head is taken to start there at rest
    if (!(length > 0)) this.planner.flush();
    else this.planner.move((x - this.px) / 1000, (y - this.py) / 1000, dz, filament, speed);
    this.px = x;
    this.py = y;
  }

  layerStart(): void {
    this.planner.tag = this.layers++;
  }
  layerEnd(): void {}
  zMove(z: number, distance: number, speed: number): void {
    if (distance > 0 && !Number.isNaN(this.pz)) this.planner.move(0, 0, z - this.pz, 0, speed);
    this.pz = z;
  }
  travel(x: number, y: number, length: number, speed: number): void {
    this.xy(x, y, length, 0, 0, speed);
  }
  extrudeStart(): void {}
  extrude(x: number, y: number, length: number, filament: number, speed: number): void {
    this.filament += filament;
    this.xy(x, y, length, 0, filament, speed);
  }
  extrudeZ(x: number, y: number, z: number, length: number, filament: number, speed: number): void {
    this.filament += filament;
    const dz = Number.isNaN(this.pz) ? 0 : z - this.pz;
    this.pz = z;
    this.xy(x, y, length, dz, filament, speed);
  }
  arc(
    x: number,
    y: number,
    cx: number,
    cy: number,
    clockwise: boolean,
    length: number,
    filament: number,
    speed: number,
  ): void {
    this.filament += filament;
    const r = hypot(this.px - cx, this.py - cy);
    const chords = this.arcChords(length);
    if (!(r > 0) || chords === 1) {
      this.xy(x, y, length, 0, filament, speed);
      return;
    }
    const a0 = Math.atan2(this.py - cy, this.px - cx);
    const step = ((clockwise ? -1 : 1) * (length * 1000)) / r / chords;
    const e = filament / chords;
    for (let k = 1; k < chords; k++) {
      const a = a0 + step * k;
      this.xy(cx + r * Math.cos(a), cy + r * Math.sin(a), 1, 0, e, speed);
    }
    this.xy(x, y, 1, 0, e, speed);
  }
  retract(filament: number, speed: number): void {
    this.filament -= filament;
    this.planner.move(0, 0, 0, -filament, speed);
  }
  prime(filament: number, speed: number): void {
    this.filament += filament;
    this.planner.move(0, 0, 0, filament, speed);
  }
  wipe(x: number, y: number, length: number, filament: number, speed: number): void {
    this.filament -= filament;
    // a move with E (the retraction on the way): the planner holds E to the extruder's limits
    if (!(length > 0)) this.planner.move(0, 0, 0, -filament, speed);
    else this.planner.move((x - this.px) / 1000, (y - this.py) / 1000, 0, -filament, speed);
    this.px = x;
    this.py = y;
  }
  objectStart(): void {}
  objectEnd(): void {}
}

/** Klipper's gcode_arcs: ⌊length / resolution⌋ segments. */
const klipperArcChords = (length: number) => Math.max(1, Math.floor(length / ARC_SEGMENT_MM));
/** Marlin's: ⌈length / MM_PER_ARC_SEGMENT⌉ chords. */
const marlinArcChords = (length: number) => Math.max(1, Math.ceil(length / ARC_SEGMENT_MM));

/** Estimate print time (per layer and total) and filament use of a plan. */
export function estimatePlan(plan: PrintPlan, s: EstimateSettings): PlanEstimate {
  const steps = estimatePlanSteps(plan, s);
  for (;;) {
    const r = steps.next();
    if (r.done) return r.value;
  }
}

/** `estimatePlan` as steps: yields after each layer. */
export function* estimatePlanSteps(plan: PrintPlan, s: EstimateSettings): Generator<void, PlanEstimate> {
  let layerSeconds: number[];
  let filament: number;
  const timer =
    s.gcodeFlavor === 'klipper'
      ? new PlannerTimer(new KlipperPlanner(klipperLimits(s)), klipperArcChords)
      : new PlannerTimer(new MarlinPlanner(marlinLimits(s)), marlinArcChords);
  yield* walkPlanSteps(plan, s, timer);
  layerSeconds = timer.layerSeconds();
  filament = timer.filament;
  let printTimeSeconds = 0;
  for (const t of layerSeconds) printTimeSeconds += t;
  const volumeCm3 = (filament * filamentAreaMm2(s.filamentDiameter)) / 1000;
  return {
    printTimeSeconds,
    filamentMm: filament,
    filamentGrams: volumeCm3 * s.filamentDensity,
    layerSeconds,
  };
}
