import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { Measurement } from './measure.js';
import { notRun, relativeToGrid, renderReport, summarize, type BenchReport, type SlicerStats } from './report.js';

const run = (wallSeconds: number, peakMiB: number | null, exitCode = 0): Measurement => ({
  exitCode, signal: null, timedOut: false, spawnError: null, wallSeconds, peakMiB, stderrTail: exitCode === 0 ? '' : 'error: broken mesh\n',
});
const ok = (wallSeconds: number, peakMiB: number): SlicerStats => ({ status: 'ok', wallSeconds, peakMiB, samples: [wallSeconds] });

test('summarize takes medians; a failure wins', () => {
  const s = summarize([run(3, 100), run(1, 90), run(2, 120)]);
  assert.equal(s.status, 'ok');
  assert.equal(s.wallSeconds, 2);
  assert.equal(s.peakMiB, 100);
  assert.deepEqual(s.samples, [3, 1, 2]);
  const f = summarize([run(1, 10), run(1, 10, 2)]);
  assert.equal(f.status, 'failed');
  assert.equal(f.wallSeconds, null);
  assert.match(f.message!, /exit code 2: error: broken mesh/);
  assert.equal(summarize([{ ...run(600, null), exitCode: null, signal: 'SIGKILL', timedOut: true }]).status, 'timeout');
  assert.equal(summarize([run(1, null)]).peakMiB, null);
});

test('relativeToGrid divides by the grid row', () => {
  const rows = relativeToGrid([
    { pattern: 'grid', strata: ok(2, 50) },
    { pattern: 'gyroid', strata: ok(3, 60) },
    { pattern: 'lightning', strata: notRun('skipped') },
  ]);
  assert.deepEqual(rows.map((r) => r.relativeToGrid), [1, 1.5, null]);
});

function report(over: Partial<BenchReport>): BenchReport {
  return {
    startedAt: '2026-01-01T00:00:00Z',
    machine: { cpus: 2, cpuModel: 'Test CPU', node: 'v20', platform: 'linux x64', loadAverage: { start: 0.1, end: 0.2 } },
    threads: 2,
    repeat: 3,
    memoryMethod: 'gnu-time',
    strataCli: { path: '/repo/dist/cli/main.js', built: true },
    peers: { cura: { path: '/usr/bin/CuraEngine', version: 'Cura_SteamEngine version 4.13.0', definitions: '/defs/fdmprinter.def.json' }, prusa: null },
    models: [
      { model: '3DBenchy.stl', triangles: 225154, strata: ok(1.5, 150), cura: ok(3, 60), prusa: notRun('missing') },
      { model: '3DBenchy.3mf', triangles: 225154, strata: { ...notRun('skipped'), status: 'failed', message: 'exit code 1: no 3MF' }, cura: notRun('unsupported'), prusa: notRun('missing') },
    ],
    patternModel: '3DBenchy.stl',
    patterns: relativeToGrid([{ pattern: 'grid', strata: ok(1.5, 150) }, { pattern: 'gyroid', strata: ok(3, 160) }]),
    notes: [],
    ...over,
  };
}

test('renderReport: table, ratio, statuses, pattern section, failure notes', () => {
  const text = renderReport(report({}));
  assert.match(text, /median of 3 runs/);
  assert.match(text, /\/usr\/bin\/time -f %M/);
  const benchy = text.split('\n').find((l) => l.startsWith('3DBenchy.stl'))!;
  assert.deepEqual(benchy.split(/\s{2,}/), ['3DBenchy.stl', '225,154', '1.50', '150', '3.00', '60', '0.50x', '-', '-']);
  const threeMf = text.split('\n').find((l) => l.startsWith('3DBenchy.3mf'))!;
  assert.match(threeMf, /failed/);
  assert.match(threeMf, /n\/a/);
  assert.match(text, /Infill patterns on 3DBenchy\.stl/);
  assert.match(text, /gyroid\s+3\.00\s+2\.00x\s+160/);
  assert.match(text, /Strata on 3DBenchy\.3mf: exit code 1: no 3MF/);
  assert.match(text, /PrusaSlicer: not run/);
  assert.doesNotMatch(text, /machine was busy/);
});

test('renderReport warns when the machine was busy', () => {
  const base = report({});
  const text = renderReport({ ...base, machine: { ...base.machine, loadAverage: { start: 0.2, end: 3.5 } } });
  assert.match(text, /machine was busy \(load average up to 3\.50 on 2 cores\)/);
});

test('renderReport says clearly when the Strata CLI is not built', () => {
  const text = renderReport(
    report({
      strataCli: { path: '/repo/dist/cli/main.js', built: false },
      models: [{ model: 'cube.stl', triangles: 12, strata: notRun('missing', 'strata CLI not built'), cura: ok(0.1, 10), prusa: notRun('missing') }],
      patternModel: null,
      patterns: [],
    }),
  );
  assert.match(text, /strata CLI not built: \/repo\/dist\/cli\/main\.js is missing/);
  assert.match(text.split('\n').find((l) => l.startsWith('cube.stl'))!, /not built/);
  assert.doesNotMatch(text, /Infill patterns/);
});
