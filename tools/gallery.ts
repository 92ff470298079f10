/**
 * Regenerates the README's infill gallery: one SVG per registered pattern, made by the same code as
 * `strata preview` (a mid-height layer of the bundled calibration cube, 20 % infill, no skin there).
 * Run: `npm run gallery`.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { Slicer } from '#strata/api/slicer.js';
import { PATTERN_IDS } from '#strata/infill/types.js';
import { layerToSvg } from '#strata/preview/svg.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const out = root + 'docs/patterns/';
mkdirSync(out, { recursive: true });
const model = readFileSync(root + 'examples/calibration-cube.stl');
for (const id of PATTERN_IDS) {
  const slicer = new Slicer({ threads: 1, infillPattern: id, infillDensity: 20, adhesionType: 'none' });
  const { plan } = await slicer.slicePlan(model);
  // lightning only prints under top surfaces: show a layer just below the cube's top skin
  const index = id === 'lightning' ? plan.layers.length - 6 : Math.floor(plan.layers.length / 2);
  writeFileSync(
    out + `${id}.svg`,
    layerToSvg(plan.layers[index], { widthPx: 240, title: `${id}, layer ${index}` }) + '\n',
  );
  process.stdout.write(`docs/patterns/${id}.svg\n`);
}
