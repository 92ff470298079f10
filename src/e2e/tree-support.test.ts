/** Tree support end to end on SupportTest.stl: support is printed, none of it inside the part, less of it than normal support, the same G-code on any thread count. */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Slicer, prepareModel } from '../api/slicer.js';
import { Feature } from '../analysis/feature-names.js';
import { parseGcode } from '../analysis/gcode-parse.js';
import type { GcodeLayer, ParsedGcode } from '../analysis/gcode-types.js';
import { countSet, gridAround } from '../analysis/grid.js';
import { beadWidth, filamentArea, stampCapsule } from '../analysis/raster.js';
import { meshSection, rasterizeSection } from '../analysis/section.js';
import type { Mesh } from '../mesh/types.js';
import { modelsAvailable, readModel } from './models.js';

const skip = !modelsAvailable() && process.env.CI !== 'true' && 'shared models not found';
const FILAMENT_MM2 = filamentArea(1.75);
/** Raster cell for the inside-the-part measure, mm. */
const CELL_MM = 0.05;

function supportSegments(layer: GcodeLayer): number[] {
  const t = layer.extrusions;
  const out: number[] = [];
  for (let i = 0; i < t.count; i++) if (t.feature[i] === Feature.Support && t.e[i]! > 0) out.push(i);
  return out;
}

/** Extruded support volume, mm³. */
function supportVolume(g: ParsedGcode): number {
  let v = 0;
  for (const l of g.layers) for (const i of supportSegments(l)) v += l.extrusions.e[i]! * FILAMENT_MM2;
  return v;
}

/** Support beads (as wide as their extruded volume makes them) inside the model's sections, summed over layers, mm². */
function supportInsidePart(mesh: Mesh, g: ParsedGcode): number {
  let total = 0;
  for (const l of g.layers) {
    const segs = supportSegments(l);
    if (segs.length === 0) continue;
    const t = l.extrusions;
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const i of segs) {
      x0 = Math.min(x0, t.x0[i]!, t.x1[i]!);
      x1 = Math.max(x1, t.x0[i]!, t.x1[i]!);
      y0 = Math.min(y0, t.y0[i]!, t.y1[i]!);
      y1 = Math.max(y1, t.y0[i]!, t.y1[i]!);
    }
    const grid = gridAround(x0, y0, x1, y1, CELL_MM, 1);
    const beads = new Uint8Array(grid.cols * grid.rows);
    for (const i of segs) {
      const len = Math.hypot(t.x1[i]! - t.x0[i]!, t.y1[i]! - t.y0[i]!);
      const w = Math.min(1.2, beadWidth(t.e[i]!, len, l.thickness, FILAMENT_MM2));
      stampCapsule(beads, grid, t.x0[i]!, t.y0[i]!, t.x1[i]!, t.y1[i]!, w / 2);
    }
    const part = rasterizeSection(meshSection(mesh, l.z - l.thickness / 2), grid);
    for (let k = 0; k < beads.length; k++) beads[k] &= part[k]!;
    total += countSet(beads) * CELL_MM * CELL_MM;
  }
  return total;
}

test('SupportTest.stl with tree support: support is printed, never inside the part, with less material than normal support, the same on 1 and 2 threads', { skip, timeout: 600_000 }, async () => {
  const bytes = readModel('SupportTest.stl');
  const treeSlicer = new Slicer({ threads: 1, supportEnabled: true, supportType: 'tree' });
  const tree = await treeSlicer.slice(bytes);
  const two = await new Slicer({ threads: 2, supportEnabled: true, supportType: 'tree' }).slice(bytes);
  assert.ok(tree.gcode === two.gcode, 'tree support G-code differs between 1 and 2 threads');
  assert.match(tree.gcode, /;TYPE:SUPPORT\n/);
  assert.match(tree.gcode, /;TYPE:SUPPORT-INTERFACE\n/);
  const parsed = parseGcode(tree.gcode);
  const mesh = prepareModel(bytes, treeSlicer.config).mesh;
  const inside = supportInsidePart(mesh, parsed);
  assert.ok(inside <= 1, `${inside.toFixed(2)} mm² of support inside the part`);
  const normal = parseGcode((await new Slicer({ threads: 2, supportEnabled: true, supportType: 'normal' }).slice(bytes)).gcode);
  const vt = supportVolume(parsed), vn = supportVolume(normal);
  assert.ok(vt > 0.1 * vn && vt <= 0.75 * vn, `tree support ${vt.toFixed(0)} mm³, normal ${vn.toFixed(0)} mm³`);
});
