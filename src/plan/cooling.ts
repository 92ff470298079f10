/**
 * Cooling: the part fan of each layer, and the minimum layer time.
 *
 * Fan: the first `fanOffLayers` layers of each object run `firstLayerFanSpeed`; from there the fan rises in
 * even steps to full at layer `fanFullLayer` (PrusaSlicer's full_fan_speed_layer, Cura's
 * cool_fan_full_layer). Full is `fanSpeed`, raised for a short layer: below `fanBelowLayerTime` seconds
 * towards `maxFanSpeed`, reached at `minLayerTime` (PrusaSlicer's fan_below_layer_time between min and max fan
 * speed, Cura's cool_min_layer_time_fan_speed_max). Layers are counted from each object's first: where Z
 * goes down (sequential printing, the next object) the count starts again.
 *
 * Minimum layer time: a layer that would print faster than `minLayerTime` has its extrusion speeds
 * scaled down (never below `minPrintSpeed`) so the plastic below has time to cool.
 * The layer time here is the simple length/speed sum; the final estimate is acceleration-aware.
 */
import { hypot, type Pt } from '../geometry/types.js';
import type { Config } from '../settings/resolve.js';
import type { LayerPlan, PrintPlan } from './types.js';
import { MIN_TIME_S } from '../geometry/tolerances.js';

/** Length of the path through `points` (from `from` first, when given), mm. */
function pathLengthMm(points: readonly Pt[], closed: boolean, from?: Pt): number {
  let len = from ? hypot(points[0].x - from.x, points[0].y - from.y) : 0;
  for (let i = 1; i < points.length; i++) len += hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
  if (closed && points.length > 2) {
    const a = points[points.length - 1],
      b = points[0];
    len += hypot(a.x - b.x, a.y - b.y);
  }
  return len / 1000;
}

/** Seconds the layer takes by length/speed (mm and mm/s), extrusions and travels. */
export function naiveLayerSeconds(layer: LayerPlan, from?: Pt): { extrude: number; travel: number } {
  let extrude = 0,
    travel = 0;
  let at = from;
  for (const s of layer.steps) {
    if (s.kind === 'extrude') {
      extrude += pathLengthMm(s.points, s.closed) / s.speed;
      at = s.closed ? s.points[0] : s.points[s.points.length - 1];
    } else {
      // the travel from where the last step ended
      travel += pathLengthMm(s.points, false, at) / s.speed;
      at = s.points[s.points.length - 1];
    }
  }
  return { extrude, travel };
}

/** Slow the layer's extrusions down so it lasts at least minLayerTime seconds. Mutates the steps' speeds. */
export function applyMinLayerTime(layer: LayerPlan, minLayerTime: number, minPrintSpeed: number): void {
  if (minLayerTime <= 0) return;
  const { extrude, travel } = naiveLayerSeconds(layer);
  const total = extrude + travel;
  if (total >= minLayerTime || extrude <= 0) return;
  const factor = extrude / Math.max(minLayerTime - travel, MIN_TIME_S);
  for (const s of layer.steps) {
    if (s.kind === 'extrude') s.speed = Math.max(Math.min(s.speed, minPrintSpeed), s.speed * factor);
  }
}

/** The fan settings the fan pass reads, fan speeds in %. */
export type FanSettings = Pick<
  Config,
  | 'fanSpeed'
  | 'firstLayerFanSpeed'
  | 'fanOffLayers'
  | 'fanFullLayer'
  | 'fanBelowLayerTime'
  | 'maxFanSpeed'
  | 'minLayerTime'
>;

/** The fan, 0..1, of layer `k` of its object that lasts `seconds` (before any slowing for minimum layer time). */
export function layerFan(cfg: FanSettings, k: number, seconds: number): number {
  if (k < cfg.fanOffLayers) return cfg.firstLayerFanSpeed / 100;
  let full = cfg.fanSpeed;
  const below = cfg.fanBelowLayerTime;
  if (below > 0 && seconds < below && cfg.maxFanSpeed > full) {
    const span = below - cfg.minLayerTime;
    const t = span > 0 ? Math.min(1, (below - seconds) / span) : 1;
    full += (cfg.maxFanSpeed - full) * t;
  }
  const off = cfg.fanOffLayers;
  if (cfg.fanFullLayer > off && k < cfg.fanFullLayer) {
    const start = cfg.firstLayerFanSpeed;
    full = start + ((full - start) * (k - off + 1)) / (cfg.fanFullLayer - off + 1);
  }
  return Math.round(full * 100) / 10000;
}

/** Set every layer's fan (the layer's own; bridges and overhangs keep theirs). */
export function applyLayerFans(plan: PrintPlan, cfg: FanSettings): void {
  let k = 0;
  let lastZ = -Infinity;
  for (const layer of plan.layers) {
    // Z going down starts the next object's layers (sequential printing)
    k = layer.z < lastZ ? 0 : k;
    lastZ = layer.z;
    const seconds = cfg.fanBelowLayerTime > 0 ? naiveLayerSeconds(layer) : null;
    layer.fan = layerFan(cfg, k, seconds ? seconds.extrude + seconds.travel : Infinity);
    k++;
  }
}
