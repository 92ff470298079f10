/**
 * Surfaces people look at, end to end from the G-code alone: ironing (which layers, how much of the top it
 * covers, at what flow, after the skin), monotonic top skin around a hole (no line laid between two lines
 * already printed), concentric skin (closed loops), the top pattern where skin is top and bottom at once,
 * and the same bytes on every run. Each measurement is shown to find what it looks for on a slice that has
 * it and to miss it on one that has not, so it cannot pass by measuring nothing.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer } from '#strata/api/slicer.js';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { Feature } from '../../tools/analysis/feature-names.js';
import type { GcodeLayer, ParsedGcode } from '../../tools/analysis/gcode-types.js';
import { monotonicViolations, type Segment } from '../infill/test-monotonic.js';
import { box, join, type Arrays } from './test-meshes.js';

const BASE = { threads: 1, center: false, adhesionType: 'none', infillPattern: 'lines' } as const;
const FILAMENT_AREA = (Math.PI * 1.75 * 1.75) / 4;

async function slice(input: Arrays, options: Record<string, unknown> = {}): Promise<{ gcode: string; g: ParsedGcode }> {
  const r = await new Slicer({ ...BASE, ...options } as never).slice(input);
  return { gcode: r.gcode, g: parseGcode(r.gcode) };
}

/** Segments of one feature on a layer, in print order, with their index among the layer's extrusions. */
function segmentsOf(layer: GcodeLayer, feature: number): Array<Segment & { i: number; e: number }> {
  const t = layer.extrusions;
  const out: Array<Segment & { i: number; e: number }> = [];
  for (let i = 0; i < t.count; i++)
    if (t.feature[i] === feature) out.push({ i, x0: t.x0[i], y0: t.y0[i], x1: t.x1[i], y1: t.y1[i], e: t.e[i] });
  return out;
}

/** Z of the layers that have any of a feature. */
function layersWith(g: ParsedGcode, feature: number): number[] {
  return g.layers.filter((l) => segmentsOf(l, feature).length > 0).map((l) => Math.round(l.z * 100) / 100);
}

function layerAt(g: ParsedGcode, z: number): GcodeLayer {
  const l = g.layers.find((x) => Math.abs(x.z - z) < 0.05);
  assert.ok(l, `a layer at Z ${z}`);
  return l;
}

interface Rect {
  x0: number;
  y0: number;
  x1: number;
  y1: number;
}

/**
 * The share of a rectangle that passes of the nozzle sweep over: points on a 0.025 mm grid within `reach` of
 * a segment.
 */
function coverage(segs: readonly Segment[], r: Rect, reach: number): number {
  const step = 0.025;
  const nx = Math.round((r.x1 - r.x0) / step),
    ny = Math.round((r.y1 - r.y0) / step);
  const hit = new Uint8Array(nx * ny);
  for (const s of segs) {
    const dx = s.x1 - s.x0,
      dy = s.y1 - s.y0,
      len2 = dx * dx + dy * dy;
    const i0 = Math.max(0, Math.floor((Math.min(s.x0, s.x1) - reach - r.x0) / step)),
      i1 = Math.min(nx - 1, Math.ceil((Math.max(s.x0, s.x1) + reach - r.x0) / step));
    const j0 = Math.max(0, Math.floor((Math.min(s.y0, s.y1) - reach - r.y0) / step)),
      j1 = Math.min(ny - 1, Math.ceil((Math.max(s.y0, s.y1) + reach - r.y0) / step));
    for (let j = j0; j <= j1; j++) {
      for (let i = i0; i <= i1; i++) {
        const px = r.x0 + (i + 0.5) * step,
          py = r.y0 + (j + 0.5) * step;
        const t = len2 > 0 ? Math.max(0, Math.min(1, ((px - s.x0) * dx + (py - s.y0) * dy) / len2)) : 0;
        if ((px - s.x0 - t * dx) ** 2 + (py - s.y0 - t * dy) ** 2 <= reach * reach) hit[j * nx + i] = 1;
      }
    }
  }
  let n = 0;
  for (const h of hit) n += h;
  return n / hit.length;
}

/** Filament of segments over what full lines `width` wide at `height` would take for their length. */
function flowShare(segs: ReadonlyArray<Segment & { e: number }>, width: number, height: number): number {
  let e = 0,
    len = 0;
  for (const s of segs) {
    e += s.e;
    len += Math.hypot(s.x1 - s.x0, s.y1 - s.y0);
  }
  return (e * FILAMENT_AREA) / (len * width * height);
}

// a stepped part: a 20 × 20 × 4 mm base at (50..70, 50..70) and a 10 × 20 mm block on its left half up to 8 mm;
// top surfaces: the base's right half at 4 mm, the block's top at 8 mm
const STEPPED = join(box(50, 50, 0, 70, 70, 4), box(50, 50, 0, 60, 70, 8));
const LOW_TOP: Rect = { x0: 60, y0: 50, x1: 70, y1: 70 };
const HIGH_TOP: Rect = { x0: 50, y0: 50, x1: 60, y1: 70 };

test('ironing irons every top surface (top) or only the highest (topmost), after its skin', async () => {
  const off = await slice(STEPPED);
  assert.deepEqual(layersWith(off.g, Feature.Ironing), [], 'no ironing unless asked for');
  const top = await slice(STEPPED, { ironingEnabled: true });
  assert.deepEqual(layersWith(top.g, Feature.Ironing), [4, 8]);
  const topmost = await slice(STEPPED, { ironingEnabled: true, ironingType: 'topmost' });
  assert.deepEqual(layersWith(topmost.g, Feature.Ironing), [8]);
  // on each top surface's layer, the ironing comes after the layer's skin, and stays on the surface: half a
  // line width in from the part's edges, up to the foot of the step at 4 mm
  for (const [z, r, inset] of [
    [4, LOW_TOP, { x0: 0, x1: 0.2, y0: 0.2, y1: 0.2 }],
    [8, HIGH_TOP, { x0: 0.2, x1: 0.2, y0: 0.2, y1: 0.2 }],
  ] as const) {
    const layer = layerAt(top.g, z);
    const skin = segmentsOf(layer, Feature.Skin),
      iron = segmentsOf(layer, Feature.Ironing);
    assert.ok(skin.length > 0 && iron[0].i > skin[skin.length - 1].i, `Z ${z}: ironing after the skin`);
    const ok = (x: number, y: number) =>
      x >= r.x0 + inset.x0 - 0.002 &&
      x <= r.x1 - inset.x1 + 0.002 &&
      y >= r.y0 + inset.y0 - 0.002 &&
      y <= r.y1 - inset.y1 + 0.002;
    for (const s of iron)
      assert.ok(ok(s.x0, s.y0) && ok(s.x1, s.y1), `Z ${z}: (${s.x0}, ${s.y0}) – (${s.x1}, ${s.y1}) off the surface`);
  }
});

test('ironing covers at least 90 % of the top at no more than 20 % flow; the measurement sees a bare top', async () => {
  const { g } = await slice(STEPPED, { ironingEnabled: true, ironingType: 'topmost' });
  const iron = segmentsOf(layerAt(g, 8), Feature.Ironing);
  // the passes are 0.1 mm apart: every point of the surface within half of that (and rounding) of one
  const covered = coverage(iron, HIGH_TOP, 0.06);
  assert.ok(covered >= 0.9, `ironing covers ${(covered * 100).toFixed(1)} % of the top`);
  const flow = flowShare(iron, 0.1, 0.2);
  assert.ok(
    flow <= 0.2 && Math.abs(flow - 0.15) < 0.01,
    `ironing flow ${(flow * 100).toFixed(1)} % of a full 0.1 mm line`,
  );
  // the same measurement on the layer below (no ironing there) and on the skin's own lines (0.4 mm apart)
  assert.equal(coverage(segmentsOf(layerAt(g, 7.8), Feature.Ironing), HIGH_TOP, 0.06), 0);
  assert.ok(
    coverage(segmentsOf(layerAt(g, 8), Feature.Skin), HIGH_TOP, 0.06) < 0.5,
    'skin lines 0.4 mm apart do not pass for ironing',
  );
  // the flow setting sets it
  const strong = await slice(STEPPED, {
    ironingEnabled: true,
    ironingType: 'topmost',
    ironingFlow: 30,
    ironingSpacing: 0.2,
  });
  const f2 = flowShare(segmentsOf(layerAt(strong.g, 8), Feature.Ironing), 0.2, 0.2);
  assert.ok(Math.abs(f2 - 0.3) < 0.02, `flow at 30 %: ${(f2 * 100).toFixed(1)} %`);
});

test('ironing all solid surfaces irons the skin below the top too', async () => {
  const top = await slice(STEPPED, { ironingEnabled: true });
  const all = await slice(STEPPED, { ironingEnabled: true, ironingType: 'all' });
  const layers = layersWith(all.g, Feature.Ironing);
  assert.ok(layers.length > layersWith(top.g, Feature.Ironing).length + 4, `all: ${layers.join(', ')}`);
  assert.ok(layers.includes(0.2) && layers.includes(7.8), 'bottom skin and the top skin under the top are ironed');
});

// a 24 × 24 × 3 mm plate with an 8 mm square hole through its middle (four bars round it)
const FRAME = join(
  box(50, 50, 0, 74, 58, 3),
  box(50, 66, 0, 74, 74, 3),
  box(50, 50, 0, 58, 74, 3),
  box(66, 50, 0, 74, 74, 3),
);

/** The monotonic check on the top layer's skin lines, at whichever of the two skin directions they run. */
function topSkinOrder(g: ParsedGcode): { lines: number; violations: number } {
  const skin = segmentsOf(layerAt(g, 3), Feature.Skin);
  const reports = [45, 135].map((a) => monotonicViolations(skin, a, 0.4, 1));
  return reports[0].lines > reports[1].lines ? reports[0] : reports[1];
}

test('monotonic top skin around a hole never lays a line between two lines already printed', async () => {
  const mono = await slice(FRAME, { topSkinPattern: 'monotonic' });
  const r = topSkinOrder(mono.g);
  assert.ok(r.lines > 40, `${r.lines} skin lines checked`);
  assert.equal(r.violations, 0, `${r.violations} of ${r.lines} lines laid between two printed ones`);
  // ordinary lines (nearest first) do break the rule here: the check can fail
  const lines = topSkinOrder((await slice(FRAME)).g);
  assert.ok(lines.violations > 0, `lines: ${lines.violations} of ${lines.lines}`);
});

/** Runs of connected segments; a run is closed when it ends where it started. */
function runs(segs: readonly Segment[]): Array<{ closed: boolean; length: number }> {
  const out: Array<{ closed: boolean; length: number }> = [];
  let start: Segment | null = null,
    prev: Segment | null = null,
    length = 0;
  const close = () => {
    if (start && prev) out.push({ closed: Math.hypot(prev.x1 - start.x0, prev.y1 - start.y0) < 0.01, length });
  };
  for (const s of segs) {
    if (!prev || Math.hypot(s.x0 - prev.x1, s.y0 - prev.y1) > 0.01) {
      close();
      start = s;
      length = 0;
    }
    length += Math.hypot(s.x1 - s.x0, s.y1 - s.y0);
    prev = s;
  }
  close();
  return out;
}

/** Share of a layer's skin length printed as closed loops. */
function loopShare(layer: GcodeLayer): number {
  const r = runs(segmentsOf(layer, Feature.Skin));
  const total = r.reduce((a, x) => a + x.length, 0);
  return r.filter((x) => x.closed).reduce((a, x) => a + x.length, 0) / total;
}

test('concentric skin is closed loops; where skin is top and bottom at once the top pattern wins', async () => {
  const conc = await slice(FRAME, { bottomSkinPattern: 'concentric' });
  const bottom = layerAt(conc.g, 0.2);
  assert.ok(loopShare(bottom) > 0.9, `bottom skin in loops: ${(loopShare(bottom) * 100).toFixed(0)} %`);
  assert.ok(runs(segmentsOf(bottom, Feature.Skin)).filter((x) => x.closed).length >= 10, 'loop after loop inwards');
  assert.ok(loopShare(layerAt(conc.g, 3)) < 0.5, 'the top skin keeps its lines');
  assert.ok(loopShare(layerAt((await slice(FRAME)).g, 0.2)) < 0.5, 'lines are not loops');
  // a plate 3 layers thick: each layer's skin is both top and bottom skin; the middle one (over the first,
  // under the last) is printed in the top pattern
  const plate = box(50, 50, 0, 70, 70, 0.6);
  const topConc = await slice(plate, { topSkinPattern: 'concentric' });
  assert.ok(loopShare(layerAt(topConc.g, 0.4)) > 0.9, 'top pattern where skin is both');
  const bottomConc = await slice(plate, { bottomSkinPattern: 'concentric' });
  assert.ok(loopShare(layerAt(bottomConc.g, 0.4)) < 0.5, 'not the bottom pattern');
});

test('ironing and the skin patterns give the same bytes every time and with any thread count', async () => {
  const options = {
    ironingEnabled: true,
    ironingType: 'topmost',
    topSkinPattern: 'monotonic',
    bottomSkinPattern: 'concentric',
  };
  const a = await slice(STEPPED, options);
  const b = await slice(STEPPED, options);
  const c = await slice(STEPPED, { ...options, threads: 3 });
  assert.equal(a.gcode, b.gcode);
  assert.equal(a.gcode, c.gcode);
  assert.deepEqual(layersWith(c.g, Feature.Ironing), [8]);
});
