/**
 * Infill micro-benchmark: every registered pattern on a synthetic Benchy-sized part (a 60 × 30 mm hull with
 * two holes, shrinking with height, 240 layers of 0.2 mm, a top skin at the top and a deck patch halfway),
 * at 20 % by default. Prints ms per layer per pattern (lightning's whole-object `prepare` included, spread
 * over the layers) and the ratio to grid. Run: `node dist-dev/tools/bench/infill-patterns.js [density%] [layers]`.
 */
import type { ExPolygon } from '#strata/geometry/types.js';
import type { InfillLayerInput, InfillModelInput, PatternId } from '#strata/infill/types.js';
import { PATTERNS } from '#strata/infill/registry.js';
import { generateInfill } from '#strata/infill/generate.js';
import { hull, testParams, SHAPE_CENTRE } from '../../test/infill/test-shapes.js';
import { pathLengthUm } from '#strata/infill/measure.js';
import { area } from '#strata/geometry/clip.js';

function model(layers: number): InfillModelInput {
  const ls: InfillLayerInput[] = [];
  const need: ExPolygon[][] = [];
  const c = SHAPE_CENTRE;
  const deck: ExPolygon[] = [
    {
      outer: [
        { x: c.x - 12_000, y: c.y - 6_000 },
        { x: c.x + 2_000, y: c.y - 6_000 },
        { x: c.x + 2_000, y: c.y + 6_000 },
        { x: c.x - 12_000, y: c.y + 6_000 },
      ],
      holes: [],
    },
  ];
  for (let i = 0; i < layers; i++) {
    const z = 0.2 * (i + 1);
    ls.push({ layerIndex: i, zMm: z, layerHeightMm: 0.2, region: hull(z) });
    need.push(i === layers - 1 ? hull(z) : i === Math.floor(layers / 2) ? deck : []);
  }
  return { layers: ls, supportNeeded: need };
}

const REPEATS = 3;

function main(): void {
  const density = Number(process.argv[2] ?? 20) / 100;
  const n = Number(process.argv[3] ?? 240);
  const m = model(n);
  const params = testParams(density);
  const ids = Object.keys(PATTERNS) as PatternId[];
  // warm up every code path once
  for (const id of ids) for (let i = 0; i < 10; i++) generateInfill(id, m.layers[(i * 17) % n], params);
  const rows: Array<{ id: string; ms: number; prepMs: number; density: number }> = [];
  let regionArea = 0;
  for (const l of m.layers) regionArea += area(l.region);
  // the best of REPEATS runs per pattern: the machine may be busy with other work
  for (const id of ids) {
    const p = PATTERNS[id];
    let best = { ms: Infinity, prepMs: 0, density: 0 };
    for (let rep = 0; rep < REPEATS; rep++) {
      const t0 = performance.now();
      const prepared = p.prepare ? p.prepare(m, params) : undefined;
      const t1 = performance.now();
      let len = 0;
      for (let i = 0; i < n; i++) {
        const r = generateInfill(id, m.layers[i], params, prepared ? prepared[i] : undefined);
        len += pathLengthUm(r);
      }
      const t2 = performance.now();
      if ((t2 - t0) / n < best.ms)
        best = { ms: (t2 - t0) / n, prepMs: (t1 - t0) / n, density: (len * params.lineWidthUm) / regionArea };
    }
    rows.push({ id, ...best });
  }
  const grid = rows.find((r) => r.id === 'grid')?.ms ?? 1;
  console.log(
    `infill bench: ${n} layers, hull 60 × 30 mm, density ${(density * 100).toFixed(0)} %, line width ${params.lineWidthUm} µm`,
  );
  console.log('pattern       ms/layer  (prepare)  × grid   length×width/area');
  for (const r of rows) {
    console.log(
      `${r.id.padEnd(12)} ${r.ms.toFixed(2).padStart(8)}  ${r.prepMs ? r.prepMs.toFixed(2).padStart(9) : '        -'}  ${(r.ms / grid).toFixed(2).padStart(6)}   ${(r.density * 100).toFixed(1).padStart(6)} %`,
    );
  }
}

main();
