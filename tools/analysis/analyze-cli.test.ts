import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Mesh } from '#strata/mesh/types.js';
import { boxMesh, mergeMeshes, rectLines } from './synthetic-print.js';
import { toyGcode } from './toy-slicer.js';

const CLI = fileURLToPath(new URL('./analyze-cli.js', import.meta.url));

function asciiStl(mesh: Mesh): string {
  const p = mesh.positions;
  const out = ['solid t'];
  for (let t = 0; t < mesh.indices.length; t += 3) {
    out.push(' facet normal 0 0 0', '  outer loop');
    for (let v = 0; v < 3; v++) {
      const k = 3 * mesh.indices[t + v]!;
      out.push(`   vertex ${p[k]} ${p[k + 1]} ${p[k + 2]}`);
    }
    out.push('  endloop', ' endfacet');
  }
  out.push('endsolid t');
  return out.join('\n');
}

test('the developer command centres the model on the print and reports support', () => {
  // The model file is centred on the origin; the print is centred on (55, 60).
  const file = mergeMeshes(boxMesh(-5, -10, 0, 5, 10, 4), boxMesh(-15, -10, 4, 15, 10, 6));
  const placed = mergeMeshes(boxMesh(50, 50, 0, 60, 70, 4), boxMesh(40, 50, 4, 70, 70, 6));
  const o = { layerHeight: 0.2, firstLayerHeight: 0.2, lineWidth: 0.4, filamentDiameter: 1.75, infillSpacing: 4 };
  const support = (i: number, _z: number, h: number) =>
    i <= 18
      ? [
          [40, 50, 49.4, 70],
          [60.6, 50, 70, 70],
        ].flatMap((r) => rectLines(r as [number, number, number, number], 0.4, h, 0.4, 1.75, 'SUPPORT'))
      : [];
  const dir = mkdtempSync(join(tmpdir(), 'analyze-cli-'));
  try {
    writeFileSync(join(dir, 't.stl'), asciiStl(file));
    writeFileSync(join(dir, 't.gcode'), toyGcode(placed, { ...o, skinLayers: 4, extra: support }));
    const text = spawnSync(process.execPath, [CLI, join(dir, 't.stl'), join(dir, 't.gcode'), '--layers'], {
      encoding: 'utf8',
    });
    assert.equal(text.status, 0, text.stderr);
    assert.match(text.stdout, /walls: outline coverage 100\.0 %/);
    assert.match(text.stdout, /support: overhang \(50° from vertical\) 3\d\d\.\d mm², supported (9[5-9]|100)\.\d %/);
    assert.match(text.stdout, /top Z gap: median 0\.20 mm \(1 layer\)/);
    assert.match(text.stdout, /^20 4\.200 part: /m, 'per-layer support lines');
    const json = spawnSync(
      process.execPath,
      [CLI, join(dir, 't.stl'), join(dir, 't.gcode'), '--json', '--overhang-angle', '60'],
      { encoding: 'utf8' },
    );
    assert.equal(json.status, 0, json.stderr);
    const summary = JSON.parse(json.stdout).summary;
    assert.equal(summary.support.overhangAngleDeg, 60);
    assert.ok(summary.support.overhangSupported > 0.95, JSON.stringify(summary.support));
    // Left where the file puts it, the model misses the print.
    const args = [CLI, join(dir, 't.stl'), join(dir, 't.gcode'), '--center', 'none', '--json'];
    const none = spawnSync(process.execPath, args, { encoding: 'utf8' });
    const missed = JSON.parse(none.stdout).summary;
    assert.ok(missed.walls.coverage < 0.5 && missed.outside.maxMm > 20, JSON.stringify(missed.outside));
    const bad = spawnSync(process.execPath, [CLI, join(dir, 't.stl')], { encoding: 'utf8' });
    assert.notEqual(bad.status, 0);
    assert.match(bad.stderr, /^error: usage/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
