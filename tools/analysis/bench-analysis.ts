/**
 * Speed of the analyser: `node dist-dev/tools/analysis/bench-analysis.js [model.stl[.gz]]` parses ~30 MB of G-code and
 * analyses a model (default ../shared/models/3DBenchy.stl.gz) against toy G-code made from its own sections.
 */
import { readFileSync } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import { analyzePrint } from './checks.js';
import { formatReport } from './format-report.js';
import { parseGcode } from './gcode-parse.js';
import { placeOnBed, readStl, toyGcode } from './toy-slicer.js';

const OPTS = { layerHeight: 0.2, firstLayerHeight: 0.2, lineWidth: 0.4, filamentDiameter: 1.75 };

function main(): void {
  const path = process.argv[2] ?? new URL('../../../../shared/models/3DBenchy.stl.gz', import.meta.url).pathname;
  let bytes: Uint8Array = readFileSync(path);
  if (path.endsWith('.gz')) bytes = gunzipSync(bytes);
  const mesh = placeOnBed(readStl(bytes), 110, 110);
  let t = performance.now();
  const gcode = toyGcode(mesh, { ...OPTS, infillSpacing: 4, skinLayers: 4 });
  console.log(`toy G-code: ${(gcode.length / 1e6).toFixed(1)} MB in ${(performance.now() - t).toFixed(0)} ms`);

  const big = gcode.repeat(Math.max(1, Math.ceil(30e6 / gcode.length)));
  t = performance.now();
  const parsed = parseGcode(big);
  console.log(
    `parse ${(big.length / 1e6).toFixed(1)} MB: ${(performance.now() - t).toFixed(0)} ms, ` +
      `${parsed.layers.length} layers`,
  );

  t = performance.now();
  const report = analyzePrint(mesh, gcode, OPTS);
  console.log(`analyse (all layers): ${(performance.now() - t).toFixed(0)} ms`);
  t = performance.now();
  analyzePrint(mesh, gcode, { ...OPTS, sampleEvery: 5 });
  console.log(`analyse (every 5th layer): ${(performance.now() - t).toFixed(0)} ms`);
  console.log(formatReport(report));
}

main();
