/**
 * Where a wall loop starts (its seam): aligned on a sharp corner near the rear, nearest to the nozzle,
 * at the rear, or at a seeded random vertex. Deterministic for a given layer and loop.
 */
import { hypot, type Polygon, type Pt } from '../geometry/types.js';

export type SeamMode = 'aligned' | 'nearest' | 'rear' | 'random';

/** A small deterministic hash → [0, 1). */
export function hash01(a: number, b: number, c: number): number {
  let h = (a * 0x9e3779b1) ^ (b * 0x85ebca77) ^ (c * 0xc2b2ae3d);
  h = Math.imul(h ^ (h >>> 16), 0x7feb352d);
  h = Math.imul(h ^ (h >>> 15), 0x846ca68b);
  h ^= h >>> 16;
  return (h >>> 0) / 4294967296;
}

function rearmost(loop: Polygon): number {
  let best = 0;
  for (let i = 1; i < loop.length; i++) {
    const p = loop[i],
      q = loop[best];
    if (p.y > q.y || (p.y === q.y && p.x < q.x)) best = i;
  }
  return best;
}

function nearest(loop: Polygon, at: Pt): number {
  let best = 0;
  let bd = Infinity;
  for (let i = 0; i < loop.length; i++) {
    const d = (loop[i].x - at.x) ** 2 + (loop[i].y - at.y) ** 2;
    if (d < bd) {
      bd = d;
      best = i;
    }
  }
  return best;
}

/** Turn at vertex i in radians: positive = left (convex for a CCW outer ring), negative = right. */
function turn(loop: Polygon, i: number): number {
  const n = loop.length;
  const a = loop[(i - 1 + n) % n],
    b = loop[i],
    c = loop[(i + 1) % n];
  const ux = b.x - a.x,
    uy = b.y - a.y,
    vx = c.x - b.x,
    vy = c.y - b.y;
  return Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

/** Sharpest-corner seam: among corners turning more than 40°, the one nearest the loop's rear; else the rearmost vertex. */
function aligned(loop: Polygon): number {
  let maxY = -Infinity,
    minX = Infinity,
    maxX = -Infinity;
  for (const p of loop) {
    if (p.y > maxY) maxY = p.y;
    if (p.x < minX) minX = p.x;
    if (p.x > maxX) maxX = p.x;
  }
  const ref = { x: (minX + maxX) / 2, y: maxY };
  const SHARP = (40 * Math.PI) / 180;
  let best = -1;
  let bestScore = Infinity;
  for (let i = 0; i < loop.length; i++) {
    const t = Math.abs(turn(loop, i));
    if (t < SHARP) continue;
    const p = loop[i];
    // distance to the rear reference, lightly favouring sharper corners
    const score = hypot(p.x - ref.x, p.y - ref.y) * (1.5 - t / Math.PI);
    if (score < bestScore) {
      bestScore = score;
      best = i;
    }
  }
  return best >= 0 ? best : rearmost(loop);
}

export function chooseSeam(loop: Polygon, mode: SeamMode, at: Pt, seed: number, layer: number, loopNo: number): number {
  switch (mode) {
    case 'nearest':
      return nearest(loop, at);
    case 'rear':
      return rearmost(loop);
    case 'random':
      return Math.floor(hash01(seed, layer, loopNo) * loop.length) % loop.length;
    case 'aligned':
      return aligned(loop);
  }
}

/** The loop rotated to start at vertex `start`. */
export function rotateLoop(loop: Polygon, start: number): Polygon {
  if (start === 0) return loop;
  const out: Polygon = [];
  for (let i = start; i < loop.length; i++) out.push(loop[i]);
  for (let i = 0; i < start; i++) out.push(loop[i]);
  return out;
}
