import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { PATTERN_IDS } from '../infill/types.js';
import { parseBenchArgs } from './args.js';
import { runBench } from './bench.js';
import { countTriangles, listModelFiles, prepareModels } from './models.js';
import { renderReport } from './report.js';

/** A binary STL of `n` zero triangles. */
function binaryStl(n: number): Uint8Array {
  const bytes = new Uint8Array(84 + 50 * n);
  new DataView(bytes.buffer).setUint32(80, n, true);
  return bytes;
}

/** A stub of Strata's CLI: checks the arguments, writes the output, fails on models named "broken". */
const STUB_CLI = `
const args = process.argv.slice(2);
const out = args[args.indexOf('-o') + 1];
if (args[0] !== 'slice' || !out) { console.error('stub: bad arguments ' + args.join(' ')); process.exit(2); }
if (args[1].includes('broken')) { console.error('stub: cannot slice ' + args[1]); process.exit(1); }
require('node:fs').writeFileSync(out, ';stub ' + args.join(' ') + '\\n');
`;

function fixture() {
  const root = mkdtempSync(join(tmpdir(), 'strata-bench-test-'));
  const models = join(root, 'models');
  const work = join(root, 'work');
  mkdirSync(models);
  mkdirSync(work);
  writeFileSync(join(models, 'cube.stl'), binaryStl(12));
  writeFileSync(join(models, 'broken.stl'), binaryStl(3));
  writeFileSync(join(models, '3DBenchy.stl.gz'), gzipSync(binaryStl(5)));
  writeFileSync(join(models, 'ascii.stl'), 'solid a\nfacet normal 0 0 1\nouter loop\nendloop\nendfacet\nfacet normal 0 0 1\nendfacet\nendsolid a\n');
  writeFileSync(join(models, 'SOURCES.md'), '# not a model\n');
  const cli = join(root, 'stub-cli.cjs');
  writeFileSync(cli, STUB_CLI);
  return { root, models, work, cli };
}

test('models: listing, triangle counts, gzip unpacked once into the work folder', () => {
  const f = fixture();
  try {
    assert.deepEqual(listModelFiles(f.models), ['3DBenchy.stl.gz', 'ascii.stl', 'broken.stl', 'cube.stl']);
    assert.equal(countTriangles('x.stl', binaryStl(7)), 7);
    const prepared = prepareModels(f.models, ['3DBenchy.stl.gz', 'ascii.stl'], f.work);
    assert.deepEqual(prepared.map((m) => [m.name, m.triangles]), [['3DBenchy.stl', 5], ['ascii.stl', 2]]);
    assert.equal(prepared[0]!.path, join(f.work, '3DBenchy.stl'));
  } finally {
    rmSync(f.root, { recursive: true, force: true });
  }
});

test('runBench with a stub CLI: times every model, reports failures, runs every infill pattern', async () => {
  const f = fixture();
  try {
    const options = parseBenchArgs(['--models', f.models, '--strata-cli', f.cli, '--no-peers', '--threads', '1', '--timeout', '60']);
    const report = await runBench(options, { workDir: f.work, log: () => {} });
    assert.equal(report.strataCli.built, true);
    assert.equal(report.peers.cura, null);
    const byName = Object.fromEntries(report.models.map((r) => [r.model, r]));
    assert.deepEqual(Object.keys(byName), ['3DBenchy.stl', 'ascii.stl', 'broken.stl', 'cube.stl']);
    assert.equal(byName['cube.stl']!.strata.status, 'ok');
    assert.ok(byName['cube.stl']!.strata.wallSeconds! > 0);
    assert.equal(byName['cube.stl']!.triangles, 12);
    assert.equal(byName['broken.stl']!.strata.status, 'failed');
    assert.match(byName['broken.stl']!.strata.message!, /cannot slice/);
    assert.equal(byName['cube.stl']!.cura.status, 'missing');
    assert.equal(report.patternModel, '3DBenchy.stl');
    assert.deepEqual(report.patterns.map((p) => p.pattern), [...PATTERN_IDS]);
    assert.ok(report.patterns.every((p) => p.strata.status === 'ok' && p.relativeToGrid !== null));
    assert.equal(report.patterns[0]!.relativeToGrid, 1);
    const outputs = readdirSync(join(f.work, 'out'));
    assert.ok(outputs.includes('3DBenchy.stl.infill-gyroid.gcode'));
    const text = renderReport(report);
    assert.match(text, /Infill patterns on 3DBenchy\.stl/);
    assert.match(text, /Strata on broken\.stl: exit code 1: stub: cannot slice/);
  } finally {
    rmSync(f.root, { recursive: true, force: true });
  }
});

test('runBench repeats round-robin across jobs and reports the median', async () => {
  const f = fixture();
  try {
    const options = parseBenchArgs(['--models', f.models, '--strata-cli', f.cli, '--no-peers', '--only', '3DBenchy', '--repeat', '2']);
    const log: string[] = [];
    const report = await runBench(options, { workDir: f.work, log: (l) => log.push(l.trim()) });
    assert.equal(report.models[0]!.strata.samples.length, 2);
    assert.equal(report.patterns[0]!.strata.samples.length, 2);
    const patternRuns = log.filter((l) => l.includes('--infill-pattern'));
    assert.equal(patternRuns.length, 2 * PATTERN_IDS.length);
    // Round 1 of every pattern comes before round 2 of any.
    assert.ok(patternRuns.slice(0, PATTERN_IDS.length).every((l) => l.includes('run 1/2')), patternRuns.join('\n'));
  } finally {
    rmSync(f.root, { recursive: true, force: true });
  }
});

test('runBench without a built CLI reports it instead of crashing', async () => {
  const f = fixture();
  try {
    const options = parseBenchArgs(['--models', f.models, '--strata-cli', join(f.root, 'missing.js'), '--no-peers', '--only', 'cube']);
    const report = await runBench(options, { workDir: f.work, log: () => {} });
    assert.equal(report.strataCli.built, false);
    assert.equal(report.models.length, 1);
    assert.equal(report.models[0]!.strata.status, 'missing');
    assert.equal(report.patterns.length, 0);
    assert.match(renderReport(report), /strata CLI not built/);
  } finally {
    rmSync(f.root, { recursive: true, force: true });
  }
});

test('runBench rejects a filter that matches nothing, naming the models', async () => {
  const f = fixture();
  try {
    const options = parseBenchArgs(['--models', f.models, '--no-peers', '--only', 'nope']);
    await assert.rejects(runBench(options, { workDir: f.work, log: () => {} }), /no model matches --only nope; models in .*cube\.stl/);
  } finally {
    rmSync(f.root, { recursive: true, force: true });
  }
});
