/**
 * Overhangs that print clean, end to end, read back from the G-code (analysis/gcode-parse.ts): walls slowed by
 * how much of their line hangs over nothing (dynamic overhang speeds, four steps), the overhang fan on those
 * runs, and extra walls filling a cantilever's inside from its anchor (extraPerimetersOnOverhangs). The parts
 * are made here: blocks leaning at 35°, 50°, 60° and 70° from vertical, whose leaning side has tan(angle) / 2
 * of the outer wall's 0.4 mm line over nothing at 0.2 mm layers (0.35, 0.60, 0.87 and 1.37: one step each),
 * and a slab reaching 12 mm out from a pillar.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseGcode } from '../../tools/analysis/gcode-parse.js';
import { FEATURE_NAMES } from '../../tools/analysis/feature-names.js';
import { Slicer } from '#strata/api/slicer.js';
import type { SliceOptions } from '#strata/settings/schema.js';
import { box, join, type Arrays } from './test-meshes.js';

/** A mesh sheared along +x: each point moved by its height times tan(degrees). */
function leaning(m: Arrays, degrees: number): Arrays {
  const positions = m.positions.slice();
  const k = Math.tan((degrees * Math.PI) / 180);
  for (let i = 0; i < positions.length; i += 3) positions[i] += positions[i + 2] * k;
  return { positions, indices: m.indices };
}

const ANGLES = [35, 50, 60, 70];
const HEIGHT = 4;
/** Block k stands on x 40..46, y 40 + 12k .. 48 + 12k and leans in +x at ANGLES[k]. */
const LEANING = join(...ANGLES.map((deg, k) => leaning(box(40, 40 + 12 * k, 0, 46, 48 + 12 * k, HEIGHT), deg)));
const SPEEDS = {
  perimeterSpeed: 30,
  overhangSpeed25: 24,
  overhangSpeed50: 18,
  overhangSpeed75: 12,
  overhangWallSpeed: 6,
};
const COMMON: SliceOptions = { center: false, minLayerTime: 0, threads: 1 };

async function slice(mesh: Arrays, options: SliceOptions): Promise<string> {
  const { gcode } = await new Slicer({ ...COMMON, ...options }).slice(mesh);
  return gcode;
}

/**
 * Feed rates (mm/s) of the outer wall along each block's leaning side, by block: segments running along y
 * within half a line of where the side's wall runs on their layer, above the first layers.
 */
function leaningSideSpeeds(gcode: string): number[][] {
  const out: number[][] = ANGLES.map(() => []);
  for (const layer of parseGcode(gcode).layers) {
    if (layer.z < 0.6 || layer.z > HEIGHT - 0.2) continue;
    const e = layer.extrusions;
    for (let i = 0; i < e.count; i++) {
      if (
        FEATURE_NAMES[e.feature[i]] !== 'WALL-OUTER' ||
        Math.abs(e.x1[i] - e.x0[i]) > 0.01 ||
        Math.abs(e.y1[i] - e.y0[i]) < 0.5
      )
        continue;
      ANGLES.forEach((deg, k) => {
        const y0 = 40 + 12 * k;
        const side = 46 + (layer.z - 0.1) * Math.tan((deg * Math.PI) / 180) - 0.2;
        const mid = (e.y0[i] + e.y1[i]) / 2;
        const inBlock = mid > y0 + 1 && mid < y0 + 7;
        if (inBlock && Math.abs(e.x0[i] - side) < 0.2) out[k].push(Math.round(e.feedrate[i] / 6) / 10);
      });
    }
  }
  return out;
}

test('dynamic overhang speeds: the outer wall of a side leaning further out prints slower, in the four steps', {
  timeout: 120_000,
}, async () => {
  const graded = leaningSideSpeeds(await slice(LEANING, { ...SPEEDS, dynamicOverhangSpeeds: true }));
  const plain = leaningSideSpeeds(await slice(LEANING, SPEEDS));
  const expected = [SPEEDS.overhangSpeed25, SPEEDS.overhangSpeed50, SPEEDS.overhangSpeed75, SPEEDS.overhangWallSpeed];
  ANGLES.forEach((deg, k) => {
    assert.ok(
      graded[k].length >= 10 && plain[k].length >= 10,
      `${deg}°: the leaning side's wall is found (${graded[k].length}, ${plain[k].length} segments)`,
    );
    assert.deepEqual([...new Set(graded[k])], [expected[k]], `${deg}° with dynamic speeds`);
    // without them only the side wholly over nothing is slowed
    assert.deepEqual(
      [...new Set(plain[k])],
      [deg === 70 ? SPEEDS.overhangWallSpeed : SPEEDS.perimeterSpeed],
      `${deg}° without`,
    );
  });
});

/** Each outer-wall extrusion's feed rate (mm/s) and the part-cooling fan (0-255) it prints with, past the first layer. */
function wallFans(gcode: string): { speed: number; fan: number }[] {
  const out: { speed: number; fan: number }[] = [];
  let fan = 0,
    feed = 0,
    type = '',
    layer = -1;
  for (const line of gcode.split('\n')) {
    if (line.startsWith(';LAYER:')) layer = Number(line.slice(7));
    else if (line.startsWith(';TYPE:')) type = line.slice(6);
    else if (line.startsWith('M106')) fan = Number(/S(\d+)/.exec(line)?.[1] ?? 255);
    else if (line.startsWith('M107')) fan = 0;
    else if (/^G1 /.test(line)) {
      const f = /F([\d.]+)/.exec(line);
      if (f) feed = Number(f[1]) / 60;
      if (layer > 0 && type === 'WALL-OUTER' && / E/.test(line) && / [XY]/.test(line))
        out.push({ speed: Math.round(feed * 10) / 10, fan });
    }
  }
  return out;
}

test('overhang fan: the fan goes to overhangFanSpeed on the overhanging wall runs and back after them', {
  timeout: 120_000,
}, async () => {
  const on = wallFans(
    await slice(LEANING, { ...SPEEDS, dynamicOverhangSpeeds: true, overhangFanSpeed: 40, fanSpeed: 100 }),
  );
  const slowed = on.filter((s) => s.speed < SPEEDS.perimeterSpeed);
  assert.ok(slowed.length > 100, `${slowed.length} overhanging wall moves`);
  assert.ok(
    slowed.every((s) => s.fan === 102),
    'every overhanging run at 40 % (M106 S102)',
  );
  const full = on.filter((s) => s.speed === SPEEDS.perimeterSpeed);
  assert.ok(
    full.length > 100 && full.filter((s) => s.fan === 255).length > 0.95 * full.length,
    'the rest of the outer wall keeps the layer fan',
  );
  // without the setting the overhangs keep the layer's fan
  const off = await slice(LEANING, { ...SPEEDS, dynamicOverhangSpeeds: true, fanSpeed: 100 });
  assert.ok(!/^M106 S102$/m.test(off));
  assert.ok(
    wallFans(off)
      .filter((s) => s.speed < SPEEDS.perimeterSpeed)
      .every((s) => s.fan === 255),
  );
});

/** A pillar 8 mm long and a slab on it reaching 12 mm further out: its first layer hangs over nothing beyond x 48. */
const CANTILEVER = join(box(40, 40, 0, 48, 46, 6), box(40, 40, 6, 60, 46, 8));

/** Extrusion length (mm) by feature inside the box [x0, y0, x1, y1] on the layer printed at z, and where the layer's first extrusion is. */
function layerFeatures(
  gcode: string,
  z: number,
  [x0, y0, x1, y1]: readonly number[],
): { inside: Map<string, number>; first: { x: number; y: number } } {
  const layer = parseGcode(gcode).layers.find((l) => Math.abs(l.z - z) < 0.01)!;
  const e = layer.extrusions;
  const inside = new Map<string, number>();
  for (let i = 0; i < e.count; i++) {
    const f = FEATURE_NAMES[e.feature[i]];
    const mx = (e.x0[i] + e.x1[i]) / 2,
      my = (e.y0[i] + e.y1[i]) / 2;
    if (mx > x0 && mx < x1 && my > y0 && my < y1)
      inside.set(f, (inside.get(f) ?? 0) + Math.hypot(e.x1[i] - e.x0[i], e.y1[i] - e.y0[i]));
  }
  return { inside, first: { x: (e.x0[0] + e.x1[0]) / 2, y: (e.y0[0] + e.y1[0]) / 2 } };
}

test("extra perimeters on overhangs: a cantilever's inside is filled with walls from its anchor, not bridged, and only with the setting", {
  timeout: 120_000,
}, async () => {
  // the inside of the slab's overhanging part, clear of its own walls (two lines, 0.8 mm)
  const over = [49, 41, 59, 45];
  const on = layerFeatures(await slice(CANTILEVER, { extraPerimetersOnOverhangs: true }), 6.2, over);
  const off = layerFeatures(await slice(CANTILEVER, {}), 6.2, over);
  const walls = on.inside.get('WALL-INNER') ?? 0;
  // 4 mm across at 0.4 mm a line: about ten lines 10 mm long
  assert.ok(walls > 60, `extra walls over the cantilever: ${walls.toFixed(1)} mm`);
  assert.ok((on.inside.get('SKIN') ?? 0) < 2, `no skin or bridge left there: ${on.inside.get('SKIN')}`);
  assert.ok((off.inside.get('WALL-INNER') ?? 0) < 1, 'without the setting: no walls inside the slab');
  assert.ok((off.inside.get('SKIN') ?? 0) > 60, 'without the setting: bridge lines');
  // they print first, ahead of the island's walls (which run round the slab 0.2 and 0.6 mm in): the layer starts inside them
  const insideWalls = (p: { x: number; y: number }) => p.x > 40.8 && p.x < 59.2 && p.y > 40.8 && p.y < 45.2;
  assert.ok(insideWalls(on.first), `the first extrusion at ${JSON.stringify(on.first)}`);
  assert.ok(!insideWalls(off.first), 'without the setting the layer starts with a wall');
});
