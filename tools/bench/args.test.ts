import { test } from 'node:test';
import assert from 'node:assert/strict';
import { BENCH_USAGE, BenchArgsError, defaultBenchOptions, parseBenchArgs, selectModels } from './args.js';

test('defaults: one plain run gives the issue table (5 counted runs after a warm-up, every section)', () => {
  const o = parseBenchArgs([]);
  assert.deepEqual(o, defaultBenchOptions());
  assert.deepEqual(o, {
    models: [],
    threads: null,
    repeat: 5,
    warmup: 1,
    json: false,
    timeoutSeconds: 600,
    modelsDir: null,
    strataCli: null,
    peers: true,
    prusa: true,
    patterns: true,
    support: true,
    walls: true,
    threadScaling: true,
    big: true,
    keep: false,
    help: false,
  });
});

test('every flag, in both --flag value and --flag=value forms', () => {
  const o = parseBenchArgs([
    '--models',
    'benchy,cube',
    '--only=spot',
    '--models',
    ' bunny , ',
    '--threads',
    '2',
    '--repeat=7',
    '--warmup',
    '0',
    '--json',
    '--timeout',
    '30.5',
    '--models-dir',
    '/m',
    '--strata-cli=/s.js',
    '--no-peers',
    '--no-prusa',
    '--no-patterns',
    '--no-support',
    '--no-walls',
    '--no-thread-scaling',
    '--no-big',
    '--keep',
  ]);
  assert.deepEqual(o.models, ['benchy', 'cube', 'spot', 'bunny']);
  assert.equal(o.threads, 2);
  assert.equal(o.repeat, 7);
  assert.equal(o.warmup, 0);
  assert.equal(o.json, true);
  assert.equal(o.timeoutSeconds, 30.5);
  assert.equal(o.modelsDir, '/m');
  assert.equal(o.strataCli, '/s.js');
  assert.equal(o.peers, false);
  assert.equal(o.prusa, false);
  assert.equal(o.patterns, false);
  assert.equal(o.support, false);
  assert.equal(o.walls, false);
  assert.equal(o.threadScaling, false);
  assert.equal(o.big, false);
  assert.equal(o.keep, true);
  assert.equal(parseBenchArgs(['-h']).help, true);
  assert.equal(parseBenchArgs(['--help']).help, true);
});

test('--no-walls skips only the walls section, and the usage lists it', () => {
  const o = parseBenchArgs(['--no-walls']);
  assert.deepEqual(o, { ...defaultBenchOptions(), walls: false });
  assert.match(BENCH_USAGE, /^ {2}--no-walls +skip the walls section/m);
  assert.match(BENCH_USAGE, /variable walls against classic/);
  assert.throws(() => parseBenchArgs(['--no-walls=1']), /--no-walls takes no value/);
  assert.throws(() => parseBenchArgs(['--frobnicate']), /allowed: .*--no-walls/);
});

test('bad arguments name the flag', () => {
  for (const [argv, re] of [
    [['--threads', '0'], /--threads needs a whole number from 1/],
    [['--threads', '1.5'], /--threads/],
    [['--repeat', '0'], /--repeat needs a whole number from 1/],
    [['--repeat', 'x'], /--repeat/],
    [['--warmup', '-1'], /--warmup needs a whole number from 0/],
    [['--timeout', '-1'], /--timeout/],
    [['--models'], /--models needs a value/],
    [['--models', ' , '], /--models needs at least one model name/],
    [['--frobnicate'], /unknown argument "--frobnicate"; allowed: .*--no-big/],
    [['--json=yes'], /--json takes no value/],
  ] as const) {
    assert.throws(
      () => parseBenchArgs(argv),
      (e: unknown) => e instanceof BenchArgsError && re.test(e.message),
      argv.join(' '),
    );
  }
});

test('selectModels: exact name or stem first, then substring', () => {
  const names = [
    '3DBenchy.3mf',
    '3DBenchy.stl.gz',
    'CalibrationCube.stl',
    'HollowCalibrationCube.stl',
    'spot.stl',
    '3DBenchy-x4.stl',
  ];
  assert.deepEqual(selectModels(names, []), names);
  assert.deepEqual(selectModels(names, ['3dbenchy']), ['3DBenchy.3mf', '3DBenchy.stl.gz']);
  assert.deepEqual(selectModels(names, ['3DBenchy-x4']), ['3DBenchy-x4.stl']);
  assert.deepEqual(selectModels(names, ['benchy']), ['3DBenchy.3mf', '3DBenchy.stl.gz', '3DBenchy-x4.stl']);
  assert.deepEqual(selectModels(names, ['CalibrationCube']), ['CalibrationCube.stl']);
  assert.deepEqual(selectModels(names, ['calib']), ['CalibrationCube.stl', 'HollowCalibrationCube.stl']);
  assert.deepEqual(selectModels(names, ['3DBenchy.3mf', 'spot']), ['3DBenchy.3mf', 'spot.stl']);
  assert.deepEqual(selectModels(names, ['nothing']), []);
});
