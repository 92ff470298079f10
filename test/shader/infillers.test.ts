import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { ExPolygon, Polyline } from '#strata/geometry/types.js';
import { compileShader } from '#strata/shader/shader.js';
import { shaderPathsByPass } from '#strata/shader/paths.js';
import { shippedInfillersDir } from '#strata/shader/node-folder.js';
import { infillerFromImage } from '#strata/shader/infiller.js';
import { imageLabelFn } from '#strata/shader/image.js';
import { polylineLength } from '#strata/shader/polyline-tools.js';

const SHADERS = ['voronoi-foam', 'tpms-gyroid', 'tpms-schwarz-p', 'tpms-schwarz-d', 'checker', 'hexagon-grid'];
const SQUARE: ExPolygon[] = [
  {
    outer: [
      { x: 0, y: 0 },
      { x: 20000, y: 0 },
      { x: 20000, y: 20000 },
      { x: 0, y: 20000 },
    ],
    holes: [],
  },
];
/** Quarter of a 0.4 mm line, mm. */
const QUARTER = 0.1;

/** Length-weighted share of the paths whose two sides (±offset mm along the normal) have different labels. */
export function boundaryShare(
  paths: readonly Polyline[],
  label: (x: number, y: number) => number,
  offset: number,
): number {
  let good = 0;
  let total = 0;
  for (const p of paths) {
    for (let i = 1; i < p.length; i++) {
      const ax = p[i - 1].x / 1000;
      const ay = p[i - 1].y / 1000;
      const bx = p[i].x / 1000;
      const by = p[i].y / 1000;
      const len = Math.hypot(bx - ax, by - ay);
      if (len === 0) continue;
      const nx = -(by - ay) / len;
      const ny = (bx - ax) / len;
      const n = Math.max(1, Math.ceil(len / 0.02));
      for (let k = 0; k < n; k++) {
        const t = (k + 0.5) / n;
        const x = ax + (bx - ax) * t;
        const y = ay + (by - ay) * t;
        total += len / n;
        if (label(x + nx * offset, y + ny * offset) !== label(x - nx * offset, y - ny * offset)) good += len / n;
      }
    }
  }
  return total === 0 ? 0 : good / total;
}

function totalLength(paths: readonly Polyline[]): number {
  return paths.reduce((s, p) => s + polylineLength(p), 0) / 1000;
}

function inside(paths: readonly Polyline[], minX: number, minY: number, maxX: number, maxY: number): boolean {
  return paths.every((p) => p.every((q) => q.x >= minX - 1 && q.x <= maxX + 1 && q.y >= minY - 1 && q.y <= maxY + 1));
}

for (const name of SHADERS) {
  test(`shipped infiller ${name}: compiles, paths lie on cell boundaries, density changes them`, {
    timeout: 120_000,
  }, () => {
    const src = readFileSync(join(shippedInfillersDir(), name, 'shader.glsl'), 'utf8');
    const shader = compileShader(src, { fileName: `${name}/shader.glsl` });
    assert.equal(shader.warnings.length, 0, shader.warnings.join('; '));
    assert.ok(shader.usesDensity, `${name} must call density()`);
    const inst = shader.instantiate();
    for (const z of [0.2, 1.3, 4.7]) {
      const passes = shaderPathsByPass(inst, { region: SQUARE, z, layerHeight: 0.2, density: 20 });
      assert.ok(passes.length >= 1);
      passes.forEach((paths, pass) => {
        assert.ok(paths.length > 0, `${name} z=${z} pass ${pass}: no paths`);
        assert.ok(inside(paths, 0, 0, 20000, 20000), `${name}: paths leave the region`);
        inst.configure({ pass, density: () => 20, layerHeight: 0.2 });
        const share = boundaryShare(paths, (x, y) => inst.label(x, y, z), QUARTER);
        assert.ok(
          share >= 0.99,
          `${name} z=${z} pass ${pass}: only ${(share * 100).toFixed(2)} % of the path length separates two labels`,
        );
      });
      // Near 20 % density the extracted line length is within a factor 1.6 of 0.2 * area / width.
      const len = totalLength(passes.flat());
      assert.ok(
        len > (0.2 * 400) / 0.4 / 1.6 && len < ((0.2 * 400) / 0.4) * 1.6,
        `${name} z=${z}: ${len.toFixed(1)} mm of paths at 20 %`,
      );
    }
    const sparse = totalLength(shaderPathsByPass(inst, { region: SQUARE, z: 1.3, density: 10 }).flat());
    const dense = totalLength(shaderPathsByPass(inst, { region: SQUARE, z: 1.3, density: 40 }).flat());
    assert.ok(
      dense > 2.5 * sparse,
      `${name}: density 40 % gives ${dense.toFixed(1)} mm, 10 % gives ${sparse.toFixed(1)} mm`,
    );
    // A density field: denser on the right half → more paths there.
    const field = shaderPathsByPass(inst, { region: SQUARE, z: 1.3, density: (x) => (x < 10 ? 10 : 40) }).flat();
    let left = 0;
    let right = 0;
    for (const p of field) {
      for (let i = 1; i < p.length; i++) {
        const l = Math.hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
        if ((p[i].x + p[i - 1].x) / 2 < 10000) left += l;
        else right += l;
      }
    }
    assert.ok(right > 1.8 * left, `${name}: density field not followed (left ${left}, right ${right})`);
  });
}

test('hexagon-grid ui_ parameters change the paths', () => {
  const shader = compileShader(readFileSync(join(shippedInfillersDir(), 'hexagon-grid', 'shader.glsl'), 'utf8'));
  assert.deepEqual(
    shader.params.map((p) => [p.name, p.type, p.default]),
    [
      ['ui_side', 'float', 0],
      ['ui_angle', 'float', 0],
      ['ui_alternate', 'bool', false],
    ],
  );
  const inst = shader.instantiate();
  const base = totalLength(shaderPathsByPass(inst, { region: SQUARE, z: 1, density: 20 }).flat());
  const big = totalLength(shaderPathsByPass(inst, { region: SQUARE, z: 1, density: 20, params: { side: 4 } }).flat());
  assert.ok(big < base * 0.75, `side 4 mm: ${big} vs ${base}`);
  const a = shaderPathsByPass(inst, { region: SQUARE, z: 1, density: 20, params: { ui_alternate: true } }).flat();
  const b = shaderPathsByPass(inst, { region: SQUARE, z: 1.2, density: 20, params: { ui_alternate: true } }).flat();
  assert.notDeepEqual(a[0], b[0]);
});

test('shipped example image produces boundary paths', () => {
  const bytes = new Uint8Array(readFileSync(join(shippedInfillersDir(), 'example-image', 'cells.png')));
  const inf = infillerFromImage(bytes, 'example-image');
  assert.deepEqual(inf.warnings, []);
  const paths = inf.paths({ region: SQUARE, z: 0.2 }, { pixelSize: 0.1 });
  assert.ok(paths.length > 10);
  const image = inf.image;
  assert.ok(image !== undefined);
  const share = boundaryShare(paths, imageLabelFn(image, 0.1), QUARTER);
  assert.ok(share >= 0.99, `${(share * 100).toFixed(2)} %`);
  // Density scaling of images (opt-in): a denser layer gets a finer tiling.
  const sparse = totalLength(
    inf.paths({ region: SQUARE, z: 0.2, density: 10 }, { pixelSize: 0.1, densityReference: 20 }),
  );
  const dense = totalLength(
    inf.paths({ region: SQUARE, z: 0.2, density: 40 }, { pixelSize: 0.1, densityReference: 20 }),
  );
  assert.ok(dense > 2.5 * sparse);
});
