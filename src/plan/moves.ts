/**
 * The machine moves a print plan turns into, in order: Z moves, travels, extrusion segments,
 * retractions and primes. The G-code writer and the time/filament estimate both walk a plan through
 * `walkPlan`, so the estimate describes exactly the moves that get written.
 *
 * Conventions (documented once, here):
 * - A travel step goes from the current position through each of its points in turn.
 * - An extrude step starts at `points[0]`; when the nozzle is elsewhere an implicit travel (no
 *   retraction) goes there first, at the layer's travel speed. A closed step returns to `points[0]`.
 * - A retracting travel: retract, lift to layer Z + zHop (or just move to layer Z), travel, come back
 *   down to layer Z, prime `retractionDistance + retractionExtraPrime`. Retractions happen only when the
 *   step asks for one and `retractionEnabled` is on; the Z hop only with a retraction.
 * - Otherwise every layer's first move is preceded by a Z move to the layer's Z.
 * - A travel with `liftTo` (sequential printing: on to the next object) rises to that Z instead of the
 *   layer's (+ zHop), travels there, and only then comes down to the layer's Z, which may be lower than
 *   the layer before's: Z goes down only there. As a layer's last step it stays up (the end of a sequential
 *   print, so the end template's moves clear every object).
 * - E per mm of path = width × height / (π·(filamentDiameter/2)²) × flow × flowRate/100: the
 *   rectangular cross-section model (the same one the planner's widths are computed for). A step with a
 *   width per point gives each segment the mean of its two end widths.
 * - A step with a Z per point moves the nozzle to the layer's Z plus that value along each segment (one
 *   G1 with X, Y and Z); the next step comes back to the layer's Z first. On a spiral vase turn
 *   (`LayerPlan.spiral`) such a step starts at the Z the nozzle is at when its first point's Z is that
 *   (the previous turn's end): no Z move to the layer's Z comes before it.
 * - XY speeds are capped at `maxSpeed` (and floored at MIN_SPEED_MM_S so a feed rate is never 0).
 * - Zero-length segments are dropped.
 * - A segment with an arc (`step.arcs[i]`) goes around its centre in its direction; its length, and so
 *   its filament, is the arc's (radius from the start point × swept angle).
 * - Object labels: the moves of an extrusion with an `object`, and the travels between two extrusions of
 *   that object, lie between `objectStart` and `objectEnd`; travels from one object to another, layer
 *   changes and Z moves to the layer stay outside, so skipping an object's moves skips whole
 *   retract/prime pairs and never a layer change. Every object is ended before its layer ends.
 * - Firmware retraction: the prime is the same length as the retraction (the firmware's own lengths are
 *   used; no extra prime can be asked for).
 * - Standalone Z moves go at Z_SPEED_MM_S, or `maxSpeedZ` when that is slower; a z-hop's rise and
 *   descent at `zHopSpeed` when set (capped at `maxSpeedZ`). The hop is a Z move of its own, before
 *   the XY travel (no ramp).
 * - Wipe (`wipeDistance` > 0): a retracting travel that comes right after an extrusion first retracts
 *   `retractBeforeWipe` % of the retraction on the spot, then moves back along the path the nozzle has
 *   just followed (that extrusion, and its coasted end) for up to `wipeDistance`, retracting the rest
 *   on the way in proportion to the length moved (`wipe` moves: XY with negative E); what a shorter path
 *   leaves of it is retracted on the spot at the wipe's end. Then the lift and the travel, from the
 *   wipe's end. Wipe speed: 80 % of the travel speed, slower when the retraction would otherwise run
 *   faster than `retractionSpeed`. With firmware retraction the wipe moves carry no E and come before
 *   the G10.
 * - Coasting (`coastingVolume` > 0): an extrusion right before a retracting travel (the next step, or the
 *   next layer's first) ends with a plain move over its last coastingVolume / (width × height) mm (the
 *   end width where widths vary), at the extrusion's speed: `travel` moves, so the coasted part ends
 *   exactly where the extrusion ended and the travel starts. Not on steps with a Z per point, with less
 *   volume than `coastingMinVolume` (length × width × height), or shorter than twice the coasted length.
 */
import type { ExtrudeStep, LayerPlan, PrintPlan } from './types.js';
import type { Settings } from '../settings/schema.js';
import { hypot } from '../geometry/types.js';

/** Speed of standalone Z moves (layer change, Z hop), mm/s: a rate every common printer's Z axis accepts. */
export const Z_SPEED_MM_S = 5;
/** A spiral turn whose first Z is this close to the nozzle's starts there without a Z move, mm. */
const SPIRAL_SAME_Z_MM = 1e-6;
/** Slowest feed rate ever written, mm/s: keeps F positive whatever a plan asks. */
export const MIN_SPEED_MM_S = 0.1;

/** The settings the move expansion reads. */
export type MoveSettings = Pick<
  Settings,
  | 'maxSpeed'
  | 'filamentDiameter'
  | 'flowRate'
  | 'retractionEnabled'
  | 'retractionDistance'
  | 'retractionSpeed'
  | 'retractionExtraPrime'
  | 'travelSpeed'
  | 'firstLayerTravelSpeed'
  | 'firmwareRetraction'
  | 'maxSpeedZ'
  | 'zHopSpeed'
  | 'wipeDistance'
  | 'retractBeforeWipe'
  | 'coastingVolume'
  | 'coastingMinVolume'
>;

/** Share of the travel speed a wipe moves at (PrusaSlicer's and OrcaSlicer's default). */
export const WIPE_SPEED_FACTOR = 0.8;
/** Longest chord a wipe or a coasted move follows an arc by, mm. */
const ARC_CHORD_MM = 0.5;

/**
 * Receives the moves of a plan. Positions are µm (bed space), Z and lengths mm, speeds mm/s (already
 * capped), filament amounts mm of filament. A length or distance is NaN when the move starts from an
 * unknown position (the first move after the start G-code).
 */
export interface MoveSink {
  layerStart(layer: LayerPlan, position: number): void;
  layerEnd(layer: LayerPlan, position: number): void;
  zMove(z: number, distance: number, speed: number): void;
  travel(x: number, y: number, length: number, speed: number): void;
  /** Called before the segments of each extrude step (after any implicit travel to its start). */
  extrudeStart(step: ExtrudeStep): void;
  extrude(x: number, y: number, length: number, filament: number, speed: number): void;
  /** An extrusion that also moves Z (to `z`, mm), for steps with a Z per point. */
  extrudeZ(x: number, y: number, z: number, length: number, filament: number, speed: number): void;
  /** An extrusion along a circular arc around (cx, cy) µm to (x, y); `length` is the arc's, mm. */
  arc(
    x: number,
    y: number,
    cx: number,
    cy: number,
    clockwise: boolean,
    length: number,
    filament: number,
    speed: number,
  ): void;
  retract(filament: number, speed: number): void;
  /**
   * A wipe move to (x, y) µm, `length` mm, retracting `filament` mm on the way (0 with firmware
   * retraction: a plain move).
   */
  wipe(x: number, y: number, length: number, filament: number, speed: number): void;
  prime(filament: number, speed: number): void;
  /** The moves of object `index` (into `PrintPlan.objects`) begin. */
  objectStart(index: number): void;
  /** The moves of object `index` end. */
  objectEnd(index: number): void;
}

/**
 * Length (mm) of the arc from (x0, y0) to (x1, y1) around (cx, cy), all µm, turning `clockwise` or not:
 * the start radius times the swept angle, which lies in (0, 2π).
 */
export function arcLengthMm(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  cx: number,
  cy: number,
  clockwise: boolean,
): number {
  const a0 = Math.atan2(y0 - cy, x0 - cx);
  const a1 = Math.atan2(y1 - cy, x1 - cx);
  let sweep = clockwise ? a0 - a1 : a1 - a0;
  if (sweep <= 0) sweep += 2 * Math.PI;
  return (hypot(x0 - cx, y0 - cy) * sweep) / 1000;
}

/** Filament cross-section area, mm². */
export function filamentAreaMm2(filamentDiameter: number): number {
  const r = filamentDiameter / 2;
  return Math.PI * r * r;
}

/** Millimetres of filament per millimetre of an extrusion path `width` mm wide (rectangular cross-section). */
export function filamentPerMm(
  step: ExtrudeStep,
  s: Pick<MoveSettings, 'filamentDiameter' | 'flowRate'>,
  width = step.width,
): number {
  return ((width * step.height) / filamentAreaMm2(s.filamentDiameter)) * step.flow * (s.flowRate / 100);
}

/**
 * Filament of the segment of `step` from point `a` to point `b` (indices), `length` mm long: with widths per
 * point, for the mean of its two end widths (the firmware spreads a segment's E evenly, so it is laid at one
 * width); else for the step's width.
 */
export function segmentFilament(
  step: ExtrudeStep,
  s: Pick<MoveSettings, 'filamentDiameter' | 'flowRate'>,
  perMm: number,
  a: number,
  b: number,
  length: number,
): number {
  const widths = step.widths;
  if (!widths) return length * perMm;
  return length * filamentPerMm(step, s, (widths[a]! + widths[b]!) / 2);
}

function capSpeed(speed: number, maxSpeed: number): number {
  if (!(speed > MIN_SPEED_MM_S)) return MIN_SPEED_MM_S;
  return speed < maxSpeed ? speed : maxSpeed;
}

/** Where the walk has left the nozzle (µm; Z mm, NaN until the first Z move). */
interface Position {
  x: number;
  y: number;
  z: number;
  /** False until the first XY move: the start G-code leaves the nozzle somewhere unknown. */
  known: boolean;
}

function moveZ(pos: Position, target: number, speed: number, sink: MoveSink): void {
  if (target === pos.z) return;
  sink.zMove(target, Number.isNaN(pos.z) ? NaN : Math.abs(target - pos.z), speed);
  pos.z = target;
}

function travelTo(pos: Position, x: number, y: number, speed: number, sink: MoveSink): void {
  if (pos.known && x === pos.x && y === pos.y) return;
  const dx = x - pos.x;
  const dy = y - pos.y;
  const length = pos.known ? Math.sqrt(dx * dx + dy * dy) / 1000 : NaN;
  pos.x = x;
  pos.y = y;
  pos.known = true;
  sink.travel(x, y, length, speed);
}

/** No object: skirt, brim, raft, or nothing open. */
const NO_OBJECT = -1;

/** The object of the next extrusion after step `from` in `steps` (NO_OBJECT when it has none or there is none). */
function nextObject(steps: LayerPlan['steps'], from: number): number {
  for (let i = from + 1; i < steps.length; i++) {
    const step = steps[i]!;
    if (step.kind === 'extrude' && step.points.length > 0) return step.object ?? NO_OBJECT;
  }
  return NO_OBJECT;
}

/** Walk `plan` in print order, telling `sink` every machine move. */
export function walkPlan(plan: PrintPlan, s: MoveSettings, sink: MoveSink): void {
  const steps = walkPlanSteps(plan, s, sink);
  while (!steps.next().done);
}

/** What the walk carries from layer to layer. */
interface Walk {
  plan: PrintPlan;
  s: MoveSettings;
  sink: MoveSink;
  retractDistance: number;
  primeDistance: number;
  zSpeed: number;
  /** Speed of a z-hop's Z moves. */
  hopSpeed: number;
  pos: Position;
  /** The object whose moves are open. */
  open: number;
  /** Wipe on (wipeDistance > 0 with retraction). */
  wipe: boolean;
  /**
   * With wipe: the XY points (µm, x and y interleaved) the nozzle went through in the last extrude step,
   * its coasted end included, up to where it is; emptied by any other move.
   */
  behind: number[];
}

/** `walkPlan` as steps: yields after each layer, so a caller can pause between layers. */
export function* walkPlanSteps(plan: PrintPlan, s: MoveSettings, sink: MoveSink): Generator<void, void> {
  const zSpeed = s.maxSpeedZ !== null && s.maxSpeedZ < Z_SPEED_MM_S ? s.maxSpeedZ : Z_SPEED_MM_S;
  const retractDistance = s.retractionEnabled ? s.retractionDistance : 0;
  const w: Walk = {
    plan,
    s,
    sink,
    retractDistance,
    primeDistance: !s.retractionEnabled
      ? 0
      : s.firmwareRetraction
        ? s.retractionDistance
        : s.retractionDistance + s.retractionExtraPrime,
    zSpeed,
    hopSpeed:
      s.zHopSpeed === null ? zSpeed : s.maxSpeedZ !== null && s.maxSpeedZ < s.zHopSpeed ? s.maxSpeedZ : s.zHopSpeed,
    pos: { x: 0, y: 0, z: NaN, known: false },
    open: NO_OBJECT,
    wipe: retractDistance > 0 && s.wipeDistance > 0,
    behind: [],
  };
  for (let li = 0; li < plan.layers.length; li++) {
    walkLayer(w, plan.layers[li]!, li);
    yield;
  }
}

/** Whether the step after step `si` of layer `li` (the next layer's first, after a layer's last) is a retracting travel. */
function retractsNext(w: Walk, li: number, si: number): boolean {
  const steps = w.plan.layers[li]!.steps;
  const next = si + 1 < steps.length ? steps[si + 1] : w.plan.layers[li + 1]?.steps[0];
  return next !== undefined && next.kind === 'travel' && next.retract;
}

/** Point (µm) at `distance` mm along the arc from (x, y) around (cx, cy) in its direction. */
function alongArc(
  x: number,
  y: number,
  cx: number,
  cy: number,
  clockwise: boolean,
  distance: number,
): [number, number] {
  const r = hypot(x - cx, y - cy);
  const a = Math.atan2(y - cy, x - cx) + ((clockwise ? -1 : 1) * distance * 1000) / r;
  return [cx + r * Math.cos(a), cy + r * Math.sin(a)];
}

/** Points (µm) every ARC_CHORD_MM or less along an arc of `length` mm from (x, y), after the start, up to (ex, ey) exactly. */
function arcChords(
  x: number,
  y: number,
  ex: number,
  ey: number,
  cx: number,
  cy: number,
  clockwise: boolean,
  length: number,
): number[] {
  const pieces = Math.max(1, Math.ceil(length / ARC_CHORD_MM));
  const out: number[] = [];
  for (let k = 1; k < pieces; k++) out.push(...alongArc(x, y, cx, cy, clockwise, (length * k) / pieces));
  out.push(ex, ey);
  return out;
}

/**
 * The coasted length of an extrude step (mm, from its end), or 0 when it is not coasted: see the module
 * comment. `n` points, `last` segments.
 */
function coastLengthMm(s: MoveSettings, step: ExtrudeStep, n: number, last: number): number {
  if (step.z) return 0;
  const width = step.widths ? step.widths[step.closed ? 0 : n - 1]! : step.width;
  const coast = s.coastingVolume / (width * step.height);
  if (!(coast > 0)) return 0;
  const points = step.points;
  let total = 0;
  let p = points[0]!;
  for (let i = 1; i <= last; i++) {
    const q = points[i === n ? 0 : i]!;
    const arc = step.arcs?.[i];
    total += arc ? arcLengthMm(p.x, p.y, q.x, q.y, arc.cx, arc.cy, arc.clockwise) : hypot(q.x - p.x, q.y - p.y) / 1000;
    p = q;
  }
  if (total < 2 * coast || total * width * step.height < s.coastingMinVolume) return 0;
  return coast;
}

/**
 * Retract for a travel with a wipe (see the module comment): back along `w.behind` from the nozzle,
 * retracting on the way; `travelSpeed` the travel's (capped).
 */
function wipeRetract(w: Walk, travelSpeed: number): void {
  const { s, sink, pos, behind } = w;
  const total = w.retractDistance;
  const firmware = s.firmwareRetraction;
  const before = firmware ? 0 : (total * s.retractBeforeWipe) / 100;
  const during = firmware ? 0 : total - before;
  const distance = s.wipeDistance;
  let speed = WIPE_SPEED_FACTOR * travelSpeed;
  if (during > 0 && (s.retractionSpeed * distance) / during < speed) speed = (s.retractionSpeed * distance) / during;
  speed = capSpeed(speed, s.maxSpeed);
  if (before > 0) sink.retract(before, s.retractionSpeed);
  let left = distance;
  let retracted = 0;
  let x = pos.x;
  let y = pos.y;
  for (let k = behind.length - 4; k >= 0 && left > 0; k -= 2) {
    const dx = behind[k]! - x;
    const dy = behind[k + 1]! - y;
    const length = Math.sqrt(dx * dx + dy * dy) / 1000;
    if (length === 0) continue;
    const part = length < left ? length : left;
    const f = part / length;
    const tx = part === length ? behind[k]! : x + dx * f;
    const ty = part === length ? behind[k + 1]! : y + dy * f;
    left -= part;
    const e = left > 0 ? (during * part) / distance : during - retracted;
    sink.wipe(tx, ty, part, e, speed);
    retracted += e;
    x = tx;
    y = ty;
  }
  pos.x = x;
  pos.y = y;
  if (firmware) sink.retract(total, s.retractionSpeed);
  else if (during - retracted > 0) sink.retract(during - retracted, s.retractionSpeed);
}

/**
 * The moves of one layer. A plain function, called once a layer, which the engine optimises early: the loop
 * of a generator's own body runs unoptimised to its end.
 */
function walkLayer(w: Walk, layer: LayerPlan, li: number): void {
  const { s, sink, pos, retractDistance, primeDistance, zSpeed, hopSpeed, behind } = w;
  const layerZ = layer.z;
  const travelSpeed = capSpeed(li === 0 ? s.firstLayerTravelSpeed : s.travelSpeed, s.maxSpeed);
  const coasting = retractDistance > 0 && s.coastingVolume > 0;
  sink.layerStart(layer, li);
  const steps = layer.steps;
  for (let si = 0; si < steps.length; si++) {
    const step = steps[si]!;
    if (step.kind === 'travel') {
      if (w.open !== NO_OBJECT && nextObject(steps, si) !== w.open) {
        sink.objectEnd(w.open);
        w.open = NO_OBJECT;
      }
      const speed = capSpeed(step.speed, s.maxSpeed);
      const retracting = step.retract && s.retractionEnabled;
      if (retracting && retractDistance > 0) {
        const n = behind.length;
        if (w.wipe && n >= 4 && behind[n - 2] === pos.x && behind[n - 1] === pos.y) wipeRetract(w, speed);
        else sink.retract(retractDistance, s.retractionSpeed);
      }
      behind.length = 0;
      const lift = step.liftTo;
      const hop = lift === undefined && retracting && step.zHop > 0;
      moveZ(pos, lift !== undefined ? lift : hop ? layerZ + step.zHop : layerZ, hop ? hopSpeed : zSpeed, sink);
      for (let k = 0; k < step.points.length; k++) travelTo(pos, step.points[k].x, step.points[k].y, speed, sink);
      if (lift === undefined || si < steps.length - 1) moveZ(pos, layerZ, hop ? hopSpeed : zSpeed, sink);
      if (retracting && primeDistance > 0) sink.prime(primeDistance, s.retractionSpeed);
      continue;
    }
    const points = step.points;
    const n = points.length;
    if (n === 0) continue;
    behind.length = 0;
    const zs = step.z;
    // a spiral turn's rising steps start at the Z the nozzle is at (see below)
    if (!(zs && layer.spiral)) moveZ(pos, layerZ, zSpeed, sink);
    const object = step.object ?? NO_OBJECT;
    if (object !== w.open) {
      if (w.open !== NO_OBJECT) sink.objectEnd(w.open);
      if (object !== NO_OBJECT) sink.objectStart(object);
      w.open = object;
    }
    travelTo(pos, points[0]!.x, points[0]!.y, travelSpeed, sink);
    if (zs) {
      const z0 = layerZ + zs[0]!;
      // a spiral turn goes on from the previous turn's end: the same Z but for the rounding of the layer's
      // Z plus the offset back down to the previous one
      if (layer.spiral && Math.abs(z0 - pos.z) < SPIRAL_SAME_Z_MM) pos.z = z0;
      else moveZ(pos, z0, zSpeed, sink);
    }
    sink.extrudeStart(step);
    const speed = capSpeed(step.speed, s.maxSpeed);
    const perMm = filamentPerMm(step, s);
    const arcs = step.arcs;
    const last = step.closed ? n : n - 1;
    const record = w.wipe;
    if (record) behind.push(pos.x, pos.y);
    // coasting: the step is extruded up to `coastFrom` mm along it, then moved along without extrusion
    const coast = coasting && retractsNext(w, li, si) ? coastLengthMm(s, step, n, last) : 0;
    if (coast > 0) {
      walkCoasted(w, step, perMm, speed, last, coast);
      continue;
    }
    let x = pos.x;
    let y = pos.y;
    for (let i = 1; i <= last; i++) {
      const k = i === n ? 0 : i;
      const p = points[k]!;
      const dx = p.x - x;
      const dy = p.y - y;
      if (zs) {
        const z = layerZ + zs[k]!;
        const dz = z - pos.z;
        if (dx === 0 && dy === 0 && dz === 0) continue;
        const length = Math.sqrt(dx * dx + dy * dy + dz * dz * 1e6) / 1000;
        x = p.x;
        y = p.y;
        pos.z = z;
        sink.extrudeZ(x, y, z, length, segmentFilament(step, s, perMm, i - 1, k, length), speed);
        if (record) behind.push(x, y);
        continue;
      }
      if (dx === 0 && dy === 0) continue;
      const arc = arcs?.[i];
      if (arc) {
        const length = arcLengthMm(x, y, p.x, p.y, arc.cx, arc.cy, arc.clockwise);
        if (record) behind.push(...arcChords(x, y, p.x, p.y, arc.cx, arc.cy, arc.clockwise, length));
        x = p.x;
        y = p.y;
        sink.arc(x, y, arc.cx, arc.cy, arc.clockwise, length, segmentFilament(step, s, perMm, i - 1, k, length), speed);
        continue;
      }
      const length = Math.sqrt(dx * dx + dy * dy) / 1000;
      x = p.x;
      y = p.y;
      sink.extrude(x, y, length, segmentFilament(step, s, perMm, i - 1, k, length), speed);
      if (record) behind.push(x, y);
    }
    pos.x = x;
    pos.y = y;
  }
  if (w.open !== NO_OBJECT) {
    sink.objectEnd(w.open);
    w.open = NO_OBJECT;
  }
  sink.layerEnd(layer, li);
}

/**
 * The segments of a flat extrude step (no Z per point) whose last `coast` mm are coasted: extruded up to
 * there (the segment it falls in split, with its share of the filament), then `travel` moves at the
 * step's speed to its end (arcs followed by chords of at most ARC_CHORD_MM).
 */
function walkCoasted(w: Walk, step: ExtrudeStep, perMm: number, speed: number, last: number, coast: number): void {
  const { s, sink, pos, behind } = w;
  const record = w.wipe;
  const points = step.points;
  const n = points.length;
  const arcs = step.arcs;
  let total = 0;
  for (let i = 1, p = points[0]!; i <= last; i++) {
    const q = points[i === n ? 0 : i]!;
    const arc = arcs?.[i];
    total += arc ? arcLengthMm(p.x, p.y, q.x, q.y, arc.cx, arc.cy, arc.clockwise) : hypot(q.x - p.x, q.y - p.y) / 1000;
    p = q;
  }
  const coastFrom = total - coast;
  let done = 0;
  let x = pos.x;
  let y = pos.y;
  const coastTo = (tx: number, ty: number, length: number) => {
    sink.travel(tx, ty, length, speed);
    if (record) behind.push(tx, ty);
    x = tx;
    y = ty;
  };
  for (let i = 1; i <= last; i++) {
    const k = i === n ? 0 : i;
    const p = points[k]!;
    const dx = p.x - x;
    const dy = p.y - y;
    if (dx === 0 && dy === 0) continue;
    const arc = arcs?.[i];
    const length = arc
      ? arcLengthMm(x, y, p.x, p.y, arc.cx, arc.cy, arc.clockwise)
      : Math.sqrt(dx * dx + dy * dy) / 1000;
    const filament = segmentFilament(step, s, perMm, i - 1, k, length);
    const start = done;
    done += length;
    if (done <= coastFrom) {
      // extruded whole
      if (arc) {
        if (record) behind.push(...arcChords(x, y, p.x, p.y, arc.cx, arc.cy, arc.clockwise, length));
        sink.arc(p.x, p.y, arc.cx, arc.cy, arc.clockwise, length, filament, speed);
      } else {
        sink.extrude(p.x, p.y, length, filament, speed);
        if (record) behind.push(p.x, p.y);
      }
      x = p.x;
      y = p.y;
      continue;
    }
    // the part before coastFrom is extruded, the rest coasted
    const extruded = start < coastFrom ? coastFrom - start : 0;
    const f = extruded / length;
    if (arc) {
      const x0 = x;
      const y0 = y;
      if (extruded > 0) {
        const [mx, my] = alongArc(x0, y0, arc.cx, arc.cy, arc.clockwise, extruded);
        if (record) behind.push(...arcChords(x0, y0, mx, my, arc.cx, arc.cy, arc.clockwise, extruded));
        sink.arc(mx, my, arc.cx, arc.cy, arc.clockwise, extruded, filament * f, speed);
        x = mx;
        y = my;
      }
      const rest = length - extruded;
      const chords = arcChords(x, y, p.x, p.y, arc.cx, arc.cy, arc.clockwise, rest);
      for (let c = 0; c < chords.length; c += 2)
        coastTo(chords[c]!, chords[c + 1]!, hypot(chords[c]! - x, chords[c + 1]! - y) / 1000);
      continue;
    }
    if (extruded > 0) {
      const mx = x + dx * f;
      const my = y + dy * f;
      sink.extrude(mx, my, extruded, filament * f, speed);
      if (record) behind.push(mx, my);
      x = mx;
      y = my;
    }
    coastTo(p.x, p.y, length - extruded);
  }
  pos.x = x;
  pos.y = y;
}
