import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as THREE from 'three';
import { STLExporter } from 'three/examples/jsm/exporters/STLExporter.js';
// the package's own export, as a user imports it
import PolysliceDefault, {
  Filament,
  listAvailableFilaments,
  listAvailablePrinters,
  Polyslice,
  Printer,
} from 'strata-slicer/polyslice';
import { Slicer } from '#strata/api/slicer.js';
import { StrataError } from '#strata/errors.js';

const CLI = fileURLToPath(new URL('../../../dist/cli/main.js', import.meta.url));

/** A 20 × 20 × 10 mm box with a 6 mm hole, as three.js users build one (Z up, as the seeds' library slices). */
function part(): THREE.Mesh {
  const shape = new THREE.Shape();
  shape.moveTo(0, 0).lineTo(20, 0).lineTo(20, 20).lineTo(0, 20).lineTo(0, 0);
  const hole = new THREE.Path();
  hole.absarc(10, 10, 3, 0, Math.PI * 2, true);
  shape.holes.push(hole);
  const mesh = new THREE.Mesh(
    new THREE.ExtrudeGeometry(shape, { depth: 10, bevelEnabled: false, curveSegments: 24 }),
    new THREE.MeshBasicMaterial(),
  );
  mesh.name = 'part';
  return mesh;
}

/** `strata slice` on the mesh exported as STL, with these flags: the G-code. */
function strataSlice(mesh: THREE.Object3D, ...flags: string[]): string {
  const dir = mkdtempSync(join(tmpdir(), 'strata-polyslice-'));
  mesh.updateMatrixWorld(true);
  const stl = new STLExporter().parse(mesh, { binary: true }) as DataView;
  const file = join(dir, 'part.stl');
  writeFileSync(file, new Uint8Array(stl.buffer, stl.byteOffset, stl.byteLength));
  const r = spawnSync(process.execPath, [CLI, 'slice', file, '-o', join(dir, 'part.gcode'), '-q', ...flags], {
    encoding: 'utf8',
  });
  assert.equal(r.status, 0, r.stderr);
  return readFileSync(join(dir, 'part.gcode'), 'utf8');
}

/** Three.js's GCodeExporter's parse(), as its example runs it in Node (its code is three.js's; these are its calls). */
function exporterParse(
  Classes: { Polyslice: typeof Polyslice; Printer: typeof Printer; Filament: typeof Filament },
  mesh: THREE.Object3D,
  options: Record<string, unknown> = {},
): string {
  const settings = {
    printer: 'Ender3',
    filament: 'GenericPLA',
    layerHeight: 0.2,
    infillDensity: 20,
    infillPattern: 'grid',
    verbose: false,
    ...options,
  };
  const printer = new Classes.Printer(settings.printer as string);
  const filament = new Classes.Filament(settings.filament as string);
  const slicer = new Classes.Polyslice({
    printer,
    filament,
    layerHeight: settings.layerHeight as number,
    infillPattern: settings.infillPattern as 'grid',
    infillDensity: settings.infillDensity as number,
    verbose: settings.verbose as boolean,
  });
  return slicer.slice(mesh);
}

test("three.js's GCodeExporter example with Strata's classes gives strata slice's G-code for the same settings", () => {
  const mesh = part();
  const gcode = exporterParse({ Polyslice, Printer, Filament }, mesh, { printer: 'CR10', filament: 'PrusamentPLA' });
  assert.equal(
    gcode,
    strataSlice(
      mesh,
      '--printer',
      'CR10',
      '--filament',
      'PrusamentPLA',
      '--layer-height',
      '0.2',
      '--infill-density',
      '20',
      '--infill-pattern',
      'grid',
    ),
  );
  assert.match(gcode, /^M104 S215|M109 S2[12]\d/m);
  // the default export carries the classes as the seeds' library's global does (Polyslice.Polyslice…)
  assert.equal(exporterParse(PolysliceDefault, mesh), exporterParse({ Polyslice, Printer, Filament }, mesh));
});

test("the seeds' documented usage: skin, infill and automatic configuration, as Strata's own slice with the same settings", () => {
  const mesh = part();
  // SKIN.md
  const skin = new Polyslice({
    shellSkinThickness: 0.8,
    infillSpeed: 60,
    perimeterSpeed: 45,
    nozzleDiameter: 0.4,
    nozzleTemperature: 200,
    bedTemperature: 60,
  });
  skin.setShellSkinThickness(1.0);
  assert.equal(skin.getShellSkinThickness(), 1.0);
  const a = skin.slice(mesh);
  assert.equal(a, skin.gcode);
  assert.equal(
    a,
    new Slicer({
      shellSkinThickness: 1.0,
      infillSpeed: 60,
      perimeterSpeed: 45,
      nozzleDiameter: 0.4,
      nozzleTemperature: 200,
      bedTemperature: 60,
    }).sliceSync(mesh).gcode,
  );
  // INFILL.md
  const infill = new Polyslice({
    infillDensity: 20,
    infillPattern: 'gyroid',
    nozzleTemperature: 200,
    bedTemperature: 60,
  })
    .setInfillPatternCentering('global')
    .setInfillPattern('hexagons');
  assert.equal(infill.getInfillPattern(), 'hexagons');
  assert.equal(
    infill.slice(mesh),
    new Slicer({
      infillDensity: 20,
      infillPattern: 'hexagons',
      infillPatternCentering: 'global',
      nozzleTemperature: 200,
      bedTemperature: 60,
    }).sliceSync(mesh).gcode,
  );
  // API.md: automatic configuration, custom options over the filament's
  const auto = new Polyslice({
    printer: new Printer('Ender3'),
    filament: new Filament('GenericPLA'),
    bedTemperature: 0,
  });
  assert.equal(auto.getBedTemperature(), 0);
  assert.equal(auto.getNozzleTemperature(), new Filament('GenericPLA').getNozzleTemperature());
  assert.equal(auto.getBuildPlateWidth(), 220);
  assert.match(auto.slice(mesh), /^M140 S0/m);
});

test("where the seeds' library is wrong: every mesh of a group, with its parents' transforms, set down on the bed", () => {
  const group = new THREE.Group();
  const a = part();
  const b = part();
  b.position.set(40, 0, 0);
  group.add(a, b);
  group.scale.set(1, 1, 2);
  group.position.set(0, 0, 30); // floating in mid-air
  const slicer = new Polyslice({ adhesionEnabled: false });
  slicer.slice(group);
  const box = slicer.stats!.bounds;
  assert.ok(Math.abs(box.maxX - box.minX - 60) < 0.5, `both meshes printed: ${box.maxX - box.minX} mm wide`);
  assert.ok(Math.abs(box.maxZ - 20) < 0.25, `the parent's scale applies: ${box.maxZ} mm tall`);
  assert.ok(Math.abs(box.minZ - 0.2) < 1e-9, `it starts on the bed: first layer at ${box.minZ}`);
  assert.deepEqual(group.position.toArray(), [0, 0, 30], 'the scene is not changed');
  // the same placement as the bytes of the same triangles
  assert.equal(slicer.gcode, new Polyslice({ adhesionEnabled: false }).slice(group.clone()));
});

test("units: lengths, speeds, temperatures and angles in the caller's units, kept in Strata's", () => {
  const s = new Polyslice({
    lengthUnit: 'inches',
    speedUnit: 'inchSecond',
    temperatureUnit: 'fahrenheit',
    angleUnit: 'radian',
    layerHeight: 0.2 / 25.4,
    perimeterSpeed: 1,
    nozzleTemperature: 410,
    supportThreshold: Math.PI / 4,
  });
  assert.ok(Math.abs(s.config.layerHeight - 0.2) < 1e-9);
  assert.ok(Math.abs(s.config.perimeterSpeed - 25.4) < 1e-9);
  assert.ok(Math.abs(s.config.nozzleTemperature - 210) < 1e-9);
  assert.ok(Math.abs(s.config.supportThreshold - 45) < 1e-9);
  assert.ok(Math.abs(s.getLayerHeight() - 0.2 / 25.4) < 1e-12);
  s.setLengthUnit('millimeters').setTemperatureUnit('kelvin').setSpeedUnit('meterSecond');
  assert.ok(Math.abs(s.getLayerHeight() - 0.2) < 1e-9);
  assert.ok(Math.abs(s.getNozzleTemperature() - 483.15) < 1e-9);
  assert.ok(Math.abs(s.getPerimeterSpeed() - 0.0254) < 1e-12);
  assert.equal(s.getLengthUnit(), 'millimeters');
  assert.throws(() => s.setLengthUnit('furlongs' as never), /lengthUnit must be one of millimeters, inches/);
});

test("getters and setters: chainable, validated with the option's name, kept options read back", () => {
  const s = new Polyslice();
  assert.equal(s.setInfillDensity(35), s, 'setters return the slicer');
  assert.equal(s.getInfillDensity(), 35);
  assert.throws(
    () => s.setInfillDensity(150),
    (e) => e instanceof StrataError && /^infillDensity: /.test(e.message),
  );
  assert.equal(s.getInfillDensity(), 35, 'a refused value changes nothing');
  assert.throws(() => s.setInfillPattern('zigzag' as never), StrataError);
  assert.equal(s.setBuzzer(false).getBuzzer(), false);
  assert.equal(s.setCoordinatePrecision(2).getCoordinatePrecision(), 2);
  assert.throws(() => s.setPositioningMode('relative'), /absolute/);
  assert.equal(s.setExtrusionMultiplier(1.05).config.flowRate, 105);
  assert.equal(s.getExtrusionMultiplier(), 1.05);
  assert.equal(s.setBrimLineCount(10).config.brimWidth, 4);
  assert.equal(s.getBrimLineCount(), 10);
  assert.equal(
    new Polyslice({ brimLineCount: 10, nozzleDiameter: 0.6 }).config.brimWidth,
    6,
    'lines of the nozzle given with them',
  );
  assert.equal(s.setSupportGap(0.6).config.supportXYGap, 0.6);
  // adhesion: enabled and type together make Strata's adhesionType
  assert.equal(s.setAdhesionEnabled(false).config.adhesionType, 'none');
  assert.equal(s.setAdhesionType('brim').getAdhesionType(), 'brim');
  assert.equal(s.getAdhesionEnabled(), false);
  assert.equal(s.setAdhesionEnabled(true).config.adhesionType, 'brim');
  assert.throws(() => new Polyslice({ bogus: 1 } as never), /unknown Polyslice option "bogus"/);
  // Strata's own settings are options too, in Strata's units
  const strata = new Polyslice({ lengthUnit: 'inches', wallCount: 3, upAxis: 'y', brimWidth: 5, adhesionType: 'brim' });
  assert.equal(strata.config.wallCount, 3);
  assert.equal(strata.config.upAxis, 'y');
  assert.equal(strata.config.brimWidth, 5);
  assert.throws(() => new Polyslice({ layerHeight: 'thin' as never }), /layerHeight must be a number/);
});

test("printers and filaments: the seeds' names, facts from the presets, changes flow into the slice", () => {
  for (const name of ['Ender3', 'CR10', 'PrusaMK4', 'BambuLabX1Carbon', 'creality-ender-3', 'Original Prusa MK4'])
    assert.ok(new Printer(name).presetId, name);
  for (const name of ['GenericPLA', 'PrusamentPLA', 'GenericPETG', 'pla', 'generic_pla'])
    assert.ok(new Filament(name).presetId, name);
  const printers = listAvailablePrinters();
  for (const name of ['Ender3', 'CR10', 'UltimakerS5', 'prusa-core-one']) assert.ok(printers.includes(name), name);
  for (const name of printers) assert.doesNotThrow(() => new Printer(name), name);
  const filaments = listAvailableFilaments();
  for (const name of ['GenericPLA', 'PrusamentPLA', 'peek']) assert.ok(filaments.includes(name), name);
  for (const name of filaments) assert.doesNotThrow(() => new Filament(name), name);
  assert.deepEqual(new Printer('Ender3').getSize(), { x: 220, y: 220, z: 250 });
  assert.equal(new Printer('CR10').getNozzle(0)!.diameter, 0.4);
  assert.equal(new Printer('BambuLabX1Carbon').getHeatedVolume(), true);
  assert.equal(new Filament('PrusamentPETG').getType(), 'petg');
  assert.equal(new Filament('GenericTPU').getRetractionDistance(), 1);
  assert.equal(new Filament('GenericPLA').getRetractionDistance(), null, "PLA retracts by the printer's extruder");
  assert.throws(() => new Printer('Ender99'), /unknown printer "Ender99" \(did you mean "Ender3"\?\)/);
  assert.throws(() => new Filament('GenericPLX'), /unknown filament "GenericPLX"/);
  // a printer the seeds name without a Strata preset: its facts, and one clear line when sliced for
  const s5 = new Printer('UltimakerS5');
  assert.equal(s5.getSizeX(), 330);
  assert.throws(
    () => new Polyslice({ printer: s5 }),
    /no printer preset for UltiMaker S5: it prints Griffin-flavour G-code/,
  );
  // a changed printer and filament are what gets sliced
  const p = new Printer('Ender3').setSizeX(235);
  const f = new Filament('GenericPLA').setNozzleTemperature(205).setFan(80);
  const s = new Polyslice({ printer: p, filament: f });
  assert.equal(s.config.buildPlateWidth, 235);
  assert.equal(s.config.nozzleTemperature, 205);
  assert.equal(s.config.fanSpeed, 80);
  // setPrinter overrides the plate set before; setFilament the temperatures
  s.setBuildPlateWidth(200).setNozzleTemperature(190);
  s.setPrinter(new Printer('CR10'));
  assert.equal(s.config.buildPlateWidth, 300);
  assert.equal(s.getPrinter()!.getModel(), 'CR10');
  s.setFilament(new Filament('PrusamentPLA'));
  assert.equal(s.config.nozzleTemperature, 215);
  assert.equal(new Polyslice({ printer: 'Ender3', filament: 'GenericPETG' }).config.filamentId, 'petg');
});

test("progress: the seeds' callback shape, from initializing to complete; none unless given", () => {
  const seen: string[] = [];
  const s = new Polyslice({ progressCallback: (i) => seen.push(`${i.stage}:${i.percent}`) });
  s.slice(part());
  assert.equal(seen[0], 'initializing:0');
  assert.equal(seen.at(-1), 'complete:100');
  assert.ok(seen.some((x) => x.startsWith('slicing:')));
  const thrower = new Polyslice({
    progressCallback: () => {
      throw new Error('x');
    },
  });
  assert.equal(typeof thrower.slice(part()), 'string', 'a throwing callback does not stop the slice');
  assert.equal(new Polyslice().getProgressCallback(), null);
});

test('sliceAsync and the Strata slicer behind it give the same G-code', async () => {
  const s = new Polyslice({ printer: 'PrusaMK4', filament: 'PrusamentPETG' });
  const sync = s.slice(part());
  assert.equal(await s.sliceAsync(part()), sync);
  assert.equal((await s.strata.slice(part())).gcode, sync);
});
