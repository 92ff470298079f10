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
 * - Standalone Z moves go at Z_SPEED_MM_S, or `maxSpeedZ` when that is slower.
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
>;

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
  arc(x: number, y: number, cx: number, cy: number, clockwise: boolean, length: number, filament: number, speed: number): void;
  retract(filament: number, speed: number): void;
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
export function arcLengthMm(x0: number, y0: number, x1: number, y1: number, cx: number, cy: number, clockwise: boolean): number {
  const a0 = Math.atan2(y0 - cy, x0 - cx);
  const a1 = Math.atan2(y1 - cy, x1 - cx);
  let sweep = clockwise ? a0 - a1 : a1 - a0;
  if (sweep <= 0) sweep += 2 * Math.PI;
  return (hypot(x0 - cx, y0 - cy) * sweep) / 1000;
}

/** Filament cross-section area, mm². */
export function filamentArea(filamentDiameter: number): number {
  const r = filamentDiameter / 2;
  return Math.PI * r * r;
}

/** Millimetres of filament per millimetre of an extrusion path `width` mm wide (rectangular cross-section). */
export function filamentPerMm(step: ExtrudeStep, s: Pick<MoveSettings, 'filamentDiameter' | 'flowRate'>, width = step.width): number {
  return ((width * step.height) / filamentArea(s.filamentDiameter)) * step.flow * (s.flowRate / 100);
}

/**
 * Filament of the segment of `step` from point `a` to point `b` (indices), `length` mm long: with widths per
 * point, for the mean of its two end widths (the firmware spreads a segment's E evenly, so it is laid at one
 * width); else for the step's width.
 */
export function segmentFilament(step: ExtrudeStep, s: Pick<MoveSettings, 'filamentDiameter' | 'flowRate'>, perMm: number, a: number, b: number, length: number): number {
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
  s: MoveSettings;
  sink: MoveSink;
  retractDistance: number;
  primeDistance: number;
  zSpeed: number;
  pos: Position;
  /** The object whose moves are open. */
  open: number;
}

/** `walkPlan` as steps: yields after each layer, so a caller can pause between layers. */
export function* walkPlanSteps(plan: PrintPlan, s: MoveSettings, sink: MoveSink): Generator<void, void> {
  const w: Walk = {
    s,
    sink,
    retractDistance: s.retractionEnabled ? s.retractionDistance : 0,
    primeDistance: !s.retractionEnabled ? 0 : s.firmwareRetraction ? s.retractionDistance : s.retractionDistance + s.retractionExtraPrime,
    zSpeed: s.maxSpeedZ !== null && s.maxSpeedZ < Z_SPEED_MM_S ? s.maxSpeedZ : Z_SPEED_MM_S,
    pos: { x: 0, y: 0, z: NaN, known: false },
    open: NO_OBJECT,
  };
  for (let li = 0; li < plan.layers.length; li++) {
    walkLayer(w, plan.layers[li]!, li);
    yield;
  }
}

/**
 * The moves of one layer. A plain function, called once a layer, which the engine optimises early: the loop
 * of a generator's own body runs unoptimised to its end.
 */
function walkLayer(w: Walk, layer: LayerPlan, li: number): void {
  const { s, sink, pos, retractDistance, primeDistance, zSpeed } = w;
  const layerZ = layer.z;
  const travelSpeed = capSpeed(li === 0 ? s.firstLayerTravelSpeed : s.travelSpeed, s.maxSpeed);
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
      if (retracting && retractDistance > 0) sink.retract(retractDistance, s.retractionSpeed);
      const lift = step.liftTo;
      moveZ(pos, lift !== undefined ? lift : retracting && step.zHop > 0 ? layerZ + step.zHop : layerZ, zSpeed, sink);
      for (let k = 0; k < step.points.length; k++) travelTo(pos, step.points[k].x, step.points[k].y, speed, sink);
      if (lift === undefined || si < steps.length - 1) moveZ(pos, layerZ, zSpeed, sink);
      if (retracting && primeDistance > 0) sink.prime(primeDistance, s.retractionSpeed);
      continue;
    }
    const points = step.points;
    const n = points.length;
    if (n === 0) continue;
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
        continue;
      }
      if (dx === 0 && dy === 0) continue;
      const arc = arcs?.[i];
      if (arc) {
        const length = arcLengthMm(x, y, p.x, p.y, arc.cx, arc.cy, arc.clockwise);
        x = p.x;
        y = p.y;
        sink.arc(x, y, arc.cx, arc.cy, arc.clockwise, length, segmentFilament(step, s, perMm, i - 1, k, length), speed);
        continue;
      }
      const length = Math.sqrt(dx * dx + dy * dy) / 1000;
      x = p.x;
      y = p.y;
      sink.extrude(x, y, length, segmentFilament(step, s, perMm, i - 1, k, length), speed);
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
