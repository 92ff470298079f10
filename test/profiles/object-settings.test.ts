import { test } from 'node:test';
import assert from 'node:assert/strict';
import { settingsFromSource } from '#strata/profiles/index.js';

test('PrusaSlicer per-object keys: fill_density %, perimeters, unknown keys listed', () => {
  const r = settingsFromSource({
    format: 'prusaslicer',
    values: { fill_density: '80%', perimeters: '4', fill_pattern: 'gyroid', wipe_into_objects: '1' },
  });
  assert.deepEqual(r.settings, { infillDensity: 80, wallCount: 4, infillPattern: 'gyroid' });
  assert.deepEqual(r.ignored, ['wipe_into_objects']);
  assert.deepEqual(r.rejected, []);
});

test('OrcaSlicer per-object keys: sparse_infill_density, wall_loops', () => {
  const r = settingsFromSource({ format: 'orcaslicer', values: { sparse_infill_density: '40%', wall_loops: '3' } });
  assert.deepEqual(r.settings, { infillDensity: 40, wallCount: 3 });
  assert.deepEqual(r.ignored, []);
});

test('Cura per-mesh settings: infill_sparse_density, wall_line_count', () => {
  const r = settingsFromSource({
    format: 'cura',
    values: { infill_sparse_density: '15', wall_line_count: '5', magic_mesh_surface_mode: 'normal' },
  });
  assert.deepEqual(r.settings, { infillDensity: 15, wallCount: 5 });
  assert.deepEqual(r.ignored, ['magic_mesh_surface_mode']);
});

test('the print settings are context: layer counts use its layer height, its own keys are not returned', () => {
  const context = {
    format: 'prusaslicer' as const,
    values: { layer_height: '0.1', top_solid_min_thickness: '0', fill_density: '20%', perimeters: '2' },
  };
  const r = settingsFromSource({ format: 'prusaslicer', values: { top_solid_layers: '6' } }, context);
  assert.deepEqual(r.settings, { topSkinThickness: 0.6 });
  // a context of another slicer is not read
  const other = settingsFromSource(
    { format: 'prusaslicer', values: { top_solid_layers: '6' } },
    { format: 'cura', values: { layer_height: '0.1' } },
  );
  assert.deepEqual(other.settings, { topSkinThickness: 1.2 });
});

test('values that map but do not fit the schema are rejected, with the key', () => {
  const r = settingsFromSource({ format: 'prusaslicer', values: { fill_density: '180%' } });
  assert.deepEqual(r.settings, {});
  assert.equal(r.rejected.length, 1);
  assert.equal(r.rejected[0].key, 'fill_density');
});

test('Strata values pass through when valid; unknown keys are ignored, bad values rejected', () => {
  const r = settingsFromSource({
    format: 'strata',
    values: { infillDensity: 35, wallCount: 3, noSuchSetting: 1, infillPattern: 'zebra' },
  });
  assert.deepEqual(r.settings, { infillDensity: 35, wallCount: 3 });
  assert.deepEqual(r.ignored, ['noSuchSetting']);
  assert.equal(r.rejected.length, 1);
  assert.equal(r.rejected[0].key, 'infillPattern');
  assert.match(r.rejected[0].reason, /one of/);
});

test('OrcaSlicer JSON lists (one value per extruder) read as their first value', () => {
  const r = settingsFromSource({ format: 'orcaslicer', values: { sparse_infill_density: ['25%'], wall_loops: 2 } });
  assert.deepEqual(r.settings, { infillDensity: 25, wallCount: 2 });
});
