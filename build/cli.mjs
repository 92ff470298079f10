// The command line as users run it: one bundle (with its chunks) for the CLI and its layer worker, so node
// loads a few files instead of some two hundred modules (~0.1 s of every run). `npm run build` runs this
// after tsc; package.json's bin points here. The unbundled dist/cli stays for the tests.
import { build } from 'esbuild';
import { chmodSync, cpSync, rmSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const out = join(root, 'dist', 'bin');
rmSync(out, { recursive: true, force: true });
await build({
  absWorkingDir: root,
  entryPoints: { main: 'src/cli/main.ts', 'layer-worker': 'src/workers/layer-worker.ts' },
  outdir: out,
  bundle: true,
  platform: 'node',
  format: 'esm',
  target: ['node20'],
  // the pool starts its worker as new URL('./layer-worker.js', import.meta.url): chunks sit beside it
  splitting: true,
  entryNames: '[name]',
  chunkNames: 'chunk-[hash]',
  // bundled CommonJS dependencies call require: give them node's
  banner: {
    js: "import { createRequire as __strataRequire } from 'node:module'; const require = __strataRequire(import.meta.url);",
  },
  legalComments: 'eof',
  logLevel: 'warning',
});
// the clipping engine's loader reads its WebAssembly from beside itself
cpSync(join(root, 'node_modules/clipper2-wasm/dist/es/clipper2z.wasm'), join(out, 'clipper2z.wasm'));
chmodSync(join(out, 'main.js'), 0o755);
