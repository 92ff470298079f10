/**
 * Minimum layer time: a layer that would print faster than `minLayerTime` has its extrusion speeds
 * scaled down (never below `minPrintSpeed`) so the plastic below has time to cool.
 * The layer time here is the simple length/speed sum; the final estimate is acceleration-aware.
 */
import { hypot, type Pt } from '../geometry/types.js';
import type { LayerPlan } from './types.js';

/** Length of the path through `points` (from `from` first, when given), mm. */
function polyLength(points: readonly Pt[], closed: boolean, from?: Pt): number {
  let len = from ? hypot(points[0].x - from.x, points[0].y - from.y) : 0;
  for (let i = 1; i < points.length; i++) len += hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
  if (closed && points.length > 2) {
    const a = points[points.length - 1], b = points[0];
    len += hypot(a.x - b.x, a.y - b.y);
  }
  return len / 1000;
}

/** Seconds the layer takes by length/speed (mm and mm/s), extrusions and travels. */
export function naiveLayerSeconds(layer: LayerPlan, from?: Pt): { extrude: number; travel: number } {
  let extrude = 0, travel = 0;
  let at = from;
  for (const s of layer.steps) {
    if (s.kind === 'extrude') {
      extrude += polyLength(s.points, s.closed) / s.speed;
      at = s.closed ? s.points[0] : s.points[s.points.length - 1];
    } else {
      // the travel from where the last step ended
      travel += polyLength(s.points, false, at) / s.speed;
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
  const factor = extrude / Math.max(minLayerTime - travel, 1e-6);
  for (const s of layer.steps) {
    if (s.kind === 'extrude') s.speed = Math.max(Math.min(s.speed, minPrintSpeed), s.speed * factor);
  }
}
