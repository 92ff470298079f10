/**
 * Klipper's look-ahead planner (klippy/toolhead.py Move and LookAheadQueue, kinematics/cartesian.py and
 * kinematics/extruder.py check_move and calc_junction), for the time estimate of the Klipper flavour:
 * the same moves in, the same trapezoids out.
 *
 * - A move's speed is its feed rate capped at max_velocity; its acceleration max_accel. A move with Z is
 *   limited to max_z_velocity and max_z_accel scaled by move length / Z distance. A move without XYZ
 *   (extruder only) has no kinematic limit of its own, and like a retraction during a move (E going back)
 *   is limited to max_extrude_only_velocity and max_extrude_only_accel scaled by move length / E distance.
 * - Junctions (squared speeds): none into or out of an extruder-only move, nor through a reversal; else the
 *   least of the "approximated centripetal velocity" of the square-corner velocity (R = sin(θ/2) / (1 −
 *   sin(θ/2)) times junction_deviation = scv² (√2 − 1) / max_accel, times each move's acceleration), of
 *   the centripetal speed of an arc tangent to both moves within half of each (½ d tan(θ/2) a), of the
 *   extruder's instantaneous_corner_velocity over the change of E per mm, of both cruise speeds, and of
 *   what the previous move can reach.
 * - minimum_cruise_ratio (max_accel_to_decel before Klipper 0.12): a second, "smoothed" pass with a
 *   pseudo-acceleration max_accel × (1 − ratio) only lowers the cruise speed of moves that would
 *   accelerate and at once decelerate, so that a part of them is spent cruising.
 * - The queue is planned as if the head stopped after its last move; a move that starts at rest (after an
 *   extruder-only move, a reversal) ends what the ones before can depend on, so the queue is planned and
 *   emptied there. Klipper's lazy flushing in between gives the same speeds.
 */
import { KLIPPER_MIN_MOVE_MM } from '../geometry/tolerances.js';

/** Klipper's [printer] and [extruder] limits the planner uses (mm, s). */
export interface KlipperLimits {
  maxVelocity: number;
  maxAccel: number;
  /** minimum_cruise_ratio (0..1): max_accel_to_decel = maxAccel × (1 − ratio). */
  minCruiseRatio: number;
  squareCornerVelocity: number;
  maxZVelocity: number;
  maxZAccel: number;
  maxExtrudeOnlyVelocity: number;
  maxExtrudeOnlyAccel: number;
  /** [extruder] instantaneous_corner_velocity (Klipper's default 1 mm/s). */
  instantCornerVelocity: number;
}

/** Klipper's defaults for the extruder-only limits: max_velocity and max_accel × 4 nozzle² / filament area. */
export function extrudeOnlyRatio(nozzleDiameter: number, filamentDiameter: number): number {
  return (4 * nozzleDiameter * nozzleDiameter) / (Math.PI * (filamentDiameter / 2) ** 2);
}

/** Squared junction speed limit from the square-corner velocity rule and the centripetal rule (toolhead.py). */
export function klipperJunctionV2(
  cosTheta: number,
  moveD: number,
  accel: number,
  prevMoveD: number,
  prevAccel: number,
  squareCornerVelocity: number,
  maxAccel: number,
): number {
  // cosTheta: −(u_prev · u): 1 is a full reversal, −1 straight on
  if (cosTheta > 0.999999) return 0;
  const c = Math.max(cosTheta, -0.999999);
  const sinHalf = Math.sqrt(0.5 * (1 - c));
  const rJd = sinHalf / (1 - sinHalf);
  const tanHalf = sinHalf / Math.sqrt(0.5 * (1 + c));
  const jd = (squareCornerVelocity * squareCornerVelocity * (Math.SQRT2 - 1)) / maxAccel;
  return Math.min(
    rJd * jd * accel,
    rJd * jd * prevAccel,
    0.5 * moveD * tanHalf * accel,
    0.5 * prevMoveD * tanHalf * prevAccel,
  );
}

/**
 * Time of one planned move (toolhead.py set_junction): accelerate from start_v² to cruise_v², cruise,
 * decelerate to end_v², at `accel`, over `moveD` mm.
 */
export function klipperMoveSeconds(
  moveD: number,
  accel: number,
  startV2: number,
  cruiseV2: number,
  endV2: number,
): number {
  const halfInvAccel = 0.5 / accel;
  const accelD = (cruiseV2 - startV2) * halfInvAccel;
  const decelD = (cruiseV2 - endV2) * halfInvAccel;
  const cruiseD = moveD - accelD - decelD;
  const startV = Math.sqrt(startV2);
  const cruiseV = Math.sqrt(cruiseV2);
  const endV = Math.sqrt(endV2);
  return accelD / ((startV + cruiseV) * 0.5) + cruiseD / cruiseV + decelD / ((endV + cruiseV) * 0.5);
}

/**
 * The planner: `move()` the head by (dx, dy, dz, de) at a feed rate, `flush()` at the end; the time of
 * every move goes to the bucket (`tag`) current when it was added (the estimate's layers).
 */
export class KlipperPlanner {
  private moveD = new Float64Array(256);
  private accel = new Float64Array(256);
  /** Acceleration of the smoothed (minimum cruise ratio) pass. */
  private smoothAccel = new Float64Array(256);
  private maxCruiseV2 = new Float64Array(256);
  private maxStartV2 = new Float64Array(256);
  private maxSmoothedV2 = new Float64Array(256);
  private tags = new Int32Array(256);
  private count = 0;
  /** The previous move (for junctions): unit direction (XYZ, E per mm), length, limits; kinematic or not. */
  private prevKinematic = false;
  private pux = 0;
  private puy = 0;
  private puz = 0;
  private pue = 0;
  /** Bucket of the moves being added. */
  tag = 0;
  /** Seconds per bucket. */
  readonly seconds: number[] = [];
  private readonly jdAccel: number;
  private readonly pseudoAccel: number;

  constructor(readonly limits: KlipperLimits) {
    this.jdAccel = limits.maxAccel;
    this.pseudoAccel = limits.maxAccel * (1 - limits.minCruiseRatio);
  }

  private grow(): void {
    const size = this.moveD.length * 2;
    const f = (old: Float64Array) => {
      const a = new Float64Array(size);
      a.set(old);
      return a;
    };
    this.moveD = f(this.moveD);
    this.accel = f(this.accel);
    this.smoothAccel = f(this.smoothAccel);
    this.maxCruiseV2 = f(this.maxCruiseV2);
    this.maxStartV2 = f(this.maxStartV2);
    this.maxSmoothedV2 = f(this.maxSmoothedV2);
    const t = new Int32Array(size);
    t.set(this.tags);
    this.tags = t;
  }

  /** A move by (dx, dy, dz, de) mm at `speed` mm/s (the G-code feed rate). Nothing for a zero move. */
  move(dx: number, dy: number, dz: number, de: number, speed: number): void {
    const L = this.limits;
    let moveD = Math.sqrt(dx * dx + dy * dy + dz * dz);
    let velocity: number;
    let accel: number;
    const kinematic = moveD >= KLIPPER_MIN_MOVE_MM;
    if (!kinematic) {
      moveD = Math.abs(de);
      if (!(moveD > 0)) return;
      dx = dy = dz = 0;
      accel = 99999999.9;
      velocity = speed;
    } else {
      velocity = Math.min(speed, L.maxVelocity);
      accel = L.maxAccel;
    }
    const inv = 1 / moveD;
    const ux = dx * inv;
    const uy = dy * inv;
    const uz = dz * inv;
    const ue = de * inv;
    let cruiseV2 = velocity * velocity;
    let smoothAccel = this.pseudoAccel;
    const limit = (v: number, a: number) => {
      if (v * v < cruiseV2) cruiseV2 = v * v;
      if (a < accel) accel = a;
      if (accel < smoothAccel) smoothAccel = accel;
    };
    if (kinematic && dz !== 0) {
      const zRatio = moveD / Math.abs(dz);
      limit(L.maxZVelocity * zRatio, L.maxZAccel * zRatio);
    }
    if (de !== 0 && ((dx === 0 && dy === 0) || ue < 0)) {
      const invE = 1 / Math.abs(ue);
      limit(L.maxExtrudeOnlyVelocity * invE, L.maxExtrudeOnlyAccel * invE);
    }
    // junction with the previous move
    let startV2 = 0;
    let smoothedV2 = 0;
    const n = this.count;
    if (n > 0 && kinematic && this.prevKinematic) {
      const p = n - 1;
      const cosTheta = -(ux * this.pux + uy * this.puy + uz * this.puz);
      if (cosTheta <= 0.999999) {
        const diffE = ue - this.pue;
        const extruderV2 = diffE ? (L.instantCornerVelocity / Math.abs(diffE)) ** 2 : cruiseV2;
        const prevDelta = 2 * this.moveD[p]! * this.accel[p]!;
        const prevSmoothDelta = 2 * this.moveD[p]! * this.smoothAccel[p]!;
        startV2 = Math.min(
          klipperJunctionV2(
            cosTheta,
            moveD,
            accel,
            this.moveD[p]!,
            this.accel[p]!,
            L.squareCornerVelocity,
            this.jdAccel,
          ),
          extruderV2,
          cruiseV2,
          this.maxCruiseV2[p]!,
          this.maxStartV2[p]! + prevDelta,
        );
        smoothedV2 = Math.min(startV2, this.maxSmoothedV2[p]! + prevSmoothDelta);
      }
    }
    if (startV2 === 0 && smoothedV2 === 0) this.flush();
    const i = this.count;
    if (i === this.moveD.length) this.grow();
    this.moveD[i] = moveD;
    this.accel[i] = accel;
    this.smoothAccel[i] = smoothAccel;
    this.maxCruiseV2[i] = cruiseV2;
    this.maxStartV2[i] = startV2;
    this.maxSmoothedV2[i] = smoothedV2;
    this.tags[i] = this.tag;
    this.count = i + 1;
    this.prevKinematic = kinematic;
    this.pux = ux;
    this.puy = uy;
    this.puz = uz;
    this.pue = ue;
  }

  /** Plan the queued moves as ending at rest (toolhead.py LookAheadQueue.flush) and add up their times. */
  flush(): void {
    const n = this.count;
    if (n === 0) return;
    const { moveD, accel, smoothAccel, maxCruiseV2, maxStartV2, maxSmoothedV2, tags, seconds } = this;
    const add = (i: number, start: number, cruise: number, end: number) => {
      const t = klipperMoveSeconds(moveD[i]!, accel[i]!, start, cruise, end);
      const tag = tags[i]!;
      while (seconds.length <= tag) seconds.push(0);
      seconds[tag]! += t;
    };
    // delayed moves: index, start_v2, end_v2 (those whose peak is set by an earlier move)
    const delayed: number[] = [];
    let nextEndV2 = 0;
    let nextSmoothedV2 = 0;
    let peakCruiseV2 = 0;
    for (let i = n - 1; i >= 0; i--) {
      const deltaV2 = 2 * moveD[i]! * accel[i]!;
      const smoothDeltaV2 = 2 * moveD[i]! * smoothAccel[i]!;
      const reachableStartV2 = nextEndV2 + deltaV2;
      const startV2 = Math.min(maxStartV2[i]!, reachableStartV2);
      const reachableSmoothedV2 = nextSmoothedV2 + smoothDeltaV2;
      const smoothedV2 = Math.min(maxSmoothedV2[i]!, reachableSmoothedV2);
      if (smoothedV2 < reachableSmoothedV2) {
        // this move can accelerate
        if (smoothedV2 + smoothDeltaV2 > nextSmoothedV2 || delayed.length) {
          // it can decelerate, or it accelerates fully after a full deceleration
          peakCruiseV2 = Math.min(maxCruiseV2[i]!, (smoothedV2 + reachableSmoothedV2) * 0.5);
          if (delayed.length) {
            let mcV2 = peakCruiseV2;
            for (let k = delayed.length - 3; k >= 0; k -= 3) {
              const m = delayed[k]!;
              const msV2 = delayed[k + 1]!;
              const meV2 = delayed[k + 2]!;
              mcV2 = Math.min(mcV2, msV2);
              add(m, Math.min(msV2, mcV2), mcV2, Math.min(meV2, mcV2));
            }
            delayed.length = 0;
          }
        }
        const cruiseV2 = Math.min((startV2 + reachableStartV2) * 0.5, maxCruiseV2[i]!, peakCruiseV2);
        add(i, Math.min(startV2, cruiseV2), cruiseV2, Math.min(nextEndV2, cruiseV2));
      } else {
        delayed.push(i, startV2, nextEndV2);
      }
      nextEndV2 = startV2;
      nextSmoothedV2 = smoothedV2;
    }
    this.count = 0;
  }
}
