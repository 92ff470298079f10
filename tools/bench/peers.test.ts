import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, writeFileSync, chmodSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { curaCommand, findOnPath, peerReads, prusaCommand } from './peers.js';

test('CuraEngine command: threads, definitions, global then extruder settings, model, output', () => {
  const { command, args } = curaCommand(
    '/usr/bin/CuraEngine',
    '/defs/fdmprinter.def.json',
    '/m/cube.stl',
    '/o/cube.gcode',
    2,
  );
  assert.equal(command, '/usr/bin/CuraEngine');
  assert.deepEqual(args.slice(0, 4), ['slice', '-m2', '-j', '/defs/fdmprinter.def.json']);
  assert.deepEqual(args.slice(-4), ['-l', '/m/cube.stl', '-o', '/o/cube.gcode']);
  const settings = (from: number, to: number) => args.slice(from, to).filter((_, i, a) => a[i - 1] === '-s');
  const e0 = args.indexOf('-e0');
  assert.ok(e0 > 0);
  const global = settings(0, e0);
  for (const s of [
    'layer_height=0.2',
    'wall_line_count=2',
    'top_bottom_thickness=0.8',
    'infill_sparse_density=20',
    'infill_pattern=grid',
    'machine_nozzle_size=0.4',
    'machine_width=220',
  ]) {
    assert.ok(global.includes(s), s);
  }
  assert.ok(settings(e0, args.length).includes('material_diameter=1.75'), 'extruder train gets 1.75 mm filament too');
  assert.ok(!curaCommand('c', 'd', 'm', 'o', null).args.some((a) => a.startsWith('-m')));
});

test('PrusaSlicer command: common profile flags, output before the model', () => {
  const { args } = prusaCommand('/usr/bin/prusa-slicer', '/tmp/d', '/m/cube.stl', '/o/cube.gcode');
  const flag = (name: string) => args[args.indexOf(name) + 1];
  assert.ok(args.includes('--export-gcode'));
  assert.equal(flag('--datadir'), '/tmp/d');
  assert.equal(flag('--layer-height'), '0.2');
  assert.equal(flag('--perimeters'), '2');
  assert.equal(flag('--top-solid-layers'), '4');
  assert.equal(flag('--bottom-solid-layers'), '4');
  assert.equal(flag('--fill-density'), '20%');
  assert.equal(flag('--fill-pattern'), 'grid');
  assert.equal(flag('--bed-shape'), '0x0,220x0,220x220,0x220');
  assert.deepEqual(args.slice(-3), ['-o', '/o/cube.gcode', '/m/cube.stl']);
});

test('peerReads: CuraEngine reads STL only', () => {
  assert.equal(peerReads('cura', '/m/a.STL'), true);
  assert.equal(peerReads('cura', '/m/a.3mf'), false);
  assert.equal(peerReads('prusa', '/m/a.3mf'), true);
});

test('findOnPath finds executables only', () => {
  const dir = mkdtempSync(join(tmpdir(), 'strata-peers-'));
  try {
    writeFileSync(join(dir, 'tool'), '#!/bin/sh\n');
    chmodSync(join(dir, 'tool'), 0o755);
    writeFileSync(join(dir, 'data'), '');
    chmodSync(join(dir, 'data'), 0o644);
    assert.equal(findOnPath('tool', { PATH: `/nonexistent:${dir}` }), join(dir, 'tool'));
    assert.equal(findOnPath('data', { PATH: dir }), null);
    assert.equal(findOnPath('tool', {}), null);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
