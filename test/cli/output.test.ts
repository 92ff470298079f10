import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  linkSync,
  mkdtempSync,
  readdirSync,
  readFileSync,
  statSync,
  symlinkSync,
  writeFileSync,
  chmodSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { StrataError } from '#strata/errors.js';
import {
  abortPendingOutputs,
  openOutput,
  PipeClosed,
  reasonOf,
  refuseInputAsOutput,
  writeFailed,
} from '#strata/cli/output.js';

const dir = () => mkdtempSync(join(tmpdir(), 'strata-out-'));

function refused(fn: () => unknown, re: RegExp): void {
  assert.throws(fn, (e: unknown) => e instanceof StrataError && re.test(e.message) && !e.message.includes('\n'));
}

test('a file output appears only on commit, replacing the old one and keeping its permissions', () => {
  const d = dir();
  const target = join(d, 'out.gcode');
  writeFileSync(target, 'OLD\n');
  chmodSync(target, 0o640);
  const out = openOutput(target);
  out.write('G1 X1\n');
  out.write('G1 X2\n');
  assert.equal(readFileSync(target, 'utf8'), 'OLD\n', 'untouched while writing');
  assert.equal(readdirSync(d).length, 2, 'the temporary file sits beside the target');
  out.commit();
  assert.equal(readFileSync(target, 'utf8'), 'G1 X1\nG1 X2\n');
  assert.equal(statSync(target).mode & 0o777, 0o640);
  assert.deepEqual(readdirSync(d), ['out.gcode']);
});

test('abort leaves the target as it was and no temporary file; so does the exit/signal clean-up', () => {
  const d = dir();
  const target = join(d, 'out.gcode');
  writeFileSync(target, 'OLD\n');
  const a = openOutput(target);
  a.write('half a file');
  a.abort();
  a.abort();
  assert.equal(readFileSync(target, 'utf8'), 'OLD\n');
  assert.deepEqual(readdirSync(d), ['out.gcode']);
  const b = openOutput(join(d, 'new.gcode'));
  b.write('x');
  abortPendingOutputs();
  assert.deepEqual(readdirSync(d), ['out.gcode'], 'a new file that was never committed does not appear');
});

test('writing through a symbolic link replaces the file it points at and keeps the link', () => {
  const d = dir();
  writeFileSync(join(d, 'real.gcode'), 'OLD');
  symlinkSync('real.gcode', join(d, 'link.gcode'));
  const out = openOutput(join(d, 'link.gcode'));
  out.write('NEW');
  out.commit();
  assert.equal(readFileSync(join(d, 'real.gcode'), 'utf8'), 'NEW');
  assert.ok(statSync(join(d, 'link.gcode')).isFile());
  assert.deepEqual(readdirSync(d).sort(), ['link.gcode', 'real.gcode']);
});

test('write errors are one line naming the path and the reason', () => {
  // /dev/full: every write fails with ENOSPC (a device is written directly, not renamed over)
  const full = openOutput('/dev/full');
  refused(() => full.write('G1 X1\n'), /^cannot write \/dev\/full: no space left on device$/);
  const d = dir();
  refused(() => openOutput(join(d, 'no', 'such', 'folder.gcode')), /^cannot write .*folder\.gcode: no such folder$/);
  refused(() => openOutput(d), /: it is a folder$/);
  for (const [code, text] of [
    ['EIO', 'input/output error'],
    ['EFBIG', 'file too large'],
    ['EDQUOT', 'disk quota exceeded'],
    ['EROFS', 'read-only file system'],
  ]) {
    const e = Object.assign(new Error(`${code}: something, write`), { code });
    assert.equal(reasonOf(e), text);
    const w = writeFailed('x.gcode', e);
    assert.ok(
      w instanceof StrataError && w.code === 'WRITE_FAILED' && w.message === `cannot write x.gcode: ${text}`,
      String(w),
    );
  }
  assert.ok(writeFailed('-', Object.assign(new Error('EPIPE'), { code: 'EPIPE' })) instanceof PipeClosed);
});

test('an output that is one of the inputs is refused: same path, hard link, symbolic link, default name', () => {
  const d = dir();
  const model = join(d, 'm.stl');
  writeFileSync(model, 'solid x\nendsolid x\n');
  const inputs = [{ path: model, what: 'model' }];
  refused(
    () => refuseInputAsOutput(model, inputs, false),
    /^the output .*m\.stl is the model .*m\.stl: writing there would destroy it; choose another -o$/,
  );
  refused(() => refuseInputAsOutput(join(d, '.', 'm.stl'), inputs, false), /is the model/);
  linkSync(model, join(d, 'hard.gcode'));
  refused(() => refuseInputAsOutput(join(d, 'hard.gcode'), inputs, false), /the same file through a link/);
  symlinkSync('m.stl', join(d, 'soft.gcode'));
  refused(() => refuseInputAsOutput(join(d, 'soft.gcode'), inputs, false), /the same file through a link/);
  refused(
    () => refuseInputAsOutput(model, inputs, true),
    /^the default output .* is the model .* itself: .*name the output with -o$/,
  );
  refused(() => refuseInputAsOutput(model, [{ path: model, what: 'config file' }], false), /is the config file/);
  // other files, stdout and stdin are fine
  assert.doesNotThrow(() => refuseInputAsOutput(join(d, 'other.gcode'), inputs, false));
  assert.doesNotThrow(() => refuseInputAsOutput('-', inputs, false));
  assert.doesNotThrow(() => refuseInputAsOutput(model, [{ path: '-', what: 'model' }], false));
  assert.equal(readFileSync(model, 'utf8'), 'solid x\nendsolid x\n');
});
