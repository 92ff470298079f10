import { test } from 'node:test';
import assert from 'node:assert/strict';
import { BenchArgsError, parseBenchArgs, selectModels } from './args.js';

test('defaults', () => {
  const o = parseBenchArgs([]);
  assert.deepEqual(o, {
    only: [], threads: null, repeat: 1, json: false, timeoutSeconds: 600, modelsDir: null, strataCli: null,
    peers: true, patterns: true, keep: false, help: false,
  });
});

test('every flag, in both --flag value and --flag=value forms', () => {
  const o = parseBenchArgs(['--only', 'benchy,cube', '--only=spot', '--threads', '2', '--repeat=5', '--json', '--timeout', '30.5', '--models', '/m', '--strata-cli=/s.js', '--no-peers', '--no-patterns', '--keep']);
  assert.deepEqual(o.only, ['benchy', 'cube', 'spot']);
  assert.equal(o.threads, 2);
  assert.equal(o.repeat, 5);
  assert.equal(o.json, true);
  assert.equal(o.timeoutSeconds, 30.5);
  assert.equal(o.modelsDir, '/m');
  assert.equal(o.strataCli, '/s.js');
  assert.equal(o.peers, false);
  assert.equal(o.patterns, false);
  assert.equal(o.keep, true);
  assert.equal(parseBenchArgs(['-h']).help, true);
});

test('bad arguments name the flag', () => {
  for (const [argv, re] of [
    [['--threads', '0'], /--threads/],
    [['--threads', '1.5'], /--threads/],
    [['--repeat', 'x'], /--repeat/],
    [['--timeout', '-1'], /--timeout/],
    [['--only'], /--only needs a value/],
    [['--frobnicate'], /unknown argument "--frobnicate"/],
    [['--json=yes'], /--json takes no value/],
  ] as const) {
    assert.throws(() => parseBenchArgs(argv), (e: unknown) => e instanceof BenchArgsError && re.test(e.message), argv.join(' '));
  }
});

test('selectModels: exact name or stem first, then substring', () => {
  const names = ['3DBenchy.3mf', '3DBenchy.stl.gz', 'CalibrationCube.stl', 'HollowCalibrationCube.stl', 'spot.stl'];
  assert.deepEqual(selectModels(names, []), names);
  assert.deepEqual(selectModels(names, ['3dbenchy']), ['3DBenchy.3mf', '3DBenchy.stl.gz']);
  assert.deepEqual(selectModels(names, ['CalibrationCube']), ['CalibrationCube.stl']);
  assert.deepEqual(selectModels(names, ['calib']), ['CalibrationCube.stl', 'HollowCalibrationCube.stl']);
  assert.deepEqual(selectModels(names, ['3DBenchy.3mf', 'spot']), ['3DBenchy.3mf', 'spot.stl']);
  assert.deepEqual(selectModels(names, ['nothing']), []);
});
