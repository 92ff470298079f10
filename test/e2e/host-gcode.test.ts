/**
 * End to end: arc fitting on the stanford bunny judged by the independent analyser, and the host
 * features (thumbnails, progress, firmware features) in real slices.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { decode as decodePng } from 'fast-png';
import { Slicer, prepareModel } from '#strata/api/slicer.js';
import { analyzePrint } from '../../tools/analysis/checks.js';
import { gcodeToString } from '#strata/gcode/writer.js';
import { VERSION } from '#strata/pipeline/run.js';
import { fitPlanArcs } from '#strata/plan/arc-fit.js';
import { estimatePlan } from '#strata/plan/estimate.js';
import { decodeQoi } from '#strata/thumbnail/qoi.js';
import { analysisProfile, modelsAvailable, readModel } from './models.js';

const skip = !modelsAvailable() && !process.env.CI && 'shared models not found';

test('stanford bunny: arcs cut the G-code lines by ≥ 30 % with the same footprint and filament', {
  skip,
  timeout: 600_000,
}, async () => {
  // one slice; the arc pass (the last pass over the plan, as in the pipeline) then runs on a copy of its plan
  const bytes = readModel('stanford-bunny.stl');
  const slicer = new Slicer({ threads: 1 });
  const chunks: string[] = [];
  const { plan } = await slicer.slicePlan(bytes, {}, (c) => chunks.push(c));
  const cfg = slicer.config;
  const arcPlan = structuredClone(plan);
  fitPlanArcs(arcPlan, cfg.arcTolerance);
  const analyse = (gcode: string) => ({
    gcode,
    report: analyzePrint(prepareModel(bytes, cfg).mesh, gcode, analysisProfile(cfg)),
  });
  const lines = analyse(chunks.join(''));
  const arcs = analyse(
    gcodeToString(arcPlan, { ...cfg.settings, arcFitting: true }, estimatePlan(arcPlan, cfg), {
      generator: `Strata ${VERSION}`,
      printerId: cfg.printerId,
      filamentId: cfg.filamentId,
    }),
  );
  const count = (g: string) => g.split('\n').length;
  const reduction = 1 - count(arcs.gcode) / count(lines.gcode);
  assert.ok(reduction >= 0.3, `lines ${count(lines.gcode)} → ${count(arcs.gcode)}: ${(reduction * 100).toFixed(1)} %`);
  assert.ok((arcs.gcode.match(/^G[23] /gm) ?? []).length > 10000, 'arcs written');
  const filament = (g: string) => Number(/;Filament used: ([\d.]+)m/.exec(g)![1]);
  assert.ok(
    Math.abs(filament(arcs.gcode) / filament(lines.gcode) - 1) <= 0.001,
    `filament ${filament(lines.gcode)} → ${filament(arcs.gcode)} m`,
  );
  const a = lines.report.summary,
    b = arcs.report.summary;
  assert.ok(Math.abs(b.e.extruded / a.e.extruded - 1) <= 0.001, `extruded ${a.e.extruded} → ${b.e.extruded}`);
  assert.ok(
    Math.abs(b.walls.coverage! - a.walls.coverage!) <= 0.001,
    `walls ${a.walls.coverage} → ${b.walls.coverage}`,
  );
  assert.ok(
    Math.abs(b.skin.top.coverage! - a.skin.top.coverage!) <= 0.002,
    `top skin ${a.skin.top.coverage} → ${b.skin.top.coverage}`,
  );
  assert.ok(
    Math.abs(b.skin.bottom.coverage! - a.skin.bottom.coverage!) <= 0.002,
    `bottom skin ${a.skin.bottom.coverage} → ${b.skin.bottom.coverage}`,
  );
  assert.ok(
    Math.abs(b.infill.density! - a.infill.density!) <= 0.002,
    `density ${a.infill.density} → ${b.infill.density}`,
  );
  assert.ok(b.outside.p99Mm <= 0.1 && b.outside.emptySectionLayers.length === 0, 'nothing outside the model');
  assert.equal(b.e.balance.unbalanced, 0);
  assert.equal(b.layerCount, a.layerCount);
});

test('a real slice carries M73 progress, thumbnails that decode, and firmware features', {
  skip,
  timeout: 120_000,
}, async () => {
  const slicer = new Slicer({
    threads: 1,
    thumbnails: '16x16/QOI,300x300/PNG',
    firmwareRetraction: true,
    pressureAdvance: 0.04,
    gcodeFlavor: 'klipper',
    arcFitting: true,
  });
  const { gcode } = await slicer.slice(readModel('spot.stl'));
  const blocks = [...gcode.matchAll(/^; (thumbnail(?:_QOI)?) begin (\d+)x(\d+) (\d+)\n((?:; .*\n)+?); \1 end$/gm)];
  assert.equal(blocks.length, 2);
  const bytes = (b: RegExpMatchArray) =>
    new Uint8Array(
      Buffer.from(
        b[5]!
          .split('\n')
          .map((l) => l.slice(2))
          .join(''),
        'base64',
      ),
    );
  const qoi = decodeQoi(bytes(blocks[0]!));
  assert.deepEqual([qoi.width, qoi.height], [16, 16]);
  const png = decodePng(bytes(blocks[1]!));
  assert.deepEqual([png.width, png.height], [300, 300]);
  let opaque = 0;
  for (let i = 3; i < png.data.length; i += 4) if (png.data[i] === 255) opaque++;
  assert.ok(opaque > 300 * 300 * 0.1, `the model fills ${opaque} pixels`);
  const p = [...gcode.matchAll(/^M73 P(\d+) R(\d+)$/gm)].map((m) => [+m[1]!, +m[2]!]);
  assert.ok(p.length > 10);
  for (let i = 1; i < p.length; i++) assert.ok(p[i]![0]! >= p[i - 1]![0]! && p[i]![1]! <= p[i - 1]![1]!);
  assert.deepEqual(p[p.length - 1], [100, 0]);
  assert.match(gcode, /^SET_PRESSURE_ADVANCE ADVANCE=0\.04$/m);
  assert.match(gcode, /^G10$/m);
  assert.match(gcode, /^G[23] /m);
});

/** A closed box from (x0,y0,0) to (x1,y1,h), outward-facing. */
function box(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  h: number,
): { positions: Float32Array; indices: Uint32Array } {
  const v = [
    [x0, y0, 0],
    [x1, y0, 0],
    [x1, y1, 0],
    [x0, y1, 0],
    [x0, y0, h],
    [x1, y0, h],
    [x1, y1, h],
    [x0, y1, h],
  ].flat();
  const f = [
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ];
  return { positions: new Float32Array(v), indices: new Uint32Array(f) };
}

/** Whether (x, y) lies inside the convex counter-clockwise polygon, within `tol` mm. */
function insideConvex(x: number, y: number, poly: number[][], tol: number): boolean {
  for (let i = 0; i < poly.length; i++) {
    const [ax, ay] = poly[i]!,
      [bx, by] = poly[(i + 1) % poly.length]!;
    const len = Math.hypot(bx! - ax!, by! - ay!);
    if (((bx! - ax!) * (y - ay!) - (by! - ay!) * (x - ax!)) / len < -tol) return false;
  }
  return true;
}

test('two objects on a Klipper printer: defined, labelled per layer, every extrusion inside its own footprint; cancelling one keeps E balanced', {
  timeout: 120_000,
}, async () => {
  const slicer = new Slicer({ threads: 1, printer: 'voron-2.4-350', arcFitting: true });
  const { gcode, stats } = await slicer.slice([
    { name: 'left cube', ...box(0, 0, 15, 15, 6) },
    { name: 'right cube', ...box(40, 0, 55, 15, 6) },
  ]);
  const defs = [...gcode.matchAll(/^EXCLUDE_OBJECT_DEFINE NAME=(\S+) CENTER=(\S+) POLYGON=(\S+)$/gm)];
  assert.deepEqual(
    defs.map((d) => d[1]),
    ['left_cube', 'right_cube'],
  );
  const polygons = new Map(defs.map((d) => [d[1]!, JSON.parse(d[3]!) as number[][]]));
  let open: string | null = null;
  let x = 0,
    y = 0;
  let blocks = 0,
    inside = 0,
    outside = 0;
  for (const l of gcode.split('\n')) {
    const s = /^EXCLUDE_OBJECT_START NAME=(\S+)$/.exec(l);
    if (s) {
      assert.equal(open, null);
      open = s[1]!;
      blocks++;
      continue;
    }
    const e = /^EXCLUDE_OBJECT_END NAME=(\S+)$/.exec(l);
    if (e) {
      assert.equal(e[1], open);
      open = null;
      continue;
    }
    if (l.startsWith(';LAYER:')) assert.equal(open, null, 'no block across a layer change');
    if (!/^G[0-3] /.test(l)) continue;
    const mx = /X(-?[\d.]+)/.exec(l),
      my = /Y(-?[\d.]+)/.exec(l);
    if (mx) x = +mx[1]!;
    if (my) y = +my[1]!;
    if (!/^G[123] .*E\d/.test(l) || (!mx && !my)) continue;
    if (open) {
      assert.ok(insideConvex(x, y, polygons.get(open)!, 0.01), `${open}: (${x}, ${y}) outside its footprint`);
      inside++;
    } else outside++;
  }
  assert.equal(open, null);
  assert.equal(blocks, 2 * stats.layers, 'both objects on every layer');
  assert.ok(inside > 100 && outside > 0, 'objects labelled, the skirt not');
  // cancel the left cube as Klipper would: its blocks are skipped (relative E on this printer)
  assert.match(gcode, /^M83\b/m);
  const cancelled = gcode.replace(
    /^EXCLUDE_OBJECT_START NAME=left_cube\n[\s\S]*?^EXCLUDE_OBJECT_END NAME=left_cube\n/gm,
    '',
  );
  const { parseGcode } = await import('../../tools/analysis/gcode-parse.js');
  const before = parseGcode(gcode),
    after = parseGcode(cancelled);
  assert.equal(after.balance.unbalanced, 0, 'every retraction still primed before extruding');
  assert.ok(after.e.extruded < before.e.extruded * 0.7);
});
