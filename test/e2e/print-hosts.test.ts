/**
 * Strata's G-code sent to the real print hosts, from PyPI (see print-hosts.ts): OctoPrint with its virtual
 * printer, and Moonraker. The upload must be in the host's own file list, byte for byte; a wrong key is one
 * line; OctoPrint's virtual printer prints the file to its end; and what the hosts read from the file
 * (OctoPrint's analysis, Moonraker's metadata, which Mainsail and Fluidd show) is what Strata sliced.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';
import { VERSION } from '#strata/pipeline/run.js';
import { sendToPrinter } from '#strata/send/node.js';
import {
  getBytes,
  getJson,
  MOONRAKER_PYTHON,
  OCTOPRINT,
  OCTOPRINT_KEY,
  skipWithout,
  startMoonraker,
  startOctoPrint,
} from './print-hosts.js';

const CUBE = readFileSync(new URL('../../../examples/calibration-cube.stl', import.meta.url));

/** A small, quick print: the calibration cube at a quarter of its size (5 mm), with thumbnails. */
function sliceSmall(options: Record<string, unknown> = {}) {
  return new Slicer({ scale: 0.25, thumbnails: '32x32,300x300', threads: 1, ...options }).sliceSync(CUBE);
}

const same = (a: Uint8Array, b: Uint8Array) => a.length === b.length && Buffer.from(a).equals(Buffer.from(b));

async function failure(p: Promise<unknown>): Promise<string> {
  try {
    await p;
  } catch (e) {
    assert.ok(e instanceof StrataError, String(e));
    return e.message;
  }
  assert.fail('it succeeded');
}

test('OctoPrint: the upload is in its file list byte for byte; a wrong key is one line; the virtual printer prints it to its end', {
  skip: skipWithout(OCTOPRINT, 'OctoPrint'),
  timeout: 300_000,
}, async () => {
  const { gcode, stats } = sliceSmall();
  const host = await startOctoPrint(215);
  const key = { 'X-Api-Key': OCTOPRINT_KEY };
  try {
    const bytes = new TextEncoder().encode(gcode);
    let lastSent = 0;
    const r = await sendToPrinter(bytes, {
      to: 'octoprint',
      url: host.url,
      apiKey: OCTOPRINT_KEY,
      name: 'cube.gcode',
      onProgress: ({ sent }) => (lastSent = sent),
    });
    assert.deepEqual({ name: r.name, started: r.started }, { name: 'cube.gcode', started: false });
    assert.ok(lastSent > bytes.length, 'progress up to the whole form');
    const list = (await getJson(`${host.url}/api/files/local?recursive=true`, key)) as {
      files: Array<{ name: string; size: number }>;
    };
    assert.equal(list.files.find((f) => f.name === 'cube.gcode')?.size, bytes.length);
    assert.ok(
      same(await getBytes(`${host.url}/downloads/files/local/cube.gcode`, key), bytes),
      'the host has the file byte for byte',
    );

    assert.match(
      await failure(sendToPrinter(bytes, { to: 'octoprint', url: host.url, apiKey: 'WRONG', name: 'cube.gcode' })),
      /^OctoPrint at http:\/\/127\.0\.0\.1:\d+ refused the API key \(403[^)]*\): check apiKey/,
    );
    assert.match(
      await failure(sendToPrinter(bytes, { to: 'octoprint', url: host.url, name: 'cube.gcode' })),
      /needs an API key \(403/,
    );
    // not connected to a printer: uploaded, and says it did not print
    const idle = await sendToPrinter(bytes, {
      to: 'octoprint',
      url: host.url,
      apiKey: OCTOPRINT_KEY,
      name: 'cube.gcode',
      print: true,
    });
    assert.equal(idle.started, false);
    assert.match(idle.notStarted!, /not connected/);

    // connect the virtual printer, send with print: it runs to its end
    const connect = await fetch(`${host.url}/api/connection`, {
      method: 'POST',
      headers: { ...key, 'Content-Type': 'application/json' },
      body: JSON.stringify({ command: 'connect', port: 'VIRTUAL', baudrate: 115200 }),
    });
    assert.equal(connect.status, 204);
    for (let i = 0; ; i++) {
      const c = (await getJson(`${host.url}/api/connection`, key)) as { current: { state: string } };
      if (c.current.state === 'Operational') break;
      assert.ok(i < 120, `the virtual printer connects (${c.current.state})`);
      await new Promise((res) => setTimeout(res, 250));
    }
    const printing = await sendToPrinter(bytes, {
      to: 'octoprint',
      url: host.url,
      apiKey: OCTOPRINT_KEY,
      name: 'cube.gcode',
      print: true,
    });
    assert.equal(printing.started, true);
    let job: { state: string; progress: { completion: number | null } } = { state: '', progress: { completion: null } };
    const deadline = Date.now() + 240_000;
    let seenPrinting = false;
    for (;;) {
      job = (await getJson(`${host.url}/api/job`, key)) as typeof job;
      if (job.state.startsWith('Printing')) seenPrinting = true;
      if (seenPrinting && job.state === 'Operational') break;
      assert.ok(
        Date.now() < deadline,
        `the print ends (${job.state}, ${job.progress.completion} %)\n${host.log().slice(-2000)}`,
      );
      await new Promise((res) => setTimeout(res, 500));
    }
    type FileInfo = {
      prints?: { last?: { success: boolean } };
      gcodeAnalysis?: {
        dimensions: { height: number };
        filament: { tool0: { length: number } };
        estimatedPrintTime: number;
        printingArea: { minX: number; maxX: number; minY: number; maxY: number };
      };
    };
    // OctoPrint analyses an uploaded file in the background, and not while it prints
    let info: FileInfo = {};
    for (const until = Date.now() + 60_000; ; ) {
      info = (await getJson(`${host.url}/api/files/local/cube.gcode`, key)) as FileInfo;
      if (info.gcodeAnalysis?.dimensions) break;
      assert.ok(Date.now() < until, 'OctoPrint analyses the file');
      await new Promise((res) => setTimeout(res, 500));
    }
    assert.equal(info.prints?.last?.success, true, 'printed to its end');
    // OctoPrint's own analysis of the file agrees with the slice (its printing area and filament include the start G-code's prime line)
    const a = info.gcodeAnalysis!;
    assert.ok(
      Math.abs(a.dimensions.height - stats.bounds.maxZ) < 0.01,
      `height ${a.dimensions.height} vs ${stats.bounds.maxZ}`,
    );
    assert.ok(
      a.filament.tool0.length >= stats.filamentMm - 0.5 && a.filament.tool0.length <= stats.filamentMm + 40,
      `filament ${a.filament.tool0.length} vs ${stats.filamentMm} mm`,
    );
    assert.ok(
      a.printingArea.minX <= stats.bounds.minX &&
        a.printingArea.maxX >= stats.bounds.maxX &&
        a.printingArea.minY <= stats.bounds.minY &&
        a.printingArea.maxY >= stats.bounds.maxY,
    );
    assert.ok(a.estimatedPrintTime > 0);
  } finally {
    await host.stop();
  }
});

test('Moonraker: the upload is in its file list byte for byte; a wrong key is one line; with no Klipper it says the print did not start', {
  skip: skipWithout(MOONRAKER_PYTHON, 'Moonraker'),
  timeout: 120_000,
}, async () => {
  const { gcode } = sliceSmall();
  const host = await startMoonraker();
  try {
    const apiKey = ((await getJson(`${host.url}/access/api_key`)) as { result: string }).result;
    const bytes = new TextEncoder().encode(gcode);
    const r = await sendToPrinter(bytes, { to: 'moonraker', url: host.url, apiKey, name: 'cube.gcode' });
    assert.deepEqual({ name: r.name, started: r.started }, { name: 'cube.gcode', started: false });
    const list = (await getJson(`${host.url}/server/files/list?root=gcodes`)) as {
      result: Array<{ path: string; size: number }>;
    };
    assert.equal(list.result.find((f) => f.path === 'cube.gcode')?.size, bytes.length);
    assert.ok(
      same(await getBytes(`${host.url}/server/files/gcodes/cube.gcode`), bytes),
      'the host has the file byte for byte',
    );
    assert.match(
      await failure(sendToPrinter(bytes, { to: 'moonraker', url: host.url, apiKey: 'WRONG', name: 'cube.gcode' })),
      /^Moonraker at http:\/\/127\.0\.0\.1:\d+ refused the API key \(401 Unauthorized\)/,
    );
    const printing = await sendToPrinter(bytes, {
      to: 'moonraker',
      url: host.url,
      apiKey,
      name: 'cube2.gcode',
      print: true,
    });
    assert.equal(printing.started, false);
    assert.match(printing.notStarted!, /Klipper is not ready/);
  } finally {
    await host.stop();
  }
});

test("Moonraker's metadata (what Mainsail and Fluidd show) reads Strata's G-code right", {
  skip: skipWithout(MOONRAKER_PYTHON, 'Moonraker'),
  timeout: 120_000,
}, async () => {
  const host = await startMoonraker();
  try {
    for (const [name, options] of [
      ['marlin.gcode', {}],
      ['klipper.gcode', { printer: 'creality-k1', filament: 'petg', layerHeight: 0.16, firstLayerHeight: 0.24 }],
      ['prusa.gcode', { printer: 'Original Prusa MK4', filament: 'PrusamentPLA', layerHeight: 0.15 }],
    ] as const) {
      const { gcode, stats } = sliceSmall(options);
      const cfg = new Slicer(options).config;
      await sendToPrinter(gcode, { to: 'moonraker', url: host.url, name });
      const m = (
        (await getJson(`${host.url}/server/files/metadata?filename=${name}`)) as { result: Record<string, unknown> }
      ).result;
      const near = (key: string, want: number, tol: number) =>
        assert.ok(
          typeof m[key] === 'number' && Math.abs((m[key] as number) - want) <= tol,
          `${name} ${key}: ${m[key]} vs ${want}`,
        );
      assert.equal(m.slicer, 'Strata', name);
      assert.equal(m.slicer_version, VERSION, name);
      near('layer_height', cfg.layerHeight, 1e-6);
      near('first_layer_height', cfg.firstLayerHeight, 1e-6);
      near('object_height', stats.bounds.maxZ, 1e-6);
      near('estimated_time', stats.printTimeSeconds, 1.5);
      near('filament_total', stats.filamentMm, 0.1);
      near('filament_weight_total', stats.filamentGrams, 0.01);
      near('nozzle_diameter', cfg.nozzleDiameter, 1e-6);
      near('first_layer_extr_temp', cfg.firstLayerNozzleTemperature ?? cfg.nozzleTemperature, 1e-6);
      near('first_layer_bed_temp', cfg.firstLayerBedTemperature ?? cfg.bedTemperature, 1e-6);
      near('layer_count', stats.layers, 0);
      assert.equal(typeof m.filament_type, 'string', name);
      assert.equal(typeof m.filament_name, 'string', name);
      const thumbs = m.thumbnails as Array<{ width: number; height: number; size: number }> | undefined;
      assert.deepEqual(thumbs?.map((t) => `${t.width}x${t.height}`).sort(), ['300x300', '32x32'], `${name} thumbnails`);
    }
  } finally {
    await host.stop();
  }
});
