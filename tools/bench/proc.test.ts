import { test } from 'node:test';
import assert from 'node:assert/strict';
import { clockTicksPerSecond, parseMachineTicks, parseProcStat, readMachineTicks, readSelfTimes } from './proc.js';

test('parseProcStat counts fields from the last ")" (command names may hold spaces and parentheses)', () => {
  // pid (comm) state ppid pgrp session tty tpgid flags minflt cminflt majflt cmajflt utime stime cutime cstime …
  const line = '4242 (node (a) b) S 1 4242 4242 0 -1 4194560 1000 20 0 0 150 30 812 95 20 0 11 0 100 1000000 5000';
  assert.deepEqual(parseProcStat(line), { utime: 150, stime: 30, cutime: 812, cstime: 95 });
  assert.equal(parseProcStat('garbage'), null);
  assert.equal(parseProcStat('1 (x) S 1 2 3'), null);
});

test('parseMachineTicks: busy is user + nice + system + irq + softirq + steal; guest is not counted twice', () => {
  const text = 'cpu  100 5 40 1000 7 3 2 10 50 0\ncpu0 50 2 20 500 3 1 1 5 25 0\nintr 1 2 3\n';
  assert.deepEqual(parseMachineTicks(text), { busy: 100 + 5 + 40 + 3 + 2 + 10, total: 160 + 1000 + 7 });
  assert.equal(parseMachineTicks('intr 1 2\n'), null);
});

test('on Linux the readers work and the counters only grow', {
  skip: process.platform !== 'linux' && 'not Linux',
}, () => {
  const a = readSelfTimes();
  const m = readMachineTicks();
  assert.ok(a && m);
  let x = 0;
  for (let i = 0; i < 1e6; i++) x += i;
  assert.ok(x > 0);
  const b = readSelfTimes()!;
  assert.ok(b.utime + b.stime >= a.utime + a.stime);
  assert.ok(readMachineTicks()!.busy >= m.busy);
  assert.ok(Number.isInteger(clockTicksPerSecond()) && clockTicksPerSecond() > 0);
});
