/**
 * Renders infillers/NAME/preview.png for every shipped infiller: the cells (pass 0) in pale colours
 * and the extracted paths on a 20 mm square at 20 % density (pass 0 dark, pass 1 red).
 * Run: node dist-dev/tools/make-previews.js [infillers-dir]
 */
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { encode } from 'fast-png';
import type { ExPolygon, Polyline } from '#strata/geometry/types.js';
import { imageLabelFn } from '#strata/shader/image.js';
import { loadInfiller } from '#strata/shader/infiller.js';
import { readInfillersFolder, shippedInfillersDir } from '#strata/shader/node-folder.js';
import { shaderPathsByPass } from '#strata/shader/paths.js';

const SIZE_MM = 20;
const PX = 400;
const REGION: ExPolygon[] = [
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
const LINE_COLOURS = [
  [40, 40, 50],
  [200, 30, 40],
];

function pale(label: number): number[] {
  // A stable pastel colour from the label bits.
  let h = (label % 4294967296) ^ Math.floor(label / 4294967296);
  h = Math.imul(h ^ (h >>> 16), 0x45d9f3b);
  h = Math.imul(h ^ (h >>> 16), 0x45d9f3b);
  h ^= h >>> 16;
  return [200 + (h & 55), 200 + ((h >>> 8) & 55), 200 + ((h >>> 16) & 55)];
}

function render(label: (x: number, y: number) => number, passes: Polyline[][]): Uint8Array {
  const img = new Uint8Array(PX * PX * 3);
  const s = PX / SIZE_MM;
  for (let py = 0; py < PX; py++) {
    for (let px = 0; px < PX; px++) img.set(pale(label((px + 0.5) / s, (PX - py - 0.5) / s)), (py * PX + px) * 3);
  }
  passes.forEach((paths, pass) => {
    const colour = LINE_COLOURS[pass % 2];
    for (const p of paths) {
      for (let i = 1; i < p.length; i++) {
        const a = p[i - 1];
        const b = p[i];
        const n = Math.ceil((Math.hypot(b.x - a.x, b.y - a.y) / 1000) * s * 3) + 1;
        for (let k = 0; k <= n; k++) {
          const x = ((a.x + ((b.x - a.x) * k) / n) / 1000) * s;
          const y = PX - ((a.y + ((b.y - a.y) * k) / n) / 1000) * s;
          for (let dy = -1; dy <= 0; dy++) {
            for (let dx = -1; dx <= 0; dx++) {
              const ix = Math.floor(x) + dx + 1;
              const iy = Math.floor(y) + dy + 1;
              if (ix >= 0 && iy >= 0 && ix < PX && iy < PX) img.set(colour, (iy * PX + ix) * 3);
            }
          }
        }
      }
    }
  });
  return encode({ width: PX, height: PX, data: img, channels: 3, depth: 8 });
}

export async function writePreviews(dir: string): Promise<string[]> {
  const written: string[] = [];
  for (const files of await readInfillersFolder(dir)) {
    const inf = loadInfiller(files);
    const layer = { region: REGION, z: 1, layerHeight: 0.2, density: 20 };
    let png: Uint8Array;
    if (inf.kind === 'shader' && inf.shader !== undefined) {
      const inst = inf.shader.instantiate();
      const passes = shaderPathsByPass(inst, layer);
      inst.configure({ pass: 0, density: () => 20, layerHeight: 0.2 });
      png = render((x, y) => inst.label(x, y, 1), passes);
    } else if (inf.image !== undefined) {
      png = render(imageLabelFn(inf.image, 0.1), inf.pathsByPass(layer, { pixelSize: 0.1 }));
    } else continue;
    const out = join(dir, files.name, 'preview.png');
    writeFileSync(out, png);
    written.push(out);
  }
  return written;
}

if (process.argv[1] !== undefined && import.meta.url === pathToFileURL(process.argv[1]).href) {
  for (const f of await writePreviews(process.argv[2] ?? shippedInfillersDir())) console.log(`wrote ${f}`);
}
