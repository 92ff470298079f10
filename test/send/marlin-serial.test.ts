import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import {
  CANCEL_GCODE,
  gcodeCommands,
  MarlinSender,
  numberedLine,
  type MarlinOptions,
} from '#strata/send/marlin-serial.js';
import { FakeMarlin, type FakeMarlinOptions } from './test-fake-marlin.js';

const CUBE = readFileSync(new URL('../../../examples/calibration-cube.stl', import.meta.url));
const GCODE = new Slicer({ scale: 0.25 }).sliceSync(CUBE).gcode;

/** A sender and a simulated Marlin joined by a pair of pipes. */
function connect(printer: FakeMarlinOptions = {}, sender: MarlinOptions = {}) {
  let host: MarlinSender;
  const marlin = new FakeMarlin((text) => host.receive(text), printer);
  host = new MarlinSender((data) => marlin.write(data), sender);
  return { host, marlin };
}

const wait = (ms: number) => new Promise((r) => setTimeout(r, ms));

test('lines are numbered with their checksum (XOR of the bytes before *)', () => {
  assert.equal(numberedLine(0, 'M110 N0'), 'N0 M110 N0*125');
  assert.equal(numberedLine(1, 'G28'), 'N1 G28*18');
  assert.deepEqual(gcodeCommands('; header\nG28 ; home\n\n  M104 S200  \n;end\n'), ['G28', 'M104 S200']);
});

test('a Strata slice streams to Marlin: every command executed once, in order; progress to the end', async () => {
  const progress: number[] = [];
  const { host, marlin } = connect({ busyEvery: 50 }, { onProgress: ({ done, total }) => progress.push(done / total) });
  await host.print(GCODE);
  assert.deepEqual(marlin.executed, gcodeCommands(GCODE));
  assert.ok(marlin.executed.length > 1000);
  assert.equal(progress.at(-1), 1);
  assert.equal(marlin.resends, 0);
});

test('lines garbled on the way are sent again where Marlin asks (Resend:), and run exactly once', async () => {
  const { host, marlin } = connect({ garble: (k) => k % 7 === 3 });
  await host.print(GCODE);
  assert.ok(marlin.resends > 100, `${marlin.resends} resends`);
  assert.deepEqual(marlin.executed, gcodeCommands(GCODE));
});

test('heating: temperature reports keep a long M109 alive past the idle timeout', async () => {
  const { host, marlin } = connect({ heatMs: 400, reportMs: 20 }, { idleTimeoutMs: 150 });
  await host.print('M104 S210\nM109 S210\nG28\n');
  assert.deepEqual(marlin.executed, ['M104 S210', 'M109 S210', 'G28']);
});

test('pause holds the stream after the line in flight; resume goes on', async () => {
  const lines = Array.from({ length: 200 }, (_, i) => `G1 X${i} Y${i}`).join('\n');
  let host!: MarlinSender;
  let paused = -1;
  const c = connect(
    {},
    {
      onProgress: ({ done }) => {
        if (done === 50 && paused < 0) {
          host.pause();
          paused = done;
        }
      },
    },
  );
  host = c.host;
  const printing = host.print(lines);
  await wait(100);
  assert.equal(host.paused, true);
  assert.equal(c.marlin.executed.length, 50, 'nothing more is sent while paused');
  host.resume();
  await printing;
  assert.equal(c.marlin.executed.length, 200);
});

test('cancel stops the stream and turns heaters, fan and motors off', async () => {
  const lines = Array.from({ length: 500 }, (_, i) => `G1 X${i % 200} Y10`).join('\n');
  let host!: MarlinSender;
  const c = connect({}, { onProgress: ({ done }) => done === 100 && host.cancel() });
  host = c.host;
  await assert.rejects(host.print(lines), (e) => e instanceof StrataError && e.code === 'CANCELLED');
  assert.equal(c.marlin.executed.length, 100 + CANCEL_GCODE.length);
  assert.deepEqual(c.marlin.executed.slice(-CANCEL_GCODE.length), CANCEL_GCODE);
});

test('a printer that stops answering, reports a fault or restarts ends the print with one line', async () => {
  const hung = connect({ hangOn: /^G28/ }, { idleTimeoutMs: 100 });
  await assert.rejects(
    hung.host.print('M105\nG28\nG1 X1\n'),
    /^StrataError: the printer stopped answering \(nothing for 0 s\)$|the printer stopped answering/,
  );
  const fault = connect({ faultOn: { command: /^M109/, line: 'Error:Printer halted. kill() called!' } });
  await assert.rejects(
    fault.host.print('G28\nM109 S210\nG1 X1\n'),
    (e) => e instanceof StrataError && e.message === 'the printer reported: Printer halted. kill() called!',
  );
  assert.deepEqual(fault.marlin.executed, ['G28']);
  let host!: MarlinSender;
  host = new MarlinSender(async (data) => {
    if (data.includes('G1 X1')) setTimeout(() => host.receive('start\nMarlin 2.1\n'), 0);
    else setTimeout(() => host.receive('ok\n'), 0);
  });
  await assert.rejects(host.print('G28\nG1 X1\nG1 X2\n'), /the printer restarted/);
  // a board that restarts as the port opens: the count is reset again once it has booted
  let booted = 0;
  const booting = new MarlinSender(async (data) => {
    if (data.startsWith('N0 M110') && booted++ === 0)
      setTimeout(() => booting.receive('start\necho:Marlin 2.1.2\n'), 0);
    else setTimeout(() => booting.receive('ok\n'), 0);
  });
  await booting.print('G28\n');
  assert.equal(booted, 2);
  const broken = new MarlinSender(() => Promise.reject(new Error('The device has been lost.')));
  await assert.rejects(broken.print('G28\n'), /cannot write to the printer: The device has been lost\./);
});
