import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  detectMemoryMethod,
  failureReason,
  measureCommand,
  parseGnuTimeOutput,
  parseVmHwm,
  type MemoryMethod,
} from './measure.js';

test('parseGnuTimeOutput: last line is KiB, earlier status lines ignored', () => {
  assert.equal(parseGnuTimeOutput('61440\n'), 60);
  assert.equal(parseGnuTimeOutput('Command exited with non-zero status 1\n2048\n'), 2);
  assert.equal(parseGnuTimeOutput(''), null);
  assert.equal(parseGnuTimeOutput('Command terminated by signal 9\n'), null);
});

test('parseVmHwm reads the kernel high-water mark', () => {
  assert.equal(parseVmHwm('Name:\tnode\nVmPeak:\t  999 kB\nVmHWM:\t   51200 kB\nVmRSS:\t 40000 kB\n'), 50);
  assert.equal(parseVmHwm('Name:\tzombie\nState:\tZ\n'), null);
});

const methods: MemoryMethod[] = [...new Set<MemoryMethod>([detectMemoryMethod(), 'proc-poll'])].filter(
  (m) => m !== 'proc-poll' || process.platform === 'linux',
);

for (const method of methods) {
  test(`measureCommand (${method}): wall time and a peak that sees a 64 MiB allocation`, async () => {
    const script =
      'const b = Buffer.alloc(64 * 1024 * 1024, 1); setTimeout(() => process.exit(b[0] === 1 ? 0 : 1), 60);';
    const m = await measureCommand(process.execPath, ['-e', script], { method, timeoutMs: 20_000 });
    assert.equal(failureReason(m), '');
    assert.equal(m.exitCode, 0);
    assert.ok(m.wallSeconds > 0.05 && m.wallSeconds < 20, `wall ${m.wallSeconds}`);
    assert.ok(m.peakMiB !== null && m.peakMiB >= 64 && m.peakMiB < 1024, `peak ${m.peakMiB}`);
  });
}

/** A node script that spends `ms` of its own CPU time (by its own clock, so the machine's load does not matter). */
const burn = (ms: number) =>
  `const t0 = process.cpuUsage(); for (;;) { const u = process.cpuUsage(t0); if (u.user + u.system >= ${ms * 1000}) break; }`;

test('measureCommand: CPU time from the kernel covers the process, its threads and its waited-for children', {
  skip: process.platform !== 'linux' && 'CPU accounting reads /proc',
}, async () => {
  // main thread 200 ms, two worker threads 200 ms each, a child process 200 ms: at least 0.8 s in all. One at a
  // time: process.cpuUsage in a worker counts the whole process, so two burning at once would each stop early
  const script = `
    const { Worker } = require('node:worker_threads');
    const { spawnSync } = require('node:child_process');
    const burn = ${JSON.stringify(burn(200))};
    const work = () => new Promise((r) => new Worker(burn, { eval: true }).on('exit', r));
    work().then(work).then(() => {
      spawnSync(process.execPath, ['-e', burn], { stdio: 'inherit' });
      eval(burn);
      process.exit(0);
    });
  `;
  const m = await measureCommand(process.execPath, ['-e', script], { method: 'none', timeoutMs: 60_000 });
  assert.equal(failureReason(m), '');
  assert.ok(m.cpuSeconds !== null && m.cpuSeconds >= 0.78, `cpu ${m.cpuSeconds}`);
  // and a child that sleeps uses next to none
  const idle = await measureCommand(process.execPath, ['-e', 'setTimeout(() => {}, 300)'], {
    method: 'none',
    timeoutMs: 60_000,
  });
  assert.ok(
    idle.cpuSeconds !== null && idle.cpuSeconds < 0.25 && idle.cpuSeconds < m.cpuSeconds / 3,
    `idle cpu ${idle.cpuSeconds}`,
  );
});

test('measureCommand reports a failing command with its last stderr line', async () => {
  const m = await measureCommand(process.execPath, ['-e', 'console.error("bad model"); process.exit(3)'], {
    method: detectMemoryMethod(),
    timeoutMs: 20_000,
  });
  assert.equal(m.exitCode, 3);
  assert.equal(failureReason(m), 'exit code 3: bad model');
});

test('measureCommand kills a command that runs past its timeout', async () => {
  const m = await measureCommand(process.execPath, ['-e', 'setTimeout(() => {}, 60000)'], {
    method: detectMemoryMethod(),
    timeoutMs: 300,
  });
  assert.equal(m.timedOut, true);
  assert.ok(m.wallSeconds < 10);
  assert.match(failureReason(m), /^timed out/);
});

test('measureCommand reports a missing executable instead of throwing', async () => {
  const m = await measureCommand('/nonexistent/slicer', [], { method: 'none', timeoutMs: 5000 });
  assert.notEqual(failureReason(m), '');
});
