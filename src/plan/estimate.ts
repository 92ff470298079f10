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
 * Marlin and RepRapFirmware flavours, a model of their planners:
 * - Consecutive XY moves form a chain; a retraction, a prime, a Z move or a layer end stops the head
 *   (speed 0) and ends the chain.
 * - Each segment has a nominal speed and a trapezoidal profile with the one `acceleration` of the settings.
 * - The speed at a junction between two segments is limited by both nominal speeds, by the corner angle
 *   through the junction-deviation rule calibrated so that a 90° corner allows exactly `cornerVelocity`
 *   (Klipper's square-corner velocity; a full reversal stops), and by the centripetal speed of an arc
 *   tangent to both segments within half of the shorter one (so many short segments around a curve are
 *   taken at the speed of that curve).
 * - A backward pass limits every junction so the head can still brake to the next one; a forward pass
 *   limits it to what the head can reach from the previous one. Then each segment's time is summed.
 * - Retractions, primes and Z moves: point-to-point trapezoids from rest at their own speeds.
 * - Arcs are timed as the firmware runs them: chords of ARC_SEGMENT_MM (Marlin's MM_PER_ARC_SEGMENT and
 *   Klipper's arc resolution both default to 1 mm).
 * - Machine limits (unless `machineLimits` is `ignore`): travels accelerate at `travelAcceleration`;
 *   a move's speed and acceleration are cut so that neither axis exceeds its own limit (`maxSpeedX/Y`,
 *   `maxAccelerationX/Y`), as Marlin's planner does; Z moves use `maxAccelerationZ`; retractions and
 *   primes are capped at `maxSpeedE` and accelerate at `retractAcceleration` (else `maxAccelerationE`).
 * Heating, homing and the start/end G-code are not estimated.
 *
 * Wipes (moves.ts) are travels in the chain (Marlin model: their speed cut so that the retraction on the
 * way stays within `maxSpeedE`; Klipper: moves with negative E, limited as Klipper limits them); coasted
 * ends are travels at the extrusion's speed.
 *
 * Filament: Σ E of the extrusions (width × height × length over the filament cross-section × flow ×
 * flowRate) plus the extra prime after each retraction; weight from `filamentDensity` (g/cm³).
 */
import { filamentArea, walkPlanSteps, type MoveSettings, type MoveSink } from './moves.js';
import { extrudeOnlyRatio, KlipperPlanner, type KlipperLimits } from './klipper-planner.js';
import type { Settings } from '../settings/schema.js';
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
  >;

/** Chord length firmware splits arcs into, mm (Marlin MM_PER_ARC_SEGMENT, Klipper gcode_arcs resolution). */
export const ARC_SEGMENT_MM = 1;

/** The limits the motion timer applies, resolved once from the settings (Infinity = none). */
export interface MotionLimits {
  printAccel: number;
  travelAccel: number;
  zAccel: number;
  retractAccel: number;
  maxSpeedX: number;
  maxSpeedY: number;
  maxSpeedE: number;
  maxAccelX: number;
  maxAccelY: number;
  cornerVelocity: number;
}

/** The limits the estimate uses for these settings. */
export function motionLimits(s: EstimateSettings): MotionLimits {
  const a = s.acceleration;
  const use = s.machineLimits !== 'ignore';
  const or = (v: number | null, fallback: number) => (use && v !== null ? v : fallback);
  return {
    printAccel: a,
    travelAccel: or(s.travelAcceleration, a),
    zAccel: or(s.maxAccelerationZ, a),
    retractAccel: or(s.retractAcceleration, or(s.maxAccelerationE, a)),
    maxSpeedX: or(s.maxSpeedX, Infinity),
    maxSpeedY: or(s.maxSpeedY, Infinity),
    maxSpeedE: or(s.maxSpeedE, Infinity),
    maxAccelX: or(s.maxAccelerationX, Infinity),
    maxAccelY: or(s.maxAccelerationY, Infinity),
    cornerVelocity: s.cornerVelocity,
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
 * The Klipper flavour's motion timer: the plan's moves, in mm, into Klipper's planner; each layer's moves
 * timed into that layer. Arcs are split as Klipper's gcode_arcs does (⌊length / resolution⌋ segments).
 */
class KlipperTimer implements MoveSink {
  readonly planner: KlipperPlanner;
  /** Position: X, Y µm; Z mm (NaN until known). */
  private px = 0;
  private py = 0;
  private pz = NaN;
  private layers = 0;
  filament = 0;

  constructor(limits: KlipperLimits) {
    this.planner = new KlipperPlanner(limits);
  }

  layerSeconds(): number[] {
    this.planner.flush();
    const out = this.planner.seconds.slice(0, this.layers);
    while (out.length < this.layers) out.push(0);
    for (let i = 0; i < out.length; i++) out[i] = out[i] || 0;
    return out;
  }

  private xy(x: number, y: number, length: number, dz: number, filament: number, speed: number): void {
    if (!(length > 0)) {
      // from an unknown position: no time can be given
      this.planner.flush();
    } else this.planner.move((x - this.px) / 1000, (y - this.py) / 1000, dz, filament, speed);
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
  arc(x: number, y: number, cx: number, cy: number, clockwise: boolean, length: number, filament: number, speed: number): void {
    this.filament += filament;
    const r = hypot(this.px - cx, this.py - cy);
    const segments = Math.max(1, Math.floor(length / ARC_SEGMENT_MM));
    if (!(r > 0) || segments === 1) {
      this.xy(x, y, length, 0, filament, speed);
      return;
    }
    const a0 = Math.atan2(this.py - cy, this.px - cx);
    const step = ((clockwise ? -1 : 1) * (length * 1000)) / r / segments;
    const e = filament / segments;
    for (let k = 1; k < segments; k++) {
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
    this.xy(x, y, length, 0, -filament, speed);
  }
  objectStart(): void {}
  objectEnd(): void {}
}

/** √2 − 1: the junction-deviation factor that makes a 90° corner's speed equal the corner velocity. */
const JUNCTION_FACTOR = Math.SQRT2 - 1;
/** cos of the angle above which two segments count as a full reversal (the head must stop). */
const REVERSAL_COS = 0.999999;

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
  if (accelDistance + decelDistance <= length) return (2 * vc - v0 - v1) / accel + (length - accelDistance - decelDistance) / vc;
  const peak = Math.sqrt(accel * length + (entry2 + exit2) / 2);
  return (2 * peak - v0 - v1) / accel;
}

/** Time to move `distance` from rest to rest at cruise speed `speed` with acceleration `accel`. */
export function pointToPointSeconds(distance: number, speed: number, accel: number): number {
  return distance > 0 ? segmentSeconds(distance, 0, speed, 0, accel) : 0;
}

/**
 * Squared speed allowed through the junction from direction (ux0,uy0) (segment length len0) into
 * direction (ux1,uy1) (length len1), from the corner angle alone (nominal speeds not applied).
 */
export function junctionSpeed2(
  ux0: number,
  uy0: number,
  len0: number,
  ux1: number,
  uy1: number,
  len1: number,
  accel: number,
  cornerVelocity: number,
): number {
  // theta: angle between the reversed incoming direction and the outgoing one (π = straight on).
  const cosTheta = -(ux0 * ux1 + uy0 * uy1);
  if (cosTheta > REVERSAL_COS) return 0;
  const sinHalf = Math.sqrt(0.5 * (1 - cosTheta));
  const cosHalf = Math.sqrt(Math.max(0, 0.5 * (1 + cosTheta)));
  if (cosHalf < 1e-9) return Infinity;
  const deviation = cornerVelocity * cornerVelocity * JUNCTION_FACTOR * (sinHalf / (1 - sinHalf));
  const arc = accel * 0.5 * Math.min(len0, len1) * (sinHalf / cosHalf);
  return deviation < arc ? deviation : arc;
}

/**
 * The motion timer: a MoveSink that collects chains of XY segments (growable typed arrays, owned by
 * one estimate call), runs the lookahead passes when the head stops and adds up the time per layer.
 * A class with fields rather than closures, so the per-segment doubles are updated in place.
 */
class MotionTimer implements MoveSink {
  private length = new Float64Array(1024);
  private cruise = new Float64Array(1024);
  private accel = new Float64Array(1024);
  private entryMax2 = new Float64Array(1024);
  private count = 0;
  /** Last XY position (µm) and unit direction of the last chained segment. */
  private px = 0;
  private py = 0;
  private ux = 0;
  private uy = 0;
  private layerTime = 0;
  readonly layerSeconds: number[] = [];
  filament = 0;

  constructor(private readonly limits: MotionLimits) {}

  /** Run the backward and forward passes over the chain (which starts and ends at rest), add its time, empty it. */
  private stop(): void {
    const n = this.count;
    if (n === 0) return;
    const { length, cruise, entryMax2, accel } = this;
    // Backward: every entry must allow braking to the next one.
    let next2 = 0;
    for (let i = n - 1; i >= 0; i--) {
      const reachable = next2 + 2 * accel[i]! * length[i]!;
      const e = entryMax2[i]! < reachable ? entryMax2[i]! : reachable;
      entryMax2[i] = e;
      next2 = e;
    }
    // Forward: every exit is limited by what the head reaches from the entry; sum the trapezoids.
    let seconds = 0;
    let entry2 = 0;
    let v0 = 0;
    for (let i = 0; i < n; i++) {
      const len = length[i]!;
      const a = accel[i]!;
      const nextMax2 = i + 1 < n ? entryMax2[i + 1]! : 0;
      const reachable = entry2 + 2 * a * len;
      const exit2 = nextMax2 < reachable ? nextMax2 : reachable;
      const v1 = Math.sqrt(exit2);
      seconds += segmentSeconds(len, v0, cruise[i]!, v1, a);
      entry2 = exit2;
      v0 = v1;
    }
    this.count = 0;
    this.layerTime += seconds;
  }

  private grow(): void {
    const size = this.length.length * 2;
    const grown = (old: Float64Array) => {
      const a = new Float64Array(size);
      a.set(old);
      return a;
    };
    this.length = grown(this.length);
    this.cruise = grown(this.cruise);
    this.accel = grown(this.accel);
    this.entryMax2 = grown(this.entryMax2);
  }

  private push(x: number, y: number, length: number, speed: number, baseAccel: number): void {
    if (!(length > 0)) {
      // From an unknown position: no time can be given; the chain restarts here.
      this.stop();
      this.px = x;
      this.py = y;
      return;
    }
    const nx = (x - this.px) / (1000 * length);
    const ny = (y - this.py) / (1000 * length);
    // Per-axis limits: neither axis may exceed its own speed or acceleration.
    const L = this.limits;
    const ax = nx < 0 ? -nx : nx;
    const ay = ny < 0 ? -ny : ny;
    let v = speed;
    let a = baseAccel;
    if (ax > 1e-9) {
      if (L.maxSpeedX / ax < v) v = L.maxSpeedX / ax;
      if (L.maxAccelX / ax < a) a = L.maxAccelX / ax;
    }
    if (ay > 1e-9) {
      if (L.maxSpeedY / ay < v) v = L.maxSpeedY / ay;
      if (L.maxAccelY / ay < a) a = L.maxAccelY / ay;
    }
    const i = this.count;
    let entry2 = 0;
    if (i > 0) {
      const junctionAccel = a < this.accel[i - 1]! ? a : this.accel[i - 1]!;
      entry2 = junctionSpeed2(this.ux, this.uy, this.length[i - 1]!, nx, ny, length, junctionAccel, L.cornerVelocity);
      const slower = v < this.cruise[i - 1]! ? v : this.cruise[i - 1]!;
      if (slower * slower < entry2) entry2 = slower * slower;
    }
    if (i === this.length.length) this.grow();
    this.length[i] = length;
    this.cruise[i] = v;
    this.accel[i] = a;
    this.entryMax2[i] = entry2;
    this.count = i + 1;
    this.px = x;
    this.py = y;
    this.ux = nx;
    this.uy = ny;
  }

  private pointToPoint(distance: number, speed: number, accel: number): void {
    this.stop();
    this.layerTime += pointToPointSeconds(distance, speed, accel);
  }

  layerStart(): void {
    this.layerTime = 0;
  }
  layerEnd(): void {
    this.stop();
    this.layerSeconds.push(this.layerTime);
  }
  zMove(_z: number, distance: number, speed: number): void {
    this.pointToPoint(distance, speed, this.limits.zAccel);
  }
  travel(x: number, y: number, length: number, speed: number): void {
    this.push(x, y, length, speed, this.limits.travelAccel);
  }
  extrudeStart(): void {}
  extrude(x: number, y: number, length: number, filament: number, speed: number): void {
    this.filament += filament;
    this.push(x, y, length, speed, this.limits.printAccel);
  }
  extrudeZ(x: number, y: number, _z: number, length: number, filament: number, speed: number): void {
    // the XY chain carries on: a rising nozzle is timed along the segment's whole length
    this.extrude(x, y, length, filament, speed);
  }
  arc(x: number, y: number, cx: number, cy: number, clockwise: boolean, length: number, filament: number, speed: number): void {
    this.filament += filament;
    const r = hypot(this.px - cx, this.py - cy);
    const pieces = Math.max(1, Math.ceil(length / ARC_SEGMENT_MM));
    if (!(r > 0) || pieces === 1) {
      this.push(x, y, length, speed, this.limits.printAccel);
      return;
    }
    const a0 = Math.atan2(this.py - cy, this.px - cx);
    const step = ((clockwise ? -1 : 1) * (length * 1000)) / r / pieces;
    const chord = (2 * r * Math.sin(Math.abs(step) / 2)) / 1000;
    for (let k = 1; k < pieces; k++) {
      const a = a0 + step * k;
      this.push(cx + r * Math.cos(a), cy + r * Math.sin(a), chord, speed, this.limits.printAccel);
    }
    this.push(x, y, hypot(x - this.px, y - this.py) / 1000, speed, this.limits.printAccel);
  }
  retract(filament: number, speed: number): void {
    this.filament -= filament;
    this.pointToPoint(filament, Math.min(speed, this.limits.maxSpeedE), this.limits.retractAccel);
  }
  prime(filament: number, speed: number): void {
    this.filament += filament;
    this.pointToPoint(filament, Math.min(speed, this.limits.maxSpeedE), this.limits.retractAccel);
  }
  wipe(x: number, y: number, length: number, filament: number, speed: number): void {
    this.filament -= filament;
    // a travel whose E (the retraction on the way) may not outrun the extruder's feed-rate limit
    const limit = filament > 0 && length > 0 ? (this.limits.maxSpeedE * length) / filament : Infinity;
    this.push(x, y, length, speed < limit ? speed : limit, this.limits.travelAccel);
  }
  objectStart(): void {}
  objectEnd(): void {}
}

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
  if (s.gcodeFlavor === 'klipper') {
    const timer = new KlipperTimer(klipperLimits(s));
    yield* walkPlanSteps(plan, s, timer);
    layerSeconds = timer.layerSeconds();
    filament = timer.filament;
  } else {
    const timer = new MotionTimer(motionLimits(s));
    yield* walkPlanSteps(plan, s, timer);
    layerSeconds = timer.layerSeconds;
    filament = timer.filament;
  }
  let printTimeSeconds = 0;
  for (const t of layerSeconds) printTimeSeconds += t;
  const volumeCm3 = (filament * filamentArea(s.filamentDiameter)) / 1000;
  return {
    printTimeSeconds,
    filamentMm: filament,
    filamentGrams: volumeCm3 * s.filamentDensity,
    layerSeconds,
  };
}
