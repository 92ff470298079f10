import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

const CLI = fileURLToPath(new URL('./main.js', import.meta.url));
const CUBE = fileURLToPath(new URL('../../examples/calibration-cube.stl', import.meta.url));
const run = (...args: string[]) => spawnSync(process.execPath, [CLI, ...args], { encoding: 'utf8' });

test('slice writes G-code and a one-line summary', () => {
  const dir = mkdtempSync(join(tmpdir(), 'strata-'));
  const out = join(dir, 'cube.gcode');
  const r = run('slice', CUBE, '-o', out, '--threads', '1', '--layer-height', '0.25', '--infill-density', '15');
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stderr, /80 layers, print time/);
  const g = readFileSync(out, 'utf8');
  assert.match(g, /^;FLAVOR:Marlin/m);
  assert.match(g, /^;Layer height: 0\.25$/m);
});

test('bad input: one-line errors, non-zero exit, no stack trace', () => {
  const dir = mkdtempSync(join(tmpdir(), 'strata-'));
  const junk = join(dir, 'junk.stl');
  writeFileSync(junk, 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\nendsolid');
  for (const args of [
    ['slice', join(dir, 'missing.stl')],
    ['slice', junk],
    ['slice', CUBE, '--layer-height', 'thick'],
    ['slice', CUBE, '--infill-pattern', 'zigzag'],
    ['slice', CUBE, '--layer-hieght', '0.2'],
    ['slice', CUBE, '--printer', 'no-such-printer'],
    ['frobnicate'],
  ]) {
    const r = run(...args, '-o', join(dir, 'x.gcode'));
    assert.equal(r.status, 1, `${args.join(' ')}: ${r.stderr}`);
    assert.equal(r.stderr.trim().split('\n').length, 1, r.stderr);
    assert.match(r.stderr, /^strata: error: /);
    assert.doesNotMatch(r.stderr, /\bat .*\.js:\d+/);
  }
});

test('info, presets, settings and help', () => {
  const info = run('info', CUBE);
  assert.equal(info.status, 0);
  assert.match(info.stdout, /triangles:\s+136/);
  assert.match(info.stdout, /watertight:\s+yes/);
  const presets = run('presets');
  assert.match(presets.stdout, /creality-ender-3/);
  assert.match(presets.stdout, /petg/i);
  const settings = run('settings');
  assert.match(settings.stdout, /--layer-height \(mm\) default 0\.2/);
  assert.match(run('--help').stdout, /strata slice MODEL/);
});

test('preview writes an SVG of the chosen layer', () => {
  const dir = mkdtempSync(join(tmpdir(), 'strata-'));
  const out = join(dir, 'l.svg');
  const r = run('preview', CUBE, '--layer', '10', '-o', out, '--threads', '1');
  assert.equal(r.status, 0, r.stderr);
  const svg = readFileSync(out, 'utf8');
  assert.match(svg, /^<svg /);
  assert.match(svg, /#1f77b4/, 'infill drawn');
});

test('--config, --set and a model on standard input', () => {
  const dir = mkdtempSync(join(tmpdir(), 'strata-'));
  const cfg = join(dir, 'profile.json');
  writeFileSync(cfg, JSON.stringify({ printer: 'prusa-mk4', layerHeight: 0.25, infillDensity: 10 }));
  const out = join(dir, 'o.gcode');
  const r = spawnSync(process.execPath, [CLI, 'slice', '-', '-o', out, '--config', cfg, '--set', 'wallCount=3', '--threads', '1'], {
    input: readFileSync(CUBE),
    encoding: 'utf8',
  });
  assert.equal(r.status, 0, r.stderr);
  assert.match(r.stderr, /80 layers/);
  const g = readFileSync(out, 'utf8');
  assert.match(g, /^;Layer height: 0\.25$/m);
  const bad = join(dir, 'bad.json');
  writeFileSync(bad, '{ "layerHeight": ');
  const e = run('slice', CUBE, '--config', bad, '-o', join(dir, 'x.gcode'));
  assert.equal(e.status, 1);
  assert.match(e.stderr, /not valid JSON/);
});

test('the built CLI is executable, so `npx strata` runs it', { skip: process.platform === 'win32' && 'no exec bit on Windows' }, () => {
  assert.ok((statSync(CLI).mode & 0o111) !== 0, `${CLI} has no execute permission`);
});
