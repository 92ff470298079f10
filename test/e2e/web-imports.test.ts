/**
 * The web page uses the library as any app does: through the package's public entry points, by the
 * package's name, and never a module inside it. Checked on the page's sources (web/src): every import,
 * re-export and dynamic import is the page's own file or a package, and of this package only entries its
 * package.json exports; web/tsconfig.json, which resolves those names for tsc and esbuild (web/build.mjs),
 * maps each to the source of that very entry; and the build script names no library source itself.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';

const ROOT = fileURLToPath(new URL('../../../', import.meta.url));
const WEB_SRC = join(ROOT, 'web/src');
const PACKAGE = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8')) as {
  name: string;
  exports: Record<string, string | Record<string, string>>;
};

/** Every .ts file under a folder. */
function sources(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? sources(join(dir, e.name)) : e.name.endsWith('.ts') ? [join(dir, e.name)] : [],
  );
}

/** The module specifiers a file names: imports, `import type`, re-exports and dynamic imports. */
function specifiers(file: string): string[] {
  const info = ts.preProcessFile(readFileSync(file, 'utf8'), true, true);
  return info.importedFiles.map((f) => f.fileName);
}

/** The package export a specifier names (`.`, `./worker`…), or null for another package. */
function exportOf(spec: string): string | null {
  if (spec === PACKAGE.name) return '.';
  if (spec.startsWith(`${PACKAGE.name}/`)) return `./${spec.slice(PACKAGE.name.length + 1)}`;
  return null;
}

/**
 * The source file an export is built from, as a browser bundler picks it: the `browser` condition, else the
 * types' module, else the one target (dist/x.js is built from src/x.ts).
 */
function sourceOf(subpath: string): string {
  const target = PACKAGE.exports[subpath];
  assert.ok(target, `package.json exports "${subpath}"`);
  const built =
    typeof target === 'string'
      ? target
      : (target.browser ?? target.types?.replace(/\.d\.ts$/, '.js') ?? target.default);
  assert.match(built, /^\.\/dist\/.*\.js$/, `"${subpath}" is built into dist/`);
  return join(ROOT, built.replace(/^\.\/dist\//, 'src/').replace(/\.js$/, '.ts'));
}

test('the web page imports only its own files, other packages, and the library by its public entries', () => {
  const files = sources(WEB_SRC);
  assert.ok(files.length >= 10, `the page's sources (${files.length})`);
  const wrong: string[] = [];
  const used = new Set<string>();
  for (const file of files) {
    const where = relative(ROOT, file);
    for (const spec of specifiers(file)) {
      if (spec.startsWith('.')) {
        // the page's own modules only
        const target = resolve(dirname(file), spec);
        if (relative(WEB_SRC, target).startsWith('..')) wrong.push(`${where}: ${spec} (outside web/src)`);
        continue;
      }
      if (spec.startsWith('/') || spec.startsWith('#')) {
        wrong.push(`${where}: ${spec} (a path or the package's own #imports)`);
        continue;
      }
      const entry = exportOf(spec);
      if (entry === null) continue; // another package (three)
      if (!(entry in PACKAGE.exports)) wrong.push(`${where}: ${spec} (not an entry in package.json exports)`);
      else used.add(entry);
    }
  }
  assert.deepEqual(wrong, [], 'web/src imports the library through its public entry points only');
  assert.ok(used.has('.'), `the page imports ${PACKAGE.name}`);
});

test("web/tsconfig.json resolves the package's name to its public entries' sources, and only those", () => {
  const read = ts.readConfigFile(join(ROOT, 'web/tsconfig.json'), ts.sys.readFile);
  assert.equal(read.error, undefined);
  const paths = (read.config as { compilerOptions: { paths?: Record<string, string[]> } }).compilerOptions.paths ?? {};
  const names = Object.keys(paths);
  assert.ok(names.length > 0, 'the page resolves the library by name');
  for (const name of names) {
    const entry = exportOf(name);
    assert.ok(entry !== null && !name.includes('*'), `${name}: the package's name or one of its entries, no pattern`);
    assert.ok(entry in PACKAGE.exports, `${name}: an entry in package.json exports`);
    assert.deepEqual(
      paths[name].map((p) => resolve(ROOT, 'web', p)),
      [sourceOf(entry)],
      `${name} resolves to the source of package.json's "${entry}" export`,
    );
  }
  // the build script takes the library's entries from package.json too, not source paths of its own
  const script = readFileSync(join(ROOT, 'web/build.mjs'), 'utf8').replace(/^\s*(\/\/|\*).*$/gm, '');
  assert.doesNotMatch(script, /['"`](\.\/)?src\/[\w/.-]+\.ts['"`]/, 'web/build.mjs names no library source file');
});
