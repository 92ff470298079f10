// Builds the web page (dist/web/) and the library's own browser build (dist/browser/) with esbuild.
// Run by `npm run build` and `npm ci` (prepare), after tsc. Plain static files: any host can serve them.
import { build } from 'esbuild';
import { cpSync, existsSync, mkdirSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { dirname, join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const at = (...p) => join(root, ...p);
const quiet = process.argv.includes('--quiet');

const common = {
  bundle: true,
  format: 'esm',
  platform: 'browser',
  target: ['es2022'],
  splitting: true,
  minify: true,
  sourcemap: false,
  legalComments: 'eof',
  logLevel: 'warning',
  // the clipping engine's loader imports node's 'module' only when it runs in node
  external: ['module'],
  // jpeg-js's encoder (JPEG thumbnails) hands back Buffer.from(bytes): see buffer-shim.mjs
  inject: [join(root, 'web/buffer-shim.mjs')],
  // the library loads its layer worker as new URL('./layer-worker.js', import.meta.url): keep that name
  entryNames: '[name]',
  chunkNames: '[name]-[hash]',
  metafile: true,
  absWorkingDir: root,
};

/**
 * The source of one of the package's public entries (package.json "exports": dist/x.js, or the types'
 * dist/x.d.ts, is built from src/x.ts). The page imports the library by its package name, which
 * web/tsconfig.json maps to these sources for esbuild and tsc alike.
 */
function entrySource(subpath) {
  const target = JSON.parse(readFileSync(at('package.json'), 'utf8')).exports[subpath];
  const built = typeof target === 'string' ? target : target.types.replace(/\.d\.ts$/, '.js');
  return at(built.replace(/^\.\/dist\//, 'src/').replace(/\.js$/, '.ts'));
}

/** The library for browsers: strata.js, layer-worker.js beside it, the shader compiler in a chunk. */
async function libraryBuild() {
  const out = at('dist/browser');
  rmSync(out, { recursive: true, force: true });
  return build({
    ...common,
    entryPoints: { strata: entrySource('./browser'), 'layer-worker': entrySource('./layer-worker') },
    outdir: out,
  }).then((r) => (copyClipperWasm(out), r));
}

/** The clipping engine's WebAssembly, which its loader fetches from beside the script that loads it. */
function copyClipperWasm(out) {
  cpSync(at('node_modules/clipper2-wasm/dist/es/clipper2z.wasm'), join(out, 'clipper2z.wasm'));
}

/**
 * The page: app.js (page thread), slice-worker.js (module worker), layer-worker.js (the pool's). The page
 * thread is bundled apart from the workers: both import the library's one entry, and esbuild's code
 * splitting puts every module that entry re-exports in chunks that both load (it splits by files reached,
 * not by names used), so a shared build would load the whole slicer, and wait for its WebAssembly, on the
 * page thread. Bundled alone, the page thread keeps only what it uses (package.json "sideEffects").
 */
async function pageBuild() {
  const out = at('dist/web');
  rmSync(out, { recursive: true, force: true });
  // one file: with splitting, esbuild would also emit (and share chunks with) the library's dynamic imports
  const pageThread = await build({
    ...common,
    splitting: false,
    entryPoints: { app: at('web/src/main.ts') },
    outdir: out,
  });
  const workers = await build({
    ...common,
    entryPoints: {
      'slice-worker': at('web/src/worker.ts'),
      // the library's worker pool, started by the library inside slice-worker.js
      'layer-worker': entrySource('./layer-worker'),
    },
    outdir: out,
  });
  const result = {
    metafile: {
      inputs: { ...pageThread.metafile.inputs, ...workers.metafile.inputs },
      outputs: { ...pageThread.metafile.outputs, ...workers.metafile.outputs },
    },
  };
  copyClipperWasm(out);
  cpSync(at('web/index.html'), join(out, 'index.html'));
  cpSync(at('web/style.css'), join(out, 'style.css'));
  cpSync(at('web/favicon.svg'), join(out, 'favicon.svg'));
  // the shipped custom infillers, fetched by the page when chosen
  const list = [];
  for (const name of readdirSync(at('infillers')).sort()) {
    const dir = at('infillers', name);
    if (!statSync(dir).isDirectory()) continue;
    const file = ['shader.glsl', 'cells.png'].find((f) => existsSync(join(dir, f)));
    if (!file) continue;
    mkdirSync(join(out, 'infillers', name), { recursive: true });
    cpSync(join(dir, file), join(out, 'infillers', name, file));
    const preview = existsSync(join(dir, 'preview.png'));
    if (preview) cpSync(join(dir, 'preview.png'), join(out, 'infillers', name, 'preview.png'));
    list.push({ name, file, preview });
  }
  writeFileSync(join(out, 'infillers', 'index.json'), JSON.stringify(list, null, 1) + '\n');
  return result;
}

/** Gzipped size of an output file and the chunks it imports statically (what loads before it runs). */
function loadSize(meta, file, seen = new Set()) {
  if (seen.has(file)) return 0;
  seen.add(file);
  let total = gzipSync(readFileSync(at(file))).length;
  for (const imp of meta.outputs[file]?.imports ?? [])
    if (imp.kind === 'import-statement') total += loadSize(meta, imp.path, seen);
  return total;
}

const kb = (n) => `${(n / 1024).toFixed(1)} KB`;

/** The output file holding the shader compiler (loaded only for custom infill). */
function compilerChunk(meta) {
  return Object.entries(meta.outputs).find(
    ([f, o]) => f.endsWith('.js') && Object.keys(o.inputs).some((i) => i.includes('src/shader/compile-program')),
  )?.[0];
}

const lib = await libraryBuild();
const page = await pageBuild();
// sizes (gzipped, each entry with the chunks it imports at once), and which chunk is the compiler
const info = { gzippedBytes: {}, shaderCompiler: {} };
for (const [name, meta, dir, entries] of [
  ['browser', lib.metafile, 'dist/browser', ['strata.js', 'layer-worker.js']],
  ['web', page.metafile, 'dist/web', ['app.js', 'slice-worker.js', 'layer-worker.js']],
]) {
  for (const e of entries) info.gzippedBytes[`${dir}/${e}`] = loadSize(meta, `${dir}/${e}`);
  const chunk = compilerChunk(meta);
  if (!chunk) throw new Error(`${dir}: no chunk holds the shader compiler: is it imported statically?`);
  info.shaderCompiler[name] = relative(at(dir), at(chunk));
  info.gzippedBytes[chunk] = gzipSync(readFileSync(at(chunk))).length;
}
writeFileSync(at('dist/web/build-info.json'), JSON.stringify(info, null, 1) + '\n');
if (!quiet) {
  const sizes = Object.entries(info.gzippedBytes).map(([f, n]) => `${f} ${kb(n)}`);
  process.stdout.write(
    `web build, gzipped (entries with the chunks they load at once): ${sizes.join('; ')}; shader compiler chunks load on demand\n`,
  );
}
