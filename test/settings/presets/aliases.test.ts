import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  CURA_NAMES,
  FOREIGN_NAMES,
  POLYSLICE_NAMES,
  PRINTERS_WITHOUT_PRESET,
  PRUSASLICER_NAMES,
} from '#strata/settings/presets/aliases.js';
import {
  FILAMENT_PRESETS,
  findFilament,
  findPrinter,
  PRINTER_PRESETS,
  printerWithoutPreset,
} from '#strata/settings/presets/index.js';
import { resolveConfig } from '#strata/settings/resolve.js';
import { StrataError } from '#strata/errors.js';

/** The seeds' library's printer names (its printers.coffee) and filament names (filaments.coffee), as listed there. */
const SEED_PRINTERS = [
  'Ender3',
  'Ender3V2',
  'Ender5',
  'PrusaI3MK3S',
  'PrusaMini',
  'AnycubicI3Mega',
  'CR10',
  'ArtillerySidewinderX1',
  'UltimakerS5',
  'FlashForgeCreatorPro',
  'Raise3DPro2',
  'Ender3Pro',
  'Ender3S1',
  'CR10S5',
  'PrusaXL',
  'BambuLabX1Carbon',
  'BambuLabP1P',
  'AnycubicKobra',
  'AnycubicVyper',
  'ElegooNeptune3',
  'ElegooNeptune3Pro',
  'SovolSV06',
  'Voron24',
  'MakerbotReplicatorPlus',
  'QidiXPlus',
  'FlashforgeAdventurer3',
  'MonopriceSelectMiniV2',
  'ArtilleryGenius',
  'LulzBotMini2',
  'LulzBotTAZ6',
  'Ender6',
  'CR6SE',
  'AnycubicPhotonMonoX',
  'PrusaMK4',
  'BambuLabA1Mini',
  'BambuLabA1',
  'KingroonKP3S',
  'CrealityK1',
  'CrealityK1Max',
  'AnkerMakeM5',
  'ElegooNeptune4',
  'ElegooNeptune4Pro',
  'ArtillerySidewinderX2',
  'SovolSV06Plus',
];
const SEED_FILAMENTS = [
  'GenericPLA',
  'GenericPETG',
  'GenericABS',
  'GenericTPU',
  'GenericNylon',
  'HatchboxPLA',
  'eSunPLAPlus',
  'OverturePLA',
  'PrusamentPLA',
  'PrusamentPETG',
  'PolymakerPolyLitePLA',
  'PolymakerPolyTerraPLA',
  'BambuLabPLABasic',
  'BambuLabPETGHF',
  'SunluPLA',
  'ColorFabbPLAPHA',
  'NinjaFlexTPU',
  'SainSmartTPU',
  '3DXTechCarbonX',
  'UltimakerPLA',
  'UltimakerToughPLA',
  'BambuLabPLAMatte',
  'BambuLabABS',
  'PolymakerPolyLitePETG',
  'PolymakerPolyMaxPLA',
  'eSunABSPlus',
  'eSunPETG',
  'OverturePETG',
  'HatchboxPETG',
  'HatchboxABS',
  'SunluPETG',
  'PolymakerPolyFlexTPU95',
  'ColorFabbNGen',
  'PrusaPETG',
  'GenericASA',
];

test("every printer the seeds' library names has a preset, or is listed with its size and why there is none", () => {
  for (const name of SEED_PRINTERS) {
    const preset = findPrinter(name);
    const gap = printerWithoutPreset(name);
    assert.ok(!!preset !== !!gap, `${name}: a preset (${preset?.id}) or a reason (${gap?.why}), not both`);
    if (preset) assert.equal(preset.id, POLYSLICE_NAMES.printers[name], name);
  }
  assert.equal(
    Object.keys(POLYSLICE_NAMES.printers).length + Object.keys(PRINTERS_WITHOUT_PRESET).length,
    SEED_PRINTERS.length,
  );
  // most of them print with a preset of ours
  assert.ok(Object.keys(POLYSLICE_NAMES.printers).length >= 32);
});

test("every filament the seeds' library names finds a preset of its material", () => {
  for (const name of SEED_FILAMENTS) {
    const f = findFilament(name);
    assert.ok(f, name);
    const material = /PLA/i.test(name)
      ? 'PLA'
      : /PETG|nGen/i.test(name)
        ? 'PETG'
        : /ABS/.test(name)
          ? 'ABS'
          : /ASA/.test(name)
            ? 'ASA'
            : /TPU/.test(name)
              ? 'TPU'
              : 'PA';
    assert.equal(f.material, material, `${name} → ${f.id}`);
  }
  assert.equal(Object.keys(POLYSLICE_NAMES.filaments).length, SEED_FILAMENTS.length);
});

test("branded filaments print at their own temperatures with their material's cooling, keeping the first-layer offsets", () => {
  const prusament = findFilament('PrusamentPLA')!;
  const pla = FILAMENT_PRESETS['pla']!;
  assert.equal(prusament.settings.nozzleTemperature, 215);
  assert.equal(
    prusament.settings.firstLayerNozzleTemperature! - prusament.settings.nozzleTemperature!,
    pla.settings.firstLayerNozzleTemperature! - pla.settings.nozzleTemperature!,
  );
  assert.equal(prusament.settings.fanSpeed, pla.settings.fanSpeed);
  assert.equal(prusament.settings.filamentDensity, pla.settings.filamentDensity);
  assert.equal(findFilament('3DXTechCarbonX')!.abrasive, true);
  assert.equal(
    findFilament('NinjaFlexTPU')!.settings.retractionDistance,
    FILAMENT_PRESETS['tpu-85a']!.settings.retractionDistance,
  );
});

test("PrusaSlicer's and Cura's names, and preset names ending in the nozzle size", () => {
  assert.equal(findPrinter('Original Prusa MK4')?.id, 'prusa-mk4');
  assert.equal(findPrinter('MK4IS')?.id, 'prusa-mk4');
  assert.equal(findPrinter('creality_ender3')?.id, 'creality-ender-3');
  assert.equal(findPrinter('Original Prusa i3 MK3S && MK3S+')?.id, 'prusa-i3-mk3s');
  assert.equal(findPrinter('Original Prusa MK4S 0.4 nozzle')?.id, 'prusa-mk4s');
  assert.equal(findPrinter('Bambu Lab X1 Carbon 0.4 nozzle')?.id, 'bambu-lab-x1c');
  assert.equal(findPrinter('Creality Ender-3 V2 (0.4 mm nozzle)')?.id, 'creality-ender-3-v2');
  // another nozzle size is not our preset (every preset has a 0.4 mm nozzle)
  assert.equal(findPrinter('Original Prusa MK4S 0.6 nozzle'), undefined);
  assert.equal(findFilament('generic_pla')?.id, 'pla');
  for (const source of Object.values(FOREIGN_NAMES)) {
    for (const [name, id] of Object.entries(source.printers)) assert.equal(findPrinter(name)?.id, id, name);
    for (const [name, id] of Object.entries(source.filaments)) assert.equal(findFilament(name)?.id, id, name);
  }
  assert.ok(Object.keys(PRUSASLICER_NAMES.printers).length > 20 && Object.keys(CURA_NAMES.printers).length > 20);
});

test('every foreign name points at a preset (a misspelt id would throw when the tables load)', () => {
  for (const source of Object.values(FOREIGN_NAMES)) {
    for (const id of Object.values(source.printers)) assert.ok(PRINTER_PRESETS[id], id);
    for (const id of Object.values(source.filaments)) assert.ok(FILAMENT_PRESETS[id], id);
  }
});

test('the names resolve into configs, and a printer without a preset is one clear error', () => {
  const cfg = resolveConfig({ printer: 'Ender3', filament: 'GenericPLA' });
  assert.equal(cfg.printerId, 'creality-ender-3');
  assert.equal(cfg.filamentId, 'pla');
  assert.equal(resolveConfig({ printer: 'CR10', filament: 'PrusamentPLA' }).nozzleTemperature, 215);
  const why = (printer: string) => {
    try {
      resolveConfig({ printer });
    } catch (e) {
      assert.ok(e instanceof StrataError && e.code === 'UNKNOWN_PRESET');
      return e.message;
    }
    assert.fail(`${printer} resolved`);
  };
  assert.match(
    why('UltimakerS5'),
    /^no printer preset for UltiMaker S5 \("UltimakerS5"\): it prints Griffin-flavour G-code/,
  );
  assert.match(why('ultimaker_s5'), /UltiMaker S5/);
  assert.match(why('AnycubicVyper'), /buildPlateWidth 245, buildPlateLength 245, buildVolumeHeight 260/);
  assert.match(why('AnycubicPhotonMonoX'), /resin/);
  assert.match(why('Ender99'), /^unknown printer "Ender99"/);
});
