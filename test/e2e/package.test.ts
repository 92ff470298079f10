/**
 * The published package holds what users use and nothing else: the library, the CLI, the worker, the
 * web page when it is built, the infillers, the examples and the types. Checked on what
 * `npm pack --dry-run` would publish: every shipped module is reachable by imports from an entry
 * point (so no test, fixture, developer tool or stale build output rides along), and every module
 * an entry point reaches is shipped.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { dirname, join, normalize } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../../../', import.meta.url));

interface PackFile {
  path: string;
  size: number;
}

function packedFiles(): string[] {
  const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
  const r = spawnSync(npm, ['pack', '--dry-run', '--json', '--ignore-scripts'], {
    cwd: ROOT,
    encoding: 'utf8',
    shell: process.platform === 'win32',
  });
  assert.equal(r.status, 0, r.stderr);
  const [report] = JSON.parse(r.stdout) as Array<{ files: PackFile[] }>;
  return report.files.map((f) => f.path.replace(/\\/g, '/')).sort();
}

/** Relative module specifiers a .js or .d.ts file refers to (imports, re-exports, dynamic imports, worker URLs). */
function references(file: string): string[] {
  // comments may quote a specifier without using it
  const text = readFileSync(join(ROOT, file), 'utf8')
    .replace(/\/\*[\s\S]*?\*\//g, '')
    .replace(/^\s*\/\/.*$/gm, '');
  const out: string[] = [];
  const patterns = [
    // import/export … from "./x.js", also minified (import{a}from"./x.js"), and side-effect imports
    /(?:^|[\s;{}])(?:import|export)\b\s*(?:[^'"`;]*?\bfrom\s*)?['"](\.{1,2}\/[^'"]+)['"]/g,
    /\bimport\(\s*['"](\.{1,2}\/[^'"]+)['"]\s*\)/g,
    /\bnew URL\(\s*['"](\.{1,2}\/[^'"]+\.js)['"]\s*,\s*import\.meta\.url\s*\)/g,
    // the clipping engine's loader finds its WebAssembly beside itself
    /\bnew URL\(\s*['"]([\w.-]+\.wasm)['"]\s*,\s*import\.meta\.url\s*\)/g,
  ];
  for (const re of patterns)
    for (const m of text.matchAll(re)) out.push(normalize(join(dirname(file), m[1])).replace(/\\/g, '/'));
  return out;
}

test('npm pack ships the library, CLI, worker, types, infillers and examples, and only what they use', () => {
  const files = packedFiles();
  const shipped = new Set(files);
  const pkg = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8')) as {
    main: string;
    types: string;
    bin: Record<string, string>;
    exports: unknown;
  };
  const leaves = (v: unknown): string[] =>
    typeof v === 'string' ? [v] : v && typeof v === 'object' ? Object.values(v).flatMap(leaves) : [];

  // nothing a user never calls
  const unwanted = files.filter((f) =>
    /\.test\.|\.map$|(^|\/)(e2e|analysis|bench|tools|fixtures?)\/|\.gcode$|(^|\/)test-|(^|\/)bench\./.test(f),
  );
  assert.deepEqual(unwanted, [], 'tests, fixtures, maps, G-code and developer tools are not published');

  // what users do use
  const strip = (p: string) => p.replace(/^\.\//, '');
  const roots = [pkg.main, pkg.types, ...Object.values(pkg.bin), ...leaves(pkg.exports)].map(strip);
  for (const f of [
    ...roots,
    'package.json',
    'README.md',
    'dist/workers/layer-worker.js',
    'examples/calibration-cube.stl',
  ]) {
    assert.ok(shipped.has(f), `${f} is published`);
  }
  const infillers = files.filter((f) => /^infillers\/[^/]+\/(shader\.glsl|cells\.png)$/.test(f));
  assert.ok(infillers.length >= 7, `the shipped infillers (${infillers.length})`);

  // every published module is reachable from an entry point, and everything reachable is published
  const web = files.filter((f) => f.startsWith('dist/web/') && /\.(m?js|html)$/.test(f));
  // the CLI's modules as tsc builds them from src/cli (the bin, dist/bin/main.js, is their bundle)
  const queue = [...roots, ...web, 'dist/cli/main.js'];
  const reached = new Set<string>();
  const missing: string[] = [];
  while (queue.length) {
    const f = queue.pop()!;
    if (reached.has(f)) continue;
    reached.add(f);
    if (!shipped.has(f)) {
      missing.push(f);
      continue;
    }
    if (!/\.(m?js|d\.ts|html)$/.test(f)) continue;
    const refs = references(f);
    // a module and its types come together (a types-only module's .js is an empty pair of its .d.ts)
    if (f.endsWith('.js') && shipped.has(f.replace(/\.js$/, '.d.ts'))) queue.push(f.replace(/\.js$/, '.d.ts'));
    if (f.endsWith('.d.ts') && shipped.has(f.replace(/\.d\.ts$/, '.js'))) queue.push(f.replace(/\.d\.ts$/, '.js'));
    for (const r of refs) queue.push(f.endsWith('.d.ts') && r.endsWith('.js') ? r.replace(/\.js$/, '.d.ts') : r);
  }
  assert.deepEqual(missing, [], 'every module an entry point reaches is published');
  const stray = files.filter((f) => f.startsWith('dist/') && !f.startsWith('dist/web/') && !reached.has(f));
  assert.deepEqual(
    stray,
    [],
    'published but used by nothing (a developer tool, or a stale file from an old build: rm -rf dist && npm run build)',
  );
});
