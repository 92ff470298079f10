/**
 * The page's "Send to printer": to the real Moonraker (allowing the page's origin, as the README says to)
 * the file lands in its list byte for byte as the page's Download gives it, the host is remembered across a
 * reload, a wrong key is one line; and over USB (Web Serial, given a simulated Marlin as the port) every
 * command reaches the printer once, with a garbled line sent again.
 */
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import type { Server } from 'node:http';
import { fileURLToPath } from 'node:url';
import type { Page } from 'playwright-core';
import { startServer } from '#strata/cli/serve.js';
import { gcodeCommands } from '#strata/send/marlin-serial.js';
import { browserMissing, launchChromium, type Browser } from './browser.js';
import { getBytes, getJson, MOONRAKER_PYTHON, skipWithout, startMoonraker, type RunningHost } from './print-hosts.js';

const CUBE = fileURLToPath(new URL('../../../examples/calibration-cube.stl', import.meta.url));
const missing = browserMissing() || skipWithout(MOONRAKER_PYTHON, 'Moonraker');

/** In the page, before its scripts: a Web Serial port wired to a tiny Marlin that checks numbers and checksums. */
function fakeSerial(): void {
  const w = window as unknown as { __marlin: { executed: string[]; resends: number } };
  const marlin = (w.__marlin = { executed: [] as string[], resends: 0 });
  let out!: ReadableStreamDefaultController<Uint8Array>;
  let expected = 1;
  let garbled = false;
  let pending = '';
  const say = (text: string) => out.enqueue(new TextEncoder().encode(text));
  const handle = (raw: string) => {
    const m = /^N(\d+) (.*)\*(\d+)$/.exec(raw.trim());
    let cs = 0;
    const body = raw.slice(0, raw.lastIndexOf('*'));
    for (let i = 0; i < body.length; i++) cs ^= body.charCodeAt(i);
    if (!m || cs !== Number(m[3]))
      return say(`Error:checksum mismatch, Last Line: ${expected - 1}\nResend: ${expected}\nok\n`);
    if (m[2]!.startsWith('M110')) {
      expected = 1;
      return say('ok\n');
    }
    // the fifth line arrives garbled once (a noisy cable)
    if (Number(m[1]) === 5 && !garbled) {
      garbled = true;
      marlin.resends++;
      return say(`Error:checksum mismatch, Last Line: 4\nResend: 5\nok\n`);
    }
    if (Number(m[1]) !== expected)
      return say(`Error:Line Number is not Last Line Number+1, Last Line: ${expected - 1}\nResend: ${expected}\nok\n`);
    expected++;
    marlin.executed.push(m[2]!);
    setTimeout(() => say('ok\n'), 0);
  };
  const port = {
    readable: null as ReadableStream<Uint8Array> | null,
    writable: null as WritableStream<Uint8Array> | null,
    async open() {
      port.readable = new ReadableStream<Uint8Array>({ start: (c) => void (out = c) });
      port.writable = new WritableStream<Uint8Array>({
        write(chunk) {
          pending += new TextDecoder().decode(chunk);
          let nl: number;
          while ((nl = pending.indexOf('\n')) >= 0) {
            handle(pending.slice(0, nl));
            pending = pending.slice(nl + 1);
          }
        },
      });
    },
    async close() {},
  };
  Object.defineProperty(navigator, 'serial', { value: { requestPort: async () => port }, configurable: true });
}

describe('the page sends to a printer', { skip: missing || false }, () => {
  let server: Server;
  let url: string;
  let browser: Browser;
  let moonraker: RunningHost;

  before(async () => {
    ({ server, url } = await startServer({ port: 0 }));
    browser = await launchChromium();
    moonraker = await startMoonraker();
  });

  after(async () => {
    await browser?.close();
    server?.close();
    await moonraker?.stop();
  });

  async function slicedPage(): Promise<{ page: Page; gcode: Buffer }> {
    const page = await browser.context.newPage();
    await page.addInitScript(fakeSerial);
    await page.goto(url);
    await page.waitForSelector('html[data-ready="true"]');
    await page.getByLabel('Open model', { exact: true }).setInputFiles(CUBE);
    await page.waitForFunction(() => document.querySelectorAll('#object-list li').length === 1);
    await page.getByRole('button', { name: 'Slice', exact: true }).click();
    await page.waitForSelector('#stat-layers', { timeout: 120_000 });
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Download G-code', exact: true }).click(),
    ]);
    const gcode = readFileSync((await download.path())!);
    return { page, gcode };
  }

  test('to Moonraker: in its file list byte for byte; the host remembered; a wrong key one line', {
    timeout: 240_000,
  }, async () => {
    const { page, gcode } = await slicedPage();
    await page.getByRole('button', { name: 'Send to printer', exact: true }).click();
    const dialog = page.getByRole('dialog', { name: 'Send to printer' });
    await dialog.getByLabel('Moonraker').check();
    await dialog.getByLabel('Address').fill(moonraker.url);
    await dialog.getByLabel('start printing').uncheck();
    await dialog.getByRole('button', { name: 'Send', exact: true }).click();
    const status = dialog.getByRole('status');
    await status.filter({ hasText: /^Sent |\S/ }).waitFor({ timeout: 60_000 });
    await page.waitForFunction(
      () => !/^Uploading/.test(document.getElementById('send-status')!.textContent ?? ''),
      undefined,
      { timeout: 60_000 },
    );
    assert.match(
      (await status.textContent())!,
      /^Sent calibration-cube\.gcode to Moonraker at http:\/\/127\.0\.0\.1:\d+\.$/,
    );
    const list = (await getJson(`${moonraker.url}/server/files/list?root=gcodes`)) as {
      result: Array<{ path: string; size: number }>;
    };
    assert.equal(list.result.find((f) => f.path === 'calibration-cube.gcode')?.size, gcode.length);
    assert.ok(
      Buffer.from(await getBytes(`${moonraker.url}/server/files/gcodes/calibration-cube.gcode`)).equals(gcode),
      "the host has the page's G-code byte for byte",
    );

    await dialog.getByLabel('API key').fill('WRONG');
    await dialog.getByRole('button', { name: 'Send', exact: true }).click();
    await status.filter({ hasText: /refused the API key/ }).waitFor({ timeout: 30_000 });
    assert.match(
      (await status.textContent())!,
      /^Moonraker at http:\/\/127\.0\.0\.1:\d+ refused the API key \(401 Unauthorized\): check the API key field/,
    );

    // remembered: a new page opens the dialog on Moonraker at that address (the key, not asked to be, is not)
    const again = await browser.context.newPage();
    await again.goto(url);
    await again.waitForSelector('html[data-ready="true"]');
    await again.evaluate(() => (document.getElementById('send-dialog') as HTMLDialogElement).showModal());
    assert.equal(await again.getByLabel('Address').inputValue(), moonraker.url);
    assert.equal(await again.getByLabel('Moonraker').isChecked(), true);
    assert.equal(await again.getByLabel('API key').inputValue(), '');
    await again.close();
    await page.close();
  });

  test("the page takes the seeds' library's, PrusaSlicer's and Cura's preset names in a settings file", {
    timeout: 120_000,
  }, async () => {
    const page = await browser.context.newPage();
    await page.goto(url);
    await page.waitForSelector('html[data-ready="true"]');
    for (const [printer, filament, id, fid] of [
      ['Ender3', 'GenericPLA', 'creality-ender-3', 'pla'],
      ['Original Prusa MK4', 'PrusamentPETG', 'prusa-mk4', 'prusament-petg'],
      ['creality_cr10s5', 'generic_petg', 'creality-cr-10-s5', 'petg'],
    ]) {
      await page.getByLabel('Import settings', { exact: true }).setInputFiles({
        name: 'profile.json',
        mimeType: 'application/json',
        buffer: Buffer.from(JSON.stringify({ printer, filament })),
      });
      await page.waitForFunction(
        ([p, f]) =>
          (document.getElementById('printer') as HTMLSelectElement).value === p &&
          (document.getElementById('filament') as HTMLSelectElement).value === f,
        [id, fid],
      );
    }
    await page.close();
  });

  test('over USB (Web Serial): every command once, in order, a garbled line sent again', {
    timeout: 240_000,
  }, async () => {
    const { page, gcode } = await slicedPage();
    await page.getByRole('button', { name: 'Send to printer', exact: true }).click();
    const dialog = page.getByRole('dialog', { name: 'Send to printer' });
    await dialog.getByLabel('USB (Marlin)').check();
    await dialog.getByRole('button', { name: 'Send', exact: true }).click();
    await dialog.getByRole('status').filter({ hasText: 'every line sent' }).waitFor({ timeout: 180_000 });
    const marlin = await page.evaluate(
      () => (window as unknown as { __marlin: { executed: string[]; resends: number } }).__marlin,
    );
    assert.equal(marlin.resends, 1);
    assert.deepEqual(marlin.executed, gcodeCommands(gcode.toString('utf8')));
    await page.close();
  });
});
