/**
 * Marlin 2's look-ahead planner (Marlin/src/module/planner.cpp: _populate_block, reverse_pass,
 * forward_pass, calculate_trapezoid_for_block), for the time estimate of the Marlin and RepRap flavours:
 * the same blocks in, the same trapezoids out, with the look-ahead over the whole print (the firmware's
 * 16-block buffer only matters when the host cannot keep it full).
 *
 * - A block's length is its XYZ distance (its E distance for an extruder-only move). Its nominal speed is
 *   the feed rate scaled down so that no axis, the extruder included, exceeds its max feed rate (M203).
 * - Its acceleration: an extruder-only move (retraction, prime) takes the retract acceleration (M204 R);
 *   any other the print acceleration (M204 P) when the extruder moves, else the travel acceleration
 *   (M204 T); then cut so that no axis, the extruder included, exceeds its max acceleration (M201):
 *   a ≤ max_accel[axis] × length / |axis distance|.
 * - Junction speed, junction deviation (Marlin 2's default): the unit vectors of the two blocks (XYZE and
 *   normalised when the extruder moves, else XYZ), cos θ = −u_prev · u; a reversal (cos θ > 0.999999) takes
 *   the minimum speed; else v² = a_j × junction_deviation_mm × sin(θ/2) / (1 − sin(θ/2)), a_j the block's
 *   acceleration cut by each axis's max acceleration along the unit vector of u − u_prev; and
 *   (JD_HANDLE_SMALL_SEGMENTS, on by default) for a block under 1 mm turning by less than 45°, at most
 *   v² = length × a_j / turn angle (the centripetal speed of the arc such blocks approximate; Marlin's acos
 *   is a polynomial within 0.033 rad, here it is exact). Then at most both blocks' nominal speeds.
 * - Junction speed, classic jerk (CLASSIC_JERK; a Prusa or older printer): the slower block's nominal speed,
 *   with both blocks' per-axis velocities scaled to it; the velocity change of each axis (X, Y, Z, E) at
 *   most that axis's jerk (M205 X Y Z E), by one factor on the junction speed. A block from rest enters at
 *   the speed at which no axis starts faster than its jerk.
 * - Every junction is at least the minimum planner speed (MINIMUM_PLANNER_SPEED, 0.05 mm/s; newer Marlin
 *   derives it from the steps per mm, which a slicer does not know: a few mm/s at most, and only where the
 *   junction rules give less).
 * - Reverse pass: each entry at most what brakes to the next entry within the block (the last block
 *   stops); forward pass: at most what the previous block reaches from its entry. Each block is a
 *   trapezoid (or triangle) between its entry and the next block's.
 */
import { MARLIN_MIN_MOVE_MM, MIN_ANGLE_RAD } from '../geometry/tolerances.js';

/** The limits Marlin plans with (mm, s). Infinity: no limit. */
export interface MarlinLimits {
  /** M203 X Y Z E, mm/s. */
  maxFeedrate: readonly [number, number, number, number];
  /** M201 X Y Z E, mm/s². */
  maxAccel: readonly [number, number, number, number];
  /** M204 P, T, R. */
  printAccel: number;
  travelAccel: number;
  retractAccel: number;
  /** M205 X Y Z E (classic jerk), or null for junction deviation. */
  jerk: readonly [number, number, number, number] | null;
  /** M205 J, mm (used when jerk is null). */
  junctionDeviation: number;
}

/** Marlin's MINIMUM_PLANNER_SPEED, mm/s. */
export const MINIMUM_PLANNER_SPEED = 0.05;
const MIN_SPEED2 = MINIMUM_PLANNER_SPEED * MINIMUM_PLANNER_SPEED;

/**
 * Time of one trapezoid of `length` mm: entry v0, cruise at most vc, exit v1 (mm/s), acceleration a.
 * v0 and v1 must be reachable from each other within the length (the passes see to it).
 */
export function trapezoidSeconds(length: number, v0: number, vc: number, v1: number, a: number): number {
  if (vc < v0) vc = v0;
  if (vc < v1) vc = v1;
  const accelD = (vc * vc - v0 * v0) / (2 * a);
  const decelD = (vc * vc - v1 * v1) / (2 * a);
  if (accelD + decelD <= length) return (vc - v0) / a + (vc - v1) / a + (length - accelD - decelD) / vc;
  const peak = Math.sqrt(a * length + (v0 * v0 + v1 * v1) / 2);
  return (2 * peak - v0 - v1) / a;
}

/** Marlin's limit_value_by_axis_maximum: `value` cut so that no axis of `unit` exceeds its maximum. */
function limitByAxes(value: number, unit: Float64Array, max: readonly number[]): number {
  for (let i = 0; i < 4; i++) {
    const c = unit[i] < 0 ? -unit[i] : unit[i];
    if (c > 0 && value * c > max[i]) value = max[i] / c;
  }
  return value;
}

/**
 * The planner: moves in (relative mm and a feed rate), the time of each move into `seconds[tag]` (the tag
 * current when the move was added) once its speeds are final (at a stop, or at flush()).
 */
export class MarlinPlanner {
  /** Seconds by tag (layer). */
  readonly seconds: number[] = [];
  tag = 0;
  readonly #L: MarlinLimits;
  // the queue since the last block that starts at rest regardless of what follows it
  #length: number[] = [];
  #nominal: number[] = [];
  #accel: number[] = [];
  #maxEntry2: number[] = [];
  #tags: number[] = [];
  // the previous block, for junctions; and this block's (swapped in once it is queued): no allocation per move
  #prevUnit = new Float64Array(4);
  #prevSpeed = new Float64Array(4);
  #prevNominal = 0;
  #unit = new Float64Array(4);
  #current = new Float64Array(4);
  readonly #d = new Float64Array(4);
  readonly #j = new Float64Array(4);
  readonly #diff = new Float64Array(4);

  constructor(limits: MarlinLimits) {
    this.#L = limits;
  }

  /** A move by (dx, dy, dz, de) mm at feed rate `speed` mm/s (over XYZ, or over E for an extruder-only move). */
  move(dx: number, dy: number, dz: number, de: number, speed: number): void {
    const L = this.#L;
    const xyz = Math.sqrt(dx * dx + dy * dy + dz * dz);
    const eOnly = xyz < MARLIN_MIN_MOVE_MM;
    const length = eOnly ? Math.abs(de) : xyz;
    if (!(length > MARLIN_MIN_MOVE_MM) || !(speed > 0)) return;
    const d = this.#d;
    d[0] = dx;
    d[1] = dy;
    d[2] = dz;
    d[3] = de;
    // nominal speed, cut by the axes' max feed rates
    const inv = speed / length;
    let factor = 1;
    for (let i = 0; i < 4; i++) {
      const cs = Math.abs(d[i] * inv);
      if (cs > L.maxFeedrate[i] && L.maxFeedrate[i] / cs < factor) factor = L.maxFeedrate[i] / cs;
    }
    const nominal = speed * factor;
    const current = this.#current;
    for (let i = 0; i < 4; i++) current[i] = d[i] * inv * factor;
    // acceleration, cut by the axes' max accelerations
    let accel: number;
    if (eOnly) accel = L.retractAccel;
    else {
      accel = de !== 0 ? L.printAccel : L.travelAccel;
      for (let i = 0; i < 4; i++) {
        const c = Math.abs(d[i]);
        if (c > 0 && (L.maxAccel[i] * length) / c < accel) accel = (L.maxAccel[i] * length) / c;
      }
    }
    const first = this.#prevNominal <= 0;
    let v2: number;
    if (L.jerk === null) {
      // junction deviation
      const unit = this.#unit;
      if (de !== 0) {
        const n = Math.sqrt(dx * dx + dy * dy + dz * dz + de * de);
        unit[0] = dx / n;
        unit[1] = dy / n;
        unit[2] = dz / n;
        unit[3] = de / n;
      } else {
        unit[0] = dx / xyz;
        unit[1] = dy / xyz;
        unit[2] = dz / xyz;
        unit[3] = 0;
      }
      if (first) v2 = MIN_SPEED2;
      else {
        const p = this.#prevUnit;
        let cos = -(p[0] * unit[0] + p[1] * unit[1] + p[2] * unit[2] + p[3] * unit[3]);
        if (cos > 0.999999) v2 = MIN_SPEED2;
        else {
          const j = this.#j;
          for (let i = 0; i < 4; i++) j[i] = unit[i] - p[i];
          const jn = Math.sqrt(j[0] * j[0] + j[1] * j[1] + j[2] * j[2] + j[3] * j[3]);
          for (let i = 0; i < 4; i++) j[i] /= jn;
          const ja = limitByAxes(accel, j, L.maxAccel);
          if (cos < -0.999999) cos = -0.999999;
          const sinHalf = Math.sqrt(0.5 * (1 - cos));
          v2 = (ja * L.junctionDeviation * sinHalf) / (1 - sinHalf);
          if (length < 1 && cos < -0.7071067812) {
            const theta = Math.max(Math.acos(-cos), MIN_ANGLE_RAD);
            const arc = (length * ja) / theta;
            if (arc < v2) v2 = arc;
          }
        }
        const slower = Math.min(nominal, this.#prevNominal);
        if (slower * slower < v2) v2 = slower * slower;
      }
      this.#unit = this.#prevUnit;
      this.#prevUnit = unit;
    } else {
      // classic jerk
      const jerk = L.jerk;
      const diff = this.#diff;
      diff.set(current);
      let vj: number;
      if (first) vj = nominal;
      else if (nominal < this.#prevNominal) {
        vj = nominal;
        const scale = vj / this.#prevNominal;
        for (let i = 0; i < 4; i++) diff[i] -= this.#prevSpeed[i] * scale;
      } else {
        vj = this.#prevNominal;
        const scale = vj / nominal;
        for (let i = 0; i < 4; i++) diff[i] = diff[i] * scale - this.#prevSpeed[i];
      }
      let vf = 1;
      for (let i = 0; i < 4; i++) {
        const j = Math.abs(diff[i]);
        if (j * vf > jerk[i]) vf = jerk[i] / j;
      }
      v2 = (vj * vf) ** 2;
    }
    if (v2 < MIN_SPEED2) v2 = MIN_SPEED2;
    // a block that can only start at the minimum speed ends what the blocks before it depend on
    if (v2 <= MIN_SPEED2 && this.#length.length) this.#plan();
    this.#length.push(length);
    this.#nominal.push(nominal);
    this.#accel.push(accel);
    this.#maxEntry2.push(v2);
    this.#tags.push(this.tag);
    this.#current = this.#prevSpeed;
    this.#prevSpeed = current;
    this.#prevNominal = nominal;
  }

  /** Plan and time everything queued, the last block stopping, and start afresh (the head at rest). */
  flush(): void {
    this.#plan();
    this.#prevNominal = 0;
  }

  /** The reverse and forward passes over the queue (its last block ending at the minimum speed), its times added. */
  #plan(): void {
    const n = this.#length.length;
    if (n === 0) return;
    const len = this.#length,
      nom = this.#nominal,
      acc = this.#accel,
      maxE = this.#maxEntry2;
    const entry = new Float64Array(n);
    // reverse: each entry at most what brakes to the next one
    let next2 = MIN_SPEED2;
    for (let i = n - 1; i >= 0; i--) {
      const brake = next2 + 2 * acc[i] * len[i];
      entry[i] = maxE[i] < brake ? maxE[i] : brake;
      next2 = entry[i];
    }
    // forward: each entry at most what the previous block reaches; then the trapezoids
    for (let i = 1; i < n; i++) {
      const reach = entry[i - 1] + 2 * acc[i - 1] * len[i - 1];
      if (reach < entry[i]) entry[i] = reach;
    }
    for (let i = 0; i < n; i++) {
      const v0 = Math.sqrt(entry[i]);
      const v1 = Math.sqrt(i + 1 < n ? entry[i + 1] : MIN_SPEED2);
      const t = trapezoidSeconds(len[i], v0, nom[i], v1, acc[i]);
      const tag = this.#tags[i];
      while (this.seconds.length <= tag) this.seconds.push(0);
      this.seconds[tag] += t;
    }
    this.#length = [];
    this.#nominal = [];
    this.#accel = [];
    this.#maxEntry2 = [];
    this.#tags = [];
  }
}
