import { test } from 'node:test';
import assert from 'node:assert/strict';
import { strToU8, unzipSync, zipSync } from 'fflate';
import { StrataError } from '#strata/errors.js';
import { loadModelFile, toModels } from '#strata/mesh/load.js';
import { parse3mf } from '#strata/mesh/threemf.js';
import { parse3mfProject } from '#strata/mesh/threemf-project.js';
import { writeProject3mf } from '#strata/profiles/threemf-write.js';
import type { Mesh, MeshObject } from '#strata/mesh/types.js';
import { weld } from '#strata/mesh/weld.js';

const RELS = `<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>`;

const FACES = [
  [0, 2, 3],
  [0, 3, 1],
  [4, 5, 7],
  [4, 7, 6],
  [0, 1, 5],
  [0, 5, 4],
  [2, 6, 7],
  [2, 7, 3],
  [0, 4, 6],
  [0, 6, 2],
  [1, 3, 7],
  [1, 7, 5],
];

/** Corners of an axis-aligned box. */
function corners(x0: number, y0: number, z0: number, s: number): number[][] {
  return Array.from({ length: 8 }, (_, i) => [x0 + (i & 1) * s, y0 + ((i >> 1) & 1) * s, z0 + ((i >> 2) & 1) * s]);
}

/** `<vertex>` and `<triangle>` elements of boxes in one mesh, in order. */
function meshXml(boxes: number[][][]): string {
  const v = boxes.flat().map(([x, y, z]) => `<vertex x="${x}" y="${y}" z="${z}"/>`);
  const t = boxes.flatMap((_, b) =>
    FACES.map(([p, q, r]) => `<triangle v1="${p + 8 * b}" v2="${q + 8 * b}" v3="${r + 8 * b}"/>`),
  );
  return `<mesh><vertices>${v.join('')}</vertices><triangles>${t.join('')}</triangles></mesh>`;
}

/** A box as the readers give it (welded: vertices in the order triangles first use them). */
function boxMesh(x0: number, y0: number, z0: number, s: number): Mesh {
  return weld(Float32Array.from(corners(x0, y0, z0, s).flat()), Uint32Array.from(FACES.flat()));
}

function model(resources: string, build: string, extraNs = ''): string {
  return `<?xml version="1.0" encoding="UTF-8"?>
<model unit="millimeter" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"${extraNs}>
 <resources>${resources}</resources>
 <build>${build}</build>
</model>`;
}

function zip(files: Record<string, string>): Uint8Array {
  const out: Record<string, Uint8Array> = { '_rels/.rels': strToU8(RELS) };
  for (const [k, v] of Object.entries(files)) out[k] = strToU8(v);
  return zipSync(out);
}

const triangles = (m: Mesh): number => m.indices.length / 3;

function throwsStrata(fn: () => unknown, code: string, re: RegExp): void {
  assert.throws(fn, (e: unknown) => {
    assert.ok(e instanceof StrataError, `expected StrataError, got ${String(e)}`);
    assert.equal(e.code, code, e.message);
    assert.match(e.message, re);
    assert.ok(!e.message.includes('\n'));
    return true;
  });
}

// A PrusaSlicer project, as PrusaSlicer 2.x writes one: object 1 holds the part, a modifier and a negative
// volume in one mesh (object coordinates), object 2 is its second instance (a component of object 1).
const PRUSA_MODEL = model(
  `<object id="1" name="Cube" type="model">${meshXml([corners(0, 0, 0, 20), corners(5, 5, 5, 10), corners(2, 2, 15, 3)])}</object>
   <object id="2" type="model"><components><component objectid="1"/></components></object>`,
  `<item objectid="1" transform="1 0 0 0 1 0 0 0 1 100 100 0" printable="1"/>
   <item objectid="2" transform="1 0 0 0 1 0 0 0 1 50 100 0" printable="1"/>`,
  ' xmlns:slic3rpe="http://schemas.slic3r.org/3mf/2017/06"',
);
const PRUSA_CONFIG = `<?xml version="1.0" encoding="UTF-8"?>
<config>
 <object id="1" instances_count="2">
  <metadata type="object" key="name" value="Cube &amp; co"/>
  <metadata type="object" key="perimeters" value="3"/>
  <metadata type="object" key="extruder" value="1"/>
  <volume firstid="0" lastid="11">
   <metadata type="volume" key="name" value="Cube"/>
   <metadata type="volume" key="volume_type" value="ModelPart"/>
   <metadata type="volume" key="matrix" value="1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1"/>
   <metadata type="volume" key="source_file" value="cube.stl"/>
   <mesh edges_fixed="0" degenerate_facets="0" facets_removed="0" facets_reversed="0" backwards_edges="0"/>
  </volume>
  <volume firstid="12" lastid="23">
   <metadata type="volume" key="name" value="Dense core"/>
   <metadata type="volume" key="modifier" value="1"/>
   <metadata type="volume" key="volume_type" value="ParameterModifier"/>
   <metadata type="volume" key="fill_density" value="80%"/>
  </volume>
  <volume firstid="24" lastid="35">
   <metadata type="volume" key="name" value="Hole"/>
   <metadata type="volume" key="volume_type" value="NegativeVolume"/>
  </volume>
 </object>
</config>`;
const PRUSA_RANGES = `<?xml version="1.0" encoding="utf-8"?>
<objects>
 <object id="1">
  <range min_z="5" max_z="10">
   <option opt_key="fill_density">10%</option>
   <option opt_key="layer_height">0.1</option>
  </range>
 </object>
</objects>`;
const PRUSA_PRINT =
  '; generated by PrusaSlicer 2.7.1+linux-x64 on 2024-01-01 at 10:00:00 UTC\n\n; fill_density = 20%\n; layer_height = 0.2\n; perimeters = 2\n';

test('a PrusaSlicer project: part, modifier with its fill density, negative volume, layer range, print settings, instances', () => {
  const bytes = zip({
    '3D/3dmodel.model': PRUSA_MODEL,
    'Metadata/Slic3r_PE_model.config': PRUSA_CONFIG,
    'Metadata/Prusa_Slicer_layer_config_ranges.xml': PRUSA_RANGES,
    'Metadata/Slic3r_PE.config': PRUSA_PRINT,
  });
  const { objects, projectSettings, warnings } = parse3mfProject(bytes, 'proj');
  assert.deepEqual(warnings, []);
  assert.equal(objects.length, 2);
  const [a, b] = objects;
  assert.equal(a.name, 'Cube & co');
  assert.equal(b.name, 'Cube & co (2)');
  assert.equal(triangles(a.mesh), 12);
  assert.deepEqual(
    a.volumes?.map((v) => [v.kind, v.name, triangles(v.mesh)]),
    [
      ['modifier', 'Dense core', 12],
      ['negative', 'Hole', 12],
    ],
  );
  assert.deepEqual(a.volumes?.[0].settings, { format: 'prusaslicer', values: { fill_density: '80%' } });
  assert.equal(a.volumes?.[1].settings, undefined);
  assert.deepEqual(a.settings, { format: 'prusaslicer', values: { perimeters: '3' } });
  assert.deepEqual(a.layerRanges, [
    { fromZ: 5, toZ: 10, settings: { format: 'prusaslicer', values: { fill_density: '10%', layer_height: '0.1' } } },
  ]);
  assert.deepEqual(projectSettings, {
    format: 'prusaslicer',
    values: { fill_density: '20%', layer_height: '0.2', perimeters: '2' },
  });
  // the modifier is where the build item puts it: object coordinates + the item's translation
  const mod = a.volumes![0].mesh.positions;
  assert.equal(Math.min(...mod.filter((_, i) => i % 3 === 0)), 105);
  // the second instance has the same volumes and settings, at its own place
  assert.deepEqual(
    b.volumes?.map((v) => [v.kind, triangles(v.mesh)]),
    [
      ['modifier', 12],
      ['negative', 12],
    ],
  );
  assert.deepEqual(b.settings, a.settings);
  assert.deepEqual(b.layerRanges, a.layerRanges);
  assert.equal(Math.min(...b.mesh.positions.filter((_, i) => i % 3 === 0)), 50);
  assert.notEqual(b.volumes, a.volumes);
  // parse3mf still gives every triangle of each item as one mesh
  assert.deepEqual(
    parse3mf(bytes, 'proj').map((o) => triangles(o.mesh)),
    [36, 36],
  );
});

test('loadModelFile and toModels carry the project settings and warnings', () => {
  const bytes = zip({
    '3D/3dmodel.model': PRUSA_MODEL,
    'Metadata/Slic3r_PE_model.config': PRUSA_CONFIG,
    'Metadata/Slic3r_PE.config': PRUSA_PRINT,
  });
  const file = loadModelFile(bytes, 'proj.3mf');
  assert.equal(file.objects.length, 2);
  assert.equal(file.projectSettings?.format, 'prusaslicer');
  const loaded = toModels([bytes]);
  assert.equal(loaded.projectSettings?.values.fill_density, '20%');
  assert.equal(loaded.models[0].objects[0].volumes?.length, 2);
});

test('older PrusaSlicer files: modifier = 1 without volume_type; triangles in no volume are dropped with a warning', () => {
  const config = `<config><object id="1"><metadata type="object" key="name" value="Old"/>
    <volume firstid="0" lastid="11"/>
    <volume firstid="12" lastid="23"><metadata type="volume" key="modifier" value="1"/><metadata type="volume" key="fill_density" value="0.5"/></volume>
  </object></config>`;
  const bytes = zip({
    '3D/3dmodel.model': PRUSA_MODEL.replace(/<item objectid="2"[^>]*>/, ''),
    'Metadata/Slic3r_PE_model.config': config,
  });
  const { objects, warnings } = parse3mfProject(bytes);
  assert.equal(objects.length, 1);
  assert.deepEqual(
    objects[0].volumes?.map((v) => v.kind),
    ['modifier'],
  );
  assert.equal(triangles(objects[0].mesh), 12);
  assert.equal(warnings.length, 1);
  assert.match(warnings[0], /12 triangles of object "Old" belong to no volume/);
});

test('a PrusaSlicer ModelPart with settings of its own prints and is a modifier too', () => {
  const config = `<config><object id="1">
    <volume firstid="0" lastid="11"><metadata type="volume" key="volume_type" value="ModelPart"/></volume>
    <volume firstid="12" lastid="35"><metadata type="volume" key="name" value="Second part"/><metadata type="volume" key="volume_type" value="ModelPart"/><metadata type="volume" key="perimeters" value="5"/></volume>
  </object></config>`;
  const bytes = zip({
    '3D/3dmodel.model': PRUSA_MODEL.replace(/<item objectid="2"[^>]*>/, ''),
    'Metadata/Slic3r_PE_model.config': config,
  });
  const [o] = parse3mfProject(bytes).objects;
  assert.equal(triangles(o.mesh), 36);
  assert.deepEqual(
    o.volumes?.map((v) => [v.kind, v.name, triangles(v.mesh), v.settings?.values]),
    [['modifier', 'Second part', 24, { perimeters: '5' }]],
  );
});

test('hostile PrusaSlicer configs: one-line BAD_FILE errors naming the problem', () => {
  const build = (config: string, extra: Record<string, string> = {}) =>
    zip({ '3D/3dmodel.model': PRUSA_MODEL, 'Metadata/Slic3r_PE_model.config': config, ...extra });
  const vol = (a: number, b: number) => `<volume firstid="${a}" lastid="${b}"/>`;
  throwsStrata(
    () => parse3mfProject(build(`<config><object id="1">${vol(0, 11)}${vol(12, 99)}</object></config>`)),
    'BAD_FILE',
    /covers triangles 12–99, but the object has 36/,
  );
  throwsStrata(
    () => parse3mfProject(build(`<config><object id="1">${vol(0, 20)}${vol(12, 35)}</object></config>`)),
    'BAD_FILE',
    /volumes 1 and 2 of object 1 share triangles/,
  );
  throwsStrata(
    () => parse3mfProject(build(`<config><object id="1">${vol(11, 3)}</object></config>`)),
    'BAD_FILE',
    /ends \(triangle 3\) before it starts/,
  );
  throwsStrata(
    () => parse3mfProject(build(`<config><object id="x"/></config>`)),
    'BAD_FILE',
    /Slic3r_PE_model\.config, line 1: an <object> needs a numeric id/,
  );
  throwsStrata(
    () => parse3mfProject(build(`<config><object id="1"/><object id="1"/></config>`)),
    'BAD_FILE',
    /two objects have the id 1/,
  );
  throwsStrata(
    () => parse3mfProject(build(`<config><object id="1"><volume firstid="-1" lastid="3"/></object></config>`)),
    'BAD_FILE',
    /firstid="-1" is not a whole number/,
  );
  throwsStrata(() => parse3mfProject(build(`<config><object id="1">`)), 'BAD_FILE', /ends inside <object>/);
  const overlapping = `<objects><object id="1"><range min_z="0" max_z="5"/><range min_z="4" max_z="8"/></object></objects>`;
  throwsStrata(
    () => parse3mfProject(build(PRUSA_CONFIG, { 'Metadata/Prusa_Slicer_layer_config_ranges.xml': overlapping })),
    'BAD_FILE',
    /layer ranges 0–5 mm and 4–8 mm of object 1 overlap/,
  );
  throwsStrata(
    () =>
      parse3mfProject(
        build(PRUSA_CONFIG, {
          'Metadata/Prusa_Slicer_layer_config_ranges.xml':
            '<objects><object id="1"><range min_z="3" max_z="3"/></object></objects>',
        }),
      ),
    'BAD_FILE',
    /the layer range 3–3 mm is empty/,
  );
  // harmless: an object id the model does not have, ranges of an object that does not exist
  const stray = parse3mfProject(
    build(`<config><object id="7"><volume firstid="0" lastid="1"/></object></config>`, {
      'Metadata/Prusa_Slicer_layer_config_ranges.xml':
        '<objects><object id="0"/><object id="9"><range min_z="0" max_z="1"/></object></objects>',
    }),
  );
  assert.deepEqual(
    stray.objects.map((o) => [o.name, triangles(o.mesh), o.volumes]),
    [
      ['Cube', 36, undefined],
      ['model 2', 36, undefined],
    ],
  );
  assert.equal(stray.warnings.length, 1);
});

test('a config part that declares more than the limit is refused before it is unpacked', () => {
  const big = new Uint8Array(64 * 1024 * 1024 + 1).fill(32);
  const bytes = zipSync({
    '_rels/.rels': strToU8(RELS),
    '3D/3dmodel.model': strToU8(PRUSA_MODEL),
    'Metadata/Slic3r_PE_model.config': big,
  });
  throwsStrata(() => parse3mfProject(bytes), 'LIMIT_EXCEEDED', /Slic3r_PE_model\.config unpacks to .* more than/);
});

/** Objects for the round trip: a cube with a dense modifier, a hole and a support blocker; a plain second cube. */
function projectObjects(): MeshObject[] {
  return [
    {
      name: 'Bracket "A" & <b>',
      mesh: boxMesh(10, 10, 0, 20),
      settings: { format: 'strata', values: { wallCount: 4, infillPattern: 'gyroid', topSkinThickness: 1 } },
      volumes: [
        {
          kind: 'modifier',
          name: 'core',
          mesh: boxMesh(15, 15, 5, 10),
          settings: { format: 'strata', values: { infillDensity: 80, infillPattern: 'cubic' } },
        },
        { kind: 'negative', name: 'hole', mesh: boxMesh(12, 12, 15, 3) },
        { kind: 'support-blocker', name: 'no support', mesh: boxMesh(9, 9, 0, 4) },
      ],
      layerRanges: [
        { fromZ: 5, toZ: 10.5, settings: { format: 'strata', values: { infillDensity: 10, layerHeight: 0.1 } } },
      ],
    },
    { name: 'Plain', mesh: boxMesh(50, 10, 0, 10.123457) },
  ];
}

test('writeProject3mf → parse3mfProject gives the same objects, volumes, settings and layer ranges', () => {
  const objects = projectObjects();
  const bytes = writeProject3mf(objects, {
    printSettings: { layerHeight: 0.25, infillDensity: 15 },
    slic3rPrintSettings: { layer_height: '0.25', fill_density: '15%' },
  });
  const back = parse3mfProject(bytes, 'written');
  assert.deepEqual(back.warnings, []);
  assert.deepEqual(back.projectSettings, { format: 'strata', values: { layerHeight: 0.25, infillDensity: 15 } });
  assert.equal(back.objects.length, 2);
  back.objects.forEach((o, i) => {
    const want = objects[i];
    assert.equal(o.name, want.name);
    assert.deepEqual(o.mesh.positions, want.mesh.positions);
    assert.deepEqual(o.mesh.indices, want.mesh.indices);
    assert.deepEqual(o.settings, want.settings);
    assert.deepEqual(o.layerRanges, want.layerRanges);
    assert.deepEqual(
      o.volumes?.map((v) => [v.kind, v.name, triangles(v.mesh), v.settings]),
      want.volumes?.map((v) => [v.kind, v.name, triangles(v.mesh), v.settings]),
    );
    o.volumes?.forEach((v, k) => assert.deepEqual(v.mesh.positions, want.volumes![k].mesh.positions));
  });
});

test("a written project in PrusaSlicer's layout alone (no Strata copy) reads as PrusaSlicer settings", () => {
  const files = unzipSync(
    writeProject3mf(projectObjects(), {
      printSettings: { layerHeight: 0.25 },
      slic3rPrintSettings: { layer_height: '0.25', start_gcode: 'G28\nG1 Z5' },
    }),
  );
  const text = new TextDecoder().decode(files['Metadata/Slic3r_PE_model.config']);
  assert.match(text, /<volume firstid="0" lastid="11">/);
  assert.match(text, /key="volume_type" value="ParameterModifier"/);
  assert.match(text, /key="volume_type" value="SupportBlocker"/);
  assert.match(new TextDecoder().decode(files['Metadata/Slic3r_PE.config']), /^; start_gcode = G28\\nG1 Z5$/m);
  delete files['Metadata/Strata_project.json'];
  const { objects, projectSettings } = parse3mfProject(zipSync(files));
  assert.equal(projectSettings?.format, 'prusaslicer');
  assert.deepEqual(objects[0].settings, {
    format: 'prusaslicer',
    values: { fill_pattern: 'gyroid', perimeters: '4', top_solid_layers: '4', top_solid_min_thickness: '1' },
  });
  assert.deepEqual(objects[0].volumes?.[0].settings, {
    format: 'prusaslicer',
    values: { fill_density: '80%', fill_pattern: 'cubic' },
  });
  assert.deepEqual(objects[0].layerRanges?.[0].settings, {
    format: 'prusaslicer',
    values: { layer_height: '0.1', extruder: '0', fill_density: '10%' },
  });
  assert.deepEqual(
    objects[0].volumes?.map((v) => v.kind),
    ['modifier', 'negative', 'support-blocker'],
  );
});

test("a Strata copy that does not match the volumes is reported, and PrusaSlicer's data used", () => {
  const files = unzipSync(writeProject3mf(projectObjects()));
  const json = JSON.parse(new TextDecoder().decode(files['Metadata/Strata_project.json']));
  json.objects[0].volumes.pop();
  files['Metadata/Strata_project.json'] = strToU8(JSON.stringify(json));
  const back = parse3mfProject(zipSync(files));
  assert.equal(back.warnings.length, 1);
  assert.match(back.warnings[0], /does not match its volumes/);
  assert.equal(back.objects[0].volumes?.[0].settings?.format, 'prusaslicer');
  files['Metadata/Strata_project.json'] = strToU8('{"version": 9}');
  assert.match(parse3mfProject(zipSync(files)).warnings[0], /Strata_project\.json is not used: its version is 9/);
});

test('an OrcaSlicer project: parts as components in their own model part, subtypes, settings, layer ranges', () => {
  const part = (id: number, box: number[][]) => `<object id="${id}" type="model">${meshXml([box])}</object>`;
  const objects = model(
    part(1, corners(-10, -10, 0, 20)) + part(2, corners(-5, -5, 5, 10)) + part(3, corners(-2, -2, 0, 4)),
    '',
  );
  const root = model(
    `<object id="4" type="model"><components>
      <component p:path="/3D/Objects/object_1.model" objectid="1" transform="1 0 0 0 1 0 0 0 1 0 0 0"/>
      <component p:path="/3D/Objects/object_1.model" objectid="2" transform="1 0 0 0 1 0 0 0 1 0 0 0"/>
      <component p:path="/3D/Objects/object_1.model" objectid="3" transform="1 0 0 0 1 0 0 0 1 0 0 1"/>
    </components></object>`,
    '<item objectid="4" transform="1 0 0 0 1 0 0 0 1 128 128 10" printable="1"/>',
    ' xmlns:p="http://schemas.microsoft.com/3dmanufacturing/production/2015/06"',
  );
  const config = `<?xml version="1.0" encoding="UTF-8"?>
<config>
  <object id="4">
    <metadata key="name" value="Orca box"/>
    <metadata key="extruder" value="1"/>
    <metadata key="sparse_infill_density" value="40%"/>
    <part id="1" subtype="normal_part"><metadata key="name" value="box"/><metadata key="matrix" value="1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1"/><mesh_stat edges_fixed="0"/></part>
    <part id="2" subtype="modifier_part"><metadata key="name" value="dense"/><metadata key="sparse_infill_density" value="90%"/></part>
    <part id="3" subtype="support_enforcer"><metadata key="name" value="prop"/></part>
  </object>
  <plate><metadata key="plater_id" value="1"/><model_instance><metadata key="object_id" value="4"/></model_instance></plate>
</config>`;
  const bytes = zip({
    '3D/3dmodel.model': root,
    '3D/Objects/object_1.model': objects,
    'Metadata/model_settings.config': config,
    'Metadata/project_settings.config': JSON.stringify({
      sparse_infill_density: '15%',
      wall_loops: '2',
      nozzle_diameter: ['0.4'],
    }),
    'Metadata/layer_config_ranges.xml':
      '<objects><object id="1"><range min_z="2" max_z="4"><option opt_key="wall_loops">5</option></range></object></objects>',
  });
  const {
    objects: [o, ...rest],
    projectSettings,
    warnings,
  } = parse3mfProject(bytes, 'orca');
  assert.deepEqual(warnings, []);
  assert.equal(rest.length, 0);
  assert.equal(o.name, 'Orca box');
  assert.equal(triangles(o.mesh), 12);
  assert.deepEqual(o.settings, { format: 'orcaslicer', values: { sparse_infill_density: '40%' } });
  assert.deepEqual(
    o.volumes?.map((v) => [v.kind, v.name, triangles(v.mesh), v.settings?.values]),
    [
      ['modifier', 'dense', 12, { sparse_infill_density: '90%' }],
      ['support-enforcer', 'prop', 12, undefined],
    ],
  );
  assert.equal(Math.min(...o.volumes![1].mesh.positions.filter((_, i) => i % 3 === 2)), 11);
  assert.deepEqual(o.layerRanges, [
    { fromZ: 2, toZ: 4, settings: { format: 'orcaslicer', values: { wall_loops: '5' } } },
  ]);
  assert.deepEqual(projectSettings, {
    format: 'orcaslicer',
    values: { sparse_infill_density: '15%', wall_loops: '2', nozzle_diameter: ['0.4'] },
  });
});

test("a Cura project: per-mesh settings, an infill mesh and an anti-overhang mesh as their own build items, the stacks' settings", () => {
  const cura = ' xmlns:cura="http://software.ultimaker.com/xml/cura/3mf/2015/10"';
  const group = (settings: Record<string, string>) =>
    `<metadatagroup>${Object.entries(settings)
      .map(([k, v]) => `<metadata name="cura:${k}" preserve="true" type="xs:string">${v}</metadata>`)
      .join('')}</metadatagroup>`;
  const m = model(
    `<object id="1" name="part.stl" type="model">${group({ wall_line_count: '4', extruder_nr: '0' })}${meshXml([corners(0, 0, 0, 20)])}</object>
     <object id="2" name="Modifier" type="model">${group({ infill_mesh: 'True', infill_sparse_density: '80' })}${meshXml([corners(5, 5, 5, 10)])}</object>
     <object id="3" name="Blocker" type="model">${group({ anti_overhang_mesh: 'True' })}${meshXml([corners(200, 200, 0, 5)])}</object>
     <object id="4" name="far.stl" type="model">${meshXml([corners(100, 0, 0, 10)])}</object>`,
    `<item objectid="1" transform="1 0 0 0 1 0 0 0 1 0 0 0"/><item objectid="2" transform="1 0 0 0 1 0 0 0 1 0 0 0"/>
     <item objectid="4" transform="1 0 0 0 1 0 0 0 1 0 0 0"/><item objectid="3" transform="1 0 0 0 1 0 0 0 1 0 0 0"/>`,
    cura,
  );
  const bytes = zip({
    '3D/3dmodel.model': m,
    'Cura/Creality Ender-3.global.cfg':
      '[general]\nversion = 4\nname = Ender\n\n[containers]\n0 = Ender_user\n1 = empty_quality_changes\n7 = creality_ender3\n',
    'Cura/Extruder 1.extruder.cfg':
      '[general]\nversion = 4\n\n[metadata]\nposition = 0\n\n[containers]\n0 = Ender_extruder_user\n',
    'Cura/Ender_user.inst.cfg':
      '[general]\nversion = 4\n\n[metadata]\ntype = user\n\n[values]\nlayer_height = 0.16\nadhesion_type = brim\n',
    'Cura/Ender_extruder_user.inst.cfg':
      '[general]\nversion = 4\n\n[values]\ninfill_sparse_density = 25\nlayer_height = 0.12\n',
  });
  const { objects, projectSettings, warnings } = parse3mfProject(bytes, 'cura');
  assert.deepEqual(
    objects.map((o) => o.name),
    ['part.stl', 'far.stl'],
  );
  assert.deepEqual(objects[0].settings, { format: 'cura', values: { wall_line_count: '4' } });
  assert.deepEqual(
    objects[0].volumes?.map((v) => [v.kind, v.name, triangles(v.mesh), v.settings]),
    [
      ['modifier', 'Modifier', 12, { format: 'cura', values: { infill_sparse_density: '80' } }],
      ['support-blocker', 'Blocker', 12, undefined],
    ],
  );
  assert.equal(objects[1].volumes, undefined);
  assert.equal(warnings.length, 1);
  assert.match(warnings[0], /"Blocker" overlaps no printed object; applied to "part\.stl"/);
  assert.deepEqual(projectSettings, {
    format: 'cura',
    values: { layer_height: '0.12', adhesion_type: 'brim', infill_sparse_density: '25' },
  });
});

test('a plain 3MF reads as parse3mf reads it, without settings or warnings', () => {
  const bytes = zip({ '3D/3dmodel.model': PRUSA_MODEL });
  const project = parse3mfProject(bytes, 'plain');
  const plain = parse3mf(bytes, 'plain');
  assert.deepEqual(project.warnings, []);
  assert.equal(project.projectSettings, undefined);
  assert.deepEqual(project.objects, plain);
});

test("older Bambu files: parts as triangle ranges of the object's mesh; a listed part that is no component is reported", () => {
  const m = model(
    `<object id="1" name="Old" type="model">${meshXml([corners(0, 0, 0, 20), corners(5, 5, 5, 10)])}</object>`,
    '<item objectid="1"/>',
  );
  const config = `<config><object id="1"><metadata key="name" value="Old bambu"/>
    <part id="1" subtype="normal_part" firstid="0" lastid="11"/>
    <part id="2" subtype="negative_part" firstid="12" lastid="23"><metadata key="name" value="cut"/></part>
    <part id="9" subtype="modifier_part"/>
  </object></config>`;
  const { objects, warnings } = parse3mfProject(
    zip({ '3D/3dmodel.model': m, 'Metadata/model_settings.config': config }),
  );
  assert.deepEqual(
    objects.map((o) => [o.name, triangles(o.mesh), o.volumes?.map((v) => [v.kind, v.name, triangles(v.mesh)])]),
    [['Old bambu', 12, [['negative', 'cut', 12]]]],
  );
  assert.equal(warnings.length, 1);
  assert.match(warnings[0], /lists a part 9 that is not one of its components; skipped/);
});

test('writeProject3mf: no objects, or an object without triangles, is an error; empty volumes are left out', () => {
  throwsStrata(() => writeProject3mf([]), 'EMPTY_MODEL', /at least one object/);
  const empty: Mesh = { positions: new Float32Array(0), indices: new Uint32Array(0) };
  throwsStrata(
    () => writeProject3mf([{ name: 'nothing', mesh: empty }]),
    'BAD_MESH',
    /object 1 \("nothing"\) has no triangles/,
  );
  const bytes = writeProject3mf([
    { name: 'a', mesh: boxMesh(0, 0, 0, 5), volumes: [{ kind: 'modifier', name: 'none', mesh: empty }] },
  ]);
  const [o] = parse3mfProject(bytes).objects;
  assert.equal(o.volumes, undefined);
  assert.equal(triangles(o.mesh), 12);
});

test('corrupted slicer configs either read or throw a one-line StrataError', () => {
  let seed = 11;
  const rnd = (n: number): number => {
    seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0;
    return seed % n;
  };
  const written = unzipSync(writeProject3mf(projectObjects()));
  const texts: Record<string, string> = {
    'Metadata/Slic3r_PE_model.config': PRUSA_CONFIG,
    'Metadata/Prusa_Slicer_layer_config_ranges.xml': PRUSA_RANGES,
    'Metadata/Strata_project.json': new TextDecoder().decode(written['Metadata/Strata_project.json']),
    'Metadata/model_settings.config':
      '<config><object id="1"><metadata key="name" value="o"/><part id="2" subtype="modifier_part"/><part id="1" firstid="0" lastid="11"/></object></config>',
    'Metadata/project_settings.config': '{"sparse_infill_density": "15%", "wall_loops": ["2"]}',
    'Cura/a.global.cfg': '[containers]\n0 = user\n',
    'Cura/user.inst.cfg': '[values]\ninfill_sparse_density = 20\n',
  };
  const modelFor = (file: string) =>
    file === 'Metadata/Strata_project.json' ? new TextDecoder().decode(written['3D/3dmodel.model']) : PRUSA_MODEL;
  for (const [file, text] of Object.entries(texts)) {
    const others: Record<string, string> =
      file === 'Metadata/Strata_project.json'
        ? { 'Metadata/Slic3r_PE_model.config': new TextDecoder().decode(written['Metadata/Slic3r_PE_model.config']) }
        : {};
    for (let r = 0; r < 120; r++) {
      const chars = [...text];
      const cut = r % 3 === 0 ? rnd(chars.length) : chars.length;
      for (let k = 0; k < 1 + rnd(6); k++) chars[rnd(cut)] = '<>"=/ 0-9ax%[]{}\n'[rnd(18)];
      const bytes = zip({ '3D/3dmodel.model': modelFor(file), ...others, [file]: chars.slice(0, cut).join('') });
      try {
        const p = parse3mfProject(bytes);
        assert.ok(p.objects.length > 0);
      } catch (e) {
        if (!(e instanceof StrataError)) assert.fail(`${file}: ${String(e)}`);
        assert.ok(!e.message.includes('\n'), e.message);
      }
    }
  }
});

test("a PrusaSlicer project's variable layer height profile is the object's layerHeightProfile; a bad line is named and left out", () => {
  const profile =
    'object_id=1|0.000000;0.200000;5.000000;0.100000;10.000000;0.100000;15.000000;0.300000;20.000000;0.300000\nobject_id=2|1;2;3\n';
  const { objects, warnings } = parse3mfProject(
    zip({
      '3D/3dmodel.model': PRUSA_MODEL,
      'Metadata/Slic3r_PE_model.config': PRUSA_CONFIG,
      'Metadata/Slic3r_PE_layer_heights_profile.txt': profile,
    }),
    'proj',
  );
  assert.deepEqual(objects[0].layerHeightProfile, [0, 0.2, 5, 0.1, 10, 0.1, 15, 0.3, 20, 0.3]);
  assert.deepEqual(warnings, [
    '3MF Metadata/Slic3r_PE_layer_heights_profile.txt: a line that is not a layer height profile (object_id=N|z;h;…, Z rising, heights above 0) is not used',
  ]);
});
