/**
 * The toolpath plan as a few flat typed arrays for a 3D preview (the web page draws them with
 * instancing): extrusion segments, travels and retraction points, each sorted by layer with
 * per-layer offsets, so a viewer shows "layers a to b" as an index range and never re-parses G-code.
 * Each segment also has its speed and fan, each layer its time, to colour by; and every extrusion
 * segment and travel its move number within its layer (the order the printer makes them), so a viewer
 * shows a layer move by move as a prefix of each array.
 * Built where the plan is (a worker), the arrays transfer to the page without copying.
 */
import { UM_PER_MM, type Pt } from '../geometry/types.js';
import { FEATURE_TYPES, type FeatureType, type PrintPlan } from '../plan/types.js';

/** Numbers per extrusion segment: x0 y0 x1 y1 (mm), z (top of the bead), width, height (mm), feature index, layer. */
export const SEGMENT_STRIDE = 9;
/** Numbers per travel segment: x0 y0 z0 x1 y1 z1 (mm), layer. */
export const TRAVEL_STRIDE = 7;
/** Numbers per retraction point: x y z (mm), layer. */
export const RETRACTION_STRIDE = 4;

export interface PreviewArrays {
  /** Each layer's nozzle Z, mm. */
  layerZ: Float32Array;
  /** Extrusion segments, SEGMENT_STRIDE numbers each; the feature is an index into FEATURE_TYPES. */
  segments: Float32Array;
  /** Layer i's segments are [layerSegments[i], layerSegments[i + 1]) (counted in segments). */
  layerSegments: Uint32Array;
  travels: Float32Array;
  layerTravels: Uint32Array;
  retractions: Float32Array;
  layerRetractions: Uint32Array;
  /** Extruded length per feature (FEATURE_TYPES order), mm. */
  featureLengthMm: Float64Array;
  /** Each extrusion segment's feed rate, mm/s. */
  segmentSpeed: Float32Array;
  /** Each extrusion segment's part-cooling fan, 0..1. */
  segmentFan: Float32Array;
  /** Each extrusion segment's move number within its layer (moves: extrusion segments and travels, in order). */
  segmentMove: Uint32Array;
  /** Each travel's move number within its layer. */
  travelMove: Uint32Array;
  /** Each retraction's move number within its layer: that of the travel it comes before. */
  retractionMove: Uint32Array;
  /** Moves per layer. */
  layerMoves: Uint32Array;
  /** Each layer's estimated time, s (zeros when no estimate was given). */
  layerSeconds: Float32Array;
}

const FEATURE_INDEX: ReadonlyMap<FeatureType, number> = new Map(FEATURE_TYPES.map((f, i) => [f, i]));

/** A growable Uint32Array, filled a value at a time. */
class Uints {
  data = new Uint32Array(1024);
  length = 0;
  push(v: number): void {
    if (this.length === this.data.length) {
      const next = new Uint32Array(this.data.length * 2);
      next.set(this.data);
      this.data = next;
    }
    this.data[this.length++] = v;
  }
  done(): Uint32Array {
    return this.data.slice(0, this.length);
  }
}

/** A growable Float32Array, filled a record at a time. */
class Floats {
  data = new Float32Array(4096);
  length = 0;
  /** Make room for `k` more numbers and return where they go. */
  add(k: number): number {
    if (this.length + k > this.data.length) {
      const next = new Float32Array(Math.max(this.data.length * 2, this.length + k));
      next.set(this.data.subarray(0, this.length));
      this.data = next;
    }
    const at = this.length;
    this.length += k;
    return at;
  }
  /** A right-sized copy (its own buffer, so it can be transferred). */
  done(): Float32Array {
    return this.data.slice(0, this.length);
  }
}

function put(f: Floats, ...values: number[]): void {
  const at = f.add(values.length);
  f.data.set(values, at);
}

/** The plan's arrays; `layerSeconds`: the estimate's time per layer (PlanEstimate.layerSeconds), for colouring by it. */
export function planToArrays(plan: PrintPlan, layerSeconds?: readonly number[]): PreviewArrays {
  const n = plan.layers.length;
  const segs = new Floats();
  const travels = new Floats();
  const retracts = new Floats();
  const speeds = new Floats();
  const fans = new Floats();
  const segmentMove = new Uints();
  const travelMove = new Uints();
  const retractionMove = new Uints();
  const layerMoves = new Uint32Array(n);
  const layerSegments = new Uint32Array(n + 1);
  const layerTravels = new Uint32Array(n + 1);
  const layerRetractions = new Uint32Array(n + 1);
  const layerZ = new Float32Array(n);
  const featureLengthMm = new Float64Array(FEATURE_TYPES.length);
  /** Nozzle position, mm; unknown before the first move (the start G-code leaves it anywhere). */
  let at: { x: number; y: number; z: number } | null = null;
  for (let li = 0; li < n; li++) {
    const layer = plan.layers[li];
    layerZ[li] = layer.z;
    layerSegments[li] = segs.length / SEGMENT_STRIDE;
    layerTravels[li] = travels.length / TRAVEL_STRIDE;
    layerRetractions[li] = retracts.length / RETRACTION_STRIDE;
    let move = 0;
    for (const step of layer.steps) {
      if (step.kind === 'travel') {
        // a travel on to the next object (sequential printing) goes at its lifted Z
        const z = step.liftTo ?? layer.z + (step.retract ? step.zHop : 0);
        if (step.retract && at) {
          put(retracts, at.x, at.y, at.z, li);
          retractionMove.push(move);
        }
        for (const p of step.points) {
          const x = p.x / UM_PER_MM,
            y = p.y / UM_PER_MM;
          if (at) {
            put(travels, at.x, at.y, at.z, x, y, z, li);
            travelMove.push(move++);
          }
          at = { x, y, z };
        }
        continue;
      }
      const fan = step.fan ?? layer.fan;
      const f = FEATURE_INDEX.get(step.feature) ?? 0;
      const pts: readonly Pt[] = step.points;
      const count = step.closed ? pts.length : pts.length - 1;
      const widths = step.widths,
        zs = step.z;
      let length = 0;
      for (let k = 0; k < count; k++) {
        const k1 = (k + 1) % pts.length;
        const a = pts[k],
          b = pts[k1];
        if (a.x === b.x && a.y === b.y) continue;
        const x0 = a.x / UM_PER_MM,
          y0 = a.y / UM_PER_MM,
          x1 = b.x / UM_PER_MM,
          y1 = b.y / UM_PER_MM;
        length += Math.hypot(x1 - x0, y1 - y0);
        const o = segs.add(SEGMENT_STRIDE),
          d = segs.data;
        d[o] = x0;
        d[o + 1] = y0;
        d[o + 2] = x1;
        d[o + 3] = y1;
        // a segment is drawn at the mean of its end widths (and, for a rising path, at its end's Z)
        d[o + 4] = zs ? layer.z + zs[k1]! : layer.z;
        d[o + 5] = widths ? (widths[k]! + widths[k1]!) / 2 : step.width;
        d[o + 6] = step.height;
        d[o + 7] = f;
        d[o + 8] = li;
        put(speeds, step.speed);
        put(fans, fan);
        segmentMove.push(move++);
      }
      featureLengthMm[f] += length;
      const last = step.closed ? pts[0] : pts[pts.length - 1];
      if (last) at = { x: last.x / UM_PER_MM, y: last.y / UM_PER_MM, z: layer.z };
    }
    layerMoves[li] = move;
  }
  layerSegments[n] = segs.length / SEGMENT_STRIDE;
  layerTravels[n] = travels.length / TRAVEL_STRIDE;
  layerRetractions[n] = retracts.length / RETRACTION_STRIDE;
  return {
    layerZ,
    segments: segs.done(),
    layerSegments,
    travels: travels.done(),
    layerTravels,
    retractions: retracts.done(),
    layerRetractions,
    featureLengthMm,
    segmentSpeed: speeds.done(),
    segmentFan: fans.done(),
    segmentMove: segmentMove.done(),
    travelMove: travelMove.done(),
    retractionMove: retractionMove.done(),
    layerMoves,
    layerSeconds: Float32Array.from({ length: n }, (_, i) => layerSeconds?.[i] ?? 0),
  };
}

/** The arrays' buffers: `postMessage`'s transfer list, to move the arrays to another thread rather than copy them. */
export function transferList(a: PreviewArrays): ArrayBuffer[] {
  return [
    a.layerZ,
    a.segments,
    a.layerSegments,
    a.travels,
    a.layerTravels,
    a.retractions,
    a.layerRetractions,
    a.featureLengthMm,
    a.segmentSpeed,
    a.segmentFan,
    a.segmentMove,
    a.travelMove,
    a.retractionMove,
    a.layerMoves,
    a.layerSeconds,
  ].map((t) => t.buffer as ArrayBuffer);
}
