/**
 * Bridges, end to end, read back from the G-code: a span between two pillars made here, whose bridge lines must
 * reach bridgeAnchor onto both pillars, lie bridgeSpacing apart at most and carry bridgeFlow of a round bead,
 * with nothing but bridge lines (and the walls) over the gap; and BridgeTest's bridge layers covered as
 * PrusaSlicer covers them, by the independent analyser.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join as joinPath } from 'node:path';
import { analyzePrint } from '../../tools/analysis/checks.js';
import { prepareModel, Slicer } from '#strata/api/slicer.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { MODELS_DIR, modelsAvailable } from './models-dir.js';
import { box, join } from './test-meshes.js';

/** Two pillars 8 mm wide, 10 mm apart (x 48..58), and a 2 mm slab across them from z 6: its first layer bridges the gap. */
const SPAN = join(box(40, 40, 0, 48, 50, 6), box(58, 40, 0, 66, 50, 6), box(40, 40, 6, 66, 50, 8));
const GAP = [48, 58];
const COMMON: SliceOptions = { center: false, minLayerTime: 0, threads: 1 };

interface Move {
  type: string;
  z: number;
  x0: number;
  y0: number;
  x1: number;
  y1: number;
  e: number;
}

/** Every extruding move of the G-code (absolute or relative E), with its feature and Z. */
function moves(gcode: string): Move[] {
  const out: Move[] = [];
  let x = 0,
    y = 0,
    z = 0,
    e = 0,
    relative = false,
    type = '';
  for (const line of gcode.split('\n')) {
    if (line.startsWith(';TYPE:')) type = line.slice(6);
    else if (line.startsWith('M83')) relative = true;
    else if (line.startsWith('M82')) relative = false;
    else if (line.startsWith('G92')) {
      const m = /E([-\d.]+)/.exec(line);
      if (m) e = Number(m[1]);
    } else if (/^G[01] /.test(line)) {
      const get = (k: string) => {
        const m = new RegExp(` ${k}([-\\d.]+)`).exec(line.split(';')[0]);
        return m ? Number(m[1]) : null;
      };
      const nx = get('X') ?? x,
        ny = get('Y') ?? y,
        nz = get('Z') ?? z,
        ne = get('E');
      const de = ne === null ? 0 : relative ? ne : ne - e;
      if (ne !== null && !relative) e = ne;
      if (de > 0 && (nx !== x || ny !== y)) out.push({ type, z: nz, x0: x, y0: y, x1: nx, y1: ny, e: de });
      x = nx;
      y = ny;
      z = nz;
    }
  }
  return out;
}

test('a bridge between two pillars: anchored onto both, its own spacing and flow, nothing thin over the gap', {
  timeout: 120_000,
}, async () => {
  const options: SliceOptions = { ...COMMON, bridgeAnchor: 2, bridgeSpacing: 0.5, bridgeFlow: 90 };
  const { gcode } = await new Slicer(options).slice(SPAN);
  const layer = moves(gcode).filter((m) => Math.abs(m.z - 6.2) < 0.01);
  const bridge = layer.filter((m) => m.type === 'BRIDGE');
  // the lines across the gap (links between them run along y at their ends)
  const lines = bridge.filter((m) => Math.abs(m.x1 - m.x0) > 5);
  assert.ok(lines.length >= 10, `${lines.length} bridge lines`);
  for (const l of lines) {
    const lo = Math.min(l.x0, l.x1),
      hi = Math.max(l.x0, l.x1);
    assert.ok(lo <= GAP[0] - 1 && hi >= GAP[1] + 1, `a bridge line from x ${lo} to ${hi} rests ≥ 1 mm on both pillars`);
  }
  // anchored about bridgeAnchor: no line ends much more than 2 mm onto a pillar
  const reach = Math.max(...lines.map((l) => Math.max(GAP[0] - Math.min(l.x0, l.x1), Math.max(l.x0, l.x1) - GAP[1])));
  assert.ok(reach < 2.5, `lines reach ${reach} mm onto the pillars`);
  // spread evenly across the slab, at most bridgeSpacing apart
  const ys = [...new Set(lines.map((l) => Math.round(((l.y0 + l.y1) / 2) * 100) / 100))].sort((a, b) => a - b);
  const gaps = ys.slice(1).map((y, k) => y - ys[k]);
  assert.ok(
    gaps.every((g) => g <= 0.5 + 0.01 && g >= 0.4),
    `line spacing ${gaps.map((g) => g.toFixed(3)).join(' ')}`,
  );
  // flow: bridgeFlow of a round bead one nozzle (0.4 mm) across, over 1.75 mm filament
  const expected = (0.9 * Math.PI * 0.2 * 0.2) / (Math.PI * 0.875 * 0.875);
  for (const l of lines) {
    const perMm = l.e / Math.hypot(l.x1 - l.x0, l.y1 - l.y0);
    assert.ok(Math.abs(perMm - expected) < 0.01 * expected, `E per mm ${perMm} (expected ${expected})`);
  }
  // over the gap, away from the slab's outline, only bridge lines (and their links) print
  const inGap = layer.filter((m) => {
    const mx = (m.x0 + m.x1) / 2,
      my = (m.y0 + m.y1) / 2;
    return mx > GAP[0] + 0.5 && mx < GAP[1] - 0.5 && my > 41 && my < 49;
  });
  const other = inGap.filter((m) => m.type !== 'BRIDGE');
  assert.deepEqual(
    other.map((m) => `${m.type} ${m.x0},${m.y0} → ${m.x1},${m.y1}`),
    [],
    'nothing but bridge lines over the gap',
  );
  // without anchors the lines stop where the air ends
  const bare = moves((await new Slicer({ ...options, bridgeAnchor: 0 }).slice(SPAN)).gcode).filter(
    (m) => Math.abs(m.z - 6.2) < 0.01 && m.type === 'BRIDGE' && Math.abs(m.x1 - m.x0) > 5,
  );
  assert.ok(
    bare.length > 0 && bare.every((l) => Math.min(l.x0, l.x1) > GAP[0] - 0.5),
    'bridgeAnchor 0: lines end at the gap',
  );
});

test('BridgeTest: every bridge layer as covered as PrusaSlicer 2.5 covers it, nothing outside the part', {
  skip: !modelsAvailable(),
  timeout: 300_000,
}, async () => {
  const bytes = readFileSync(joinPath(MODELS_DIR, 'BridgeTest.stl'));
  const slicer = new Slicer({ threads: 1 });
  const { gcode } = await slicer.slice(bytes);
  const report = analyzePrint(prepareModel(bytes, slicer.config).mesh, gcode, {
    layerHeight: 0.2,
    firstLayerHeight: 0.2,
    lineWidth: 0.4,
    filamentDiameter: 1.75,
  });
  // PrusaSlicer 2.5 (layer 0.2, 2 perimeters), measured with this analyser: bottom skin of each bridge layer 100.0 % covered
  const PRUSA = 0.999;
  const bridgeLayers = report.layers.filter((l) => l.index % 10 === 5 && l.index < 100);
  assert.equal(bridgeLayers.length, 10);
  for (const l of bridgeLayers)
    assert.ok((l.bottomSkin.coverage ?? 0) >= PRUSA, `layer ${l.index}: bottom skin ${l.bottomSkin.coverage}`);
  assert.ok(report.summary.outside.maxMm < 0.05, `outside ${report.summary.outside.maxMm} mm`);
  assert.ok((report.summary.walls.coverage ?? 0) > 0.99, `walls ${report.summary.walls.coverage}`);
});
