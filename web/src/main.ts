/**
 * The Strata web page: open models, place them on the bed, choose settings, slice in a worker,
 * preview the toolpaths and download the G-code. The page thread only draws and answers the user;
 * reading, slicing and building the preview data happen in the worker.
 */
import { Matrix4, Vector3 } from 'three';
import { listPresets, type Config } from 'strata-slicer';
import { byId, h, saveFile } from './dom.js';
import { duration, grams, metres, mm1 } from './format.js';
import { InfillPanel } from './infill-panel.js';
import { ObjectPanel } from './object-panel.js';
import { Plate, bedShape, type PlateItem } from './plate.js';
import { PreviewPanel } from './preview-panel.js';
import type { FromWorker, LoadedProject, SliceSummary } from './protocol.js';
import { buildSettingsPanel, InvalidFields, printSource } from './settings-panel.js';
import { SettingsStore } from './settings.js';
import { drawArrays } from './shapes.js';
import { ToolpathView } from './toolpath.js';
import { Viewer } from './viewer.js';
import { boxOf, KIND_INFO, volumeMesh } from './volumes.js';
import { Cancelled, WorkerClient } from './worker-client.js';
import { setupSendPanel } from './send-panel.js';

/** Largest model file read, bytes. */
const MAX_MODEL_BYTES = 512 * 1024 * 1024;
const MODEL_EXTENSIONS = /\.(stl|obj|3mf)$/i;

const store = new SettingsStore();
store.load();

const loader = new WorkerClient();
const slicerWorker = new WorkerClient();
/** Setting fields whose text was refused, in the print's panel and the object's. */
const invalidFields = new InvalidFields();

const ui = {
  open: byId<HTMLInputElement>('open-model'),
  saveProject: byId<HTMLButtonElement>('save-project'),
  printer: byId<HTMLSelectElement>('printer'),
  filament: byId<HTMLSelectElement>('filament'),
  slice: byId<HTMLButtonElement>('slice'),
  cancel: byId<HTMLButtonElement>('cancel'),
  download: byId<HTMLButtonElement>('download'),
  job: byId('job'),
  jobText: byId('job-text'),
  progress: byId<HTMLProgressElement>('progress'),
  messages: byId('messages'),
  empty: byId('empty'),
  drop: byId('drop'),
  viewModel: byId<HTMLButtonElement>('view-model'),
  viewPreview: byId<HTMLButtonElement>('view-preview'),
  previewPanel: byId('preview-panel'),
  objectList: byId('object-list'),
  objectTools: byId('object-tools'),
  arrange: byId<HTMLButtonElement>('arrange'),
  objX: byId<HTMLInputElement>('obj-x'),
  objY: byId<HTMLInputElement>('obj-y'),
  objScale: byId<HTMLInputElement>('obj-scale'),
  objTurn: byId<HTMLInputElement>('obj-rotz'),
  objSize: byId('obj-size'),
  rotX: byId<HTMLButtonElement>('rot-x'),
  rotY: byId<HTMLButtonElement>('rot-y'),
  layFace: byId<HTMLButtonElement>('lay-face'),
  resetObj: byId<HTMLButtonElement>('reset-obj'),
  removeObj: byId<HTMLButtonElement>('remove-obj'),
  resultCard: byId('result-card'),
  stats: byId('stats'),
  exportSettings: byId<HTMLButtonElement>('export-settings'),
  importSettings: byId<HTMLInputElement>('import-settings'),
  resetSettings: byId<HTMLButtonElement>('reset-settings'),
};

// ── messages ─────────────────────────────────────────────────────────────────
/**
 * What a message is about: a slice's outcome replaces the last one's (repeated Cancels show one
 * "Slicing cancelled."), and errors about files that failed to open go once a model opens.
 */
type Topic = 'open' | 'slice';
/** Topics whose newest message replaces the older ones. */
const ONE_AT_A_TIME: ReadonlySet<Topic> = new Set(['slice']);

/**
 * Show a message over the 3D view; errors stay until closed or their topic is settled, the rest fade
 * after a while. The same words again replace the message shown, so repeats do not pile up.
 */
function message(kind: 'error' | 'warning' | 'info', text: string, topic?: Topic): void {
  for (const old of ui.messages.querySelectorAll<HTMLElement>('.msg')) {
    if (
      (topic && ONE_AT_A_TIME.has(topic) && old.dataset.topic === topic) ||
      (old.dataset.kind === kind && old.dataset.text === text)
    )
      old.remove();
  }
  const close = h('button', { type: 'button', class: 'close', 'aria-label': 'Dismiss' }, '×');
  const el = h(
    'div',
    { class: `msg ${kind}`, role: kind === 'error' ? 'alert' : 'status', 'data-kind': kind, 'data-topic': topic },
    h('span', {}, text),
    close,
  );
  el.dataset.text = text;
  close.addEventListener('click', () => el.remove());
  ui.messages.append(el);
  while (ui.messages.children.length > 5) ui.messages.firstElementChild?.remove();
  if (kind !== 'error') setTimeout(() => el.remove(), kind === 'info' ? 6000 : 12000);
}

/** Remove the messages about a topic that is settled. */
function clearMessages(topic: Topic): void {
  for (const el of ui.messages.querySelectorAll<HTMLElement>(`.msg[data-topic="${topic}"]`)) el.remove();
}

function errorText(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

// ── state ────────────────────────────────────────────────────────────────────
let cfg: Config = safeConfig();
const plate = new Plate(bedShape(cfg));
let result: { gcode: ArrayBuffer; stats: SliceSummary; warnings: string[]; name: string } | null = null;
let slicing = false;
let faceMode = false;

function safeConfig(): Config {
  try {
    return store.config();
  } catch {
    return store.base();
  }
}

// ── 3D view ──────────────────────────────────────────────────────────────────
let viewer: Viewer | null = null;
let toolpaths: ToolpathView | null = null;
let preview: PreviewPanel | null = null;
try {
  viewer = new Viewer(byId('viewport'), {
    pick: (id) => {
      plate.selected = plate.items.find((i) => i.id === id) ?? null;
      refreshObjects();
    },
    pickVolume: (objectId, volumeId) => {
      const it = plate.items.find((i) => i.id === objectId);
      if (!it) return;
      plate.selected = it;
      objectPanel.selectVolume(it, volumeId);
      refreshObjects();
    },
    drag: (id, centre, done) => {
      const it = plate.items.find((i) => i.id === id);
      if (!it) return;
      it.center = centre;
      if (done) invalidate();
      refreshObjects(!done);
    },
    face: (id, normal) => {
      const it = plate.items.find((i) => i.id === id);
      if (!it) return;
      plate.layOnFace(it, normal);
      setFaceMode(false);
      invalidate();
      refreshObjects();
    },
  });
  toolpaths = new ToolpathView(() => viewer?.render());
  viewer.toolpaths.add(toolpaths.group);
  toolpaths.warmUp(viewer.renderer, viewer.camera);
  const view = viewer;
  preview = new PreviewPanel(toolpaths, {
    draft: (on) => view.setDraft(on),
    frame: (min, max) => view.frame(new Vector3(...min), new Vector3(...max), 5),
  });
  viewer.setBed(plate.bed);
  viewer.setMode('model');
} catch (e) {
  message(
    'error',
    `The 3D view cannot start (${errorText(e)}): this browser has WebGL turned off. Opening, slicing and downloading still work.`,
  );
}

function setView(mode: 'model' | 'preview'): void {
  ui.viewModel.setAttribute('aria-checked', String(mode === 'model'));
  ui.viewPreview.setAttribute('aria-checked', String(mode === 'preview'));
  ui.previewPanel.hidden = mode !== 'preview';
  viewer?.setMode(mode);
}
ui.viewModel.addEventListener('click', () => setView('model'));
ui.viewPreview.addEventListener('click', () => result && setView('preview'));

// ── objects ──────────────────────────────────────────────────────────────────
const objectPanel = new ObjectPanel(byId('object-card'), {
  plate,
  store,
  changed: (what) => {
    if (what === 'selection') return viewObjects();
    invalidate();
    refreshObjects();
  },
  message,
  invalid: invalidFields,
  loadMesh: async (file) => {
    try {
      const bytes = await file.arrayBuffer();
      const { model } = await loader.request<'loaded'>({ type: 'load', fileName: file.name, bytes, mesh: true }, [
        bytes,
      ]);
      for (const w of model!.warnings) message('warning', `${file.name}: ${w}`);
      return model;
    } catch (e) {
      message('error', `${file.name}: ${errorText(e)}`);
      return null;
    }
  },
});

function viewObjects(): void {
  if (!viewer) return;
  const sel = plate.selected;
  const matrices = new Map(plate.items.map((it) => [it, matrixOf(plate.affine(it))]));
  viewer.setObjects(
    plate.items.map((it) => ({
      id: it.id,
      positions: it.model.positions,
      normals: it.model.normals,
      matrix: matrices.get(it)!,
      centre: it.center,
      selected: it === sel,
      problem: plate.problems(it).length > 0,
      seeThrough: it.volumes.length > 0,
    })),
  );
  viewer.setVolumes(
    plate.items.flatMap((it) =>
      it.volumes.map((v) => ({
        objectId: it.id,
        volumeId: v.id,
        shapeKey: `${v.shape} ${v.centre.join(' ')} ${v.size.join(' ')}`,
        arrays: () => drawArrays(volumeMesh(v)),
        matrix: matrices.get(it)!,
        colour: KIND_INFO[v.kind].colour,
        selected: it === sel && objectPanel.selectedVolume === v.id,
        pickable: it === sel,
      })),
    ),
  );
}

/** Look at the objects from the front, keeping some of the bed around small ones. */
function frameObjects(): void {
  if (!viewer || plate.items.length === 0) return;
  viewer.home();
  const min = new Vector3(Infinity, Infinity, 0),
    max = new Vector3(-Infinity, -Infinity, 0);
  for (const it of plate.items) {
    const [sx, sy, sz] = plate.size(it);
    min.min(new Vector3(it.center[0] - sx / 2, it.center[1] - sy / 2, 0));
    max.max(new Vector3(it.center[0] + sx / 2, it.center[1] + sy / 2, sz));
  }
  viewer.frame(min, max, Math.max(plate.bed.width, plate.bed.depth) * 0.22);
}

/** Our row-major 3×4 affine as a three.js matrix. */
function matrixOf(a: Float64Array): Matrix4 {
  return new Matrix4().set(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10], a[11], 0, 0, 0, 1);
}

/** Redraw the object list and tools (`light`: only the numbers, while dragging). */
function refreshObjects(light = false): void {
  viewObjects();
  const sel = plate.selected;
  ui.objectTools.hidden = !sel;
  ui.arrange.disabled = plate.items.length === 0;
  ui.empty.hidden = plate.items.length > 0;
  if (sel) {
    for (const [input, value] of [
      [ui.objX, mm1(sel.center[0])],
      [ui.objY, mm1(sel.center[1])],
      [ui.objScale, String(Math.round(sel.scale * 10000) / 100)],
      [ui.objTurn, String(sel.turnZ)],
    ] as const) {
      if (document.activeElement !== input) input.value = value;
    }
    const [sx, sy, sz] = plate.size(sel);
    ui.objSize.textContent = `${mm1(sx)} × ${mm1(sy)} × ${mm1(sz)} mm, ${sel.model.triangles.toLocaleString('en')} triangles`;
  }
  if (light) return;
  objectPanel.show(sel);
  ui.objectList.replaceChildren(
    ...plate.items.map((it) => {
      const problems = [...plate.problems(it), ...(it.model.openEdges ? [`${it.model.openEdges} open edges`] : [])];
      const [sx, sy, sz] = plate.size(it);
      const own = ownText(it);
      const b = h(
        'button',
        { type: 'button', 'aria-current': String(it === plate.selected) },
        h('span', { class: 'name', title: it.fileName }, it.name),
        own
          ? h(
              'span',
              { class: 'own', title: own },
              h('span', { 'aria-hidden': 'true' }, '●'),
              h('span', { class: 'visually-hidden' }, own),
            )
          : null,
        h('span', { class: 'meta' }, `${mm1(sx)}×${mm1(sy)}×${mm1(sz)} mm`),
      );
      b.addEventListener('click', () => {
        plate.selected = it;
        refreshObjects();
      });
      return h('li', {}, b, problems.length ? h('div', { class: 'bad' }, problems.join('; ')) : null);
    }),
  );
  updateSliceButton();
}

/** What an object has of its own, in words ('' for nothing). */
function ownText(it: PlateItem): string {
  const n = Object.keys(it.settings).length,
    v = it.volumes.length,
    r = it.layerRanges.length;
  const words = [
    n && `${n} setting${n === 1 ? '' : 's'}`,
    v && `${v} volume${v === 1 ? '' : 's'}`,
    r && `${r} layer range${r === 1 ? '' : 's'}`,
  ].filter(Boolean);
  return words.length ? `Its own: ${words.join(', ')}` : '';
}

function selectedOrNull(): PlateItem | null {
  return plate.selected;
}

function onObjectEdit(fn: (it: PlateItem) => void): () => void {
  return () => {
    const it = selectedOrNull();
    if (!it) return;
    fn(it);
    invalidate();
    refreshObjects();
  };
}

function numberFrom(input: HTMLInputElement, min: number, max: number): number | null {
  const v = Number(input.value);
  if (input.value.trim() === '' || !Number.isFinite(v) || v < min || v > max) {
    message(
      'error',
      `${input.closest('label')?.querySelector('span')?.textContent?.trim() ?? 'Value'} must be a number from ${min} to ${max}`,
    );
    return null;
  }
  return v;
}

ui.objX.addEventListener(
  'change',
  onObjectEdit((it) => (it.center = [numberFrom(ui.objX, -5000, 5000) ?? it.center[0], it.center[1]])),
);
ui.objY.addEventListener(
  'change',
  onObjectEdit((it) => (it.center = [it.center[0], numberFrom(ui.objY, -5000, 5000) ?? it.center[1]])),
);
ui.objScale.addEventListener(
  'change',
  onObjectEdit((it) => {
    const pct = numberFrom(ui.objScale, 1, 10000);
    if (pct === null) return;
    it.scale = pct / 100;
    plate.relinear(it);
  }),
);
ui.objTurn.addEventListener(
  'change',
  onObjectEdit((it) => {
    const deg = numberFrom(ui.objTurn, -360, 360);
    if (deg === null) return;
    it.turnZ = deg;
    plate.relinear(it);
  }),
);
ui.rotX.addEventListener(
  'click',
  onObjectEdit((it) => plate.rotate(it, 'x', 90)),
);
ui.rotY.addEventListener(
  'click',
  onObjectEdit((it) => plate.rotate(it, 'y', 90)),
);
ui.resetObj.addEventListener(
  'click',
  onObjectEdit((it) => plate.reset(it)),
);
ui.removeObj.addEventListener('click', () => {
  const it = selectedOrNull();
  if (!it) return;
  plate.remove(it);
  invalidate();
  refreshObjects();
});
ui.arrange.addEventListener('click', () => {
  plate.arrange();
  invalidate();
  refreshObjects();
});

function setFaceMode(on: boolean): void {
  faceMode = on;
  ui.layFace.setAttribute('aria-pressed', String(on));
  viewer?.setFaceMode(on);
  if (on) message('info', 'Click the face of the object that should lie on the bed.');
}
ui.layFace.addEventListener('click', () => {
  if (faceMode) setFaceMode(false);
  else if (plate.selected) {
    setView('model');
    setFaceMode(true);
  }
});

document.addEventListener('keydown', (e) => {
  const t = e.target as HTMLElement;
  if (t.closest('input, select, textarea')) return;
  if ((e.key === 'Delete' || e.key === 'Backspace') && plate.selected) {
    if (objectPanel.deleteSelected()) return;
    plate.remove(plate.selected);
    invalidate();
    refreshObjects();
  } else if (e.key === 'Escape' && faceMode) setFaceMode(false);
});

// ── opening models ───────────────────────────────────────────────────────────
async function openFiles(files: readonly File[]): Promise<void> {
  // once a model opens, the errors about files that failed before are out of the way (this batch's stay)
  const earlier = [...ui.messages.querySelectorAll('.msg[data-topic="open"]')];
  for (const file of files) {
    if (!MODEL_EXTENSIONS.test(file.name)) {
      message('error', `${file.name}: not a model file (open STL, OBJ or 3MF)`, 'open');
      continue;
    }
    if (file.size > MAX_MODEL_BYTES) {
      message('error', `${file.name} is larger than ${MAX_MODEL_BYTES / 1024 / 1024} MB`, 'open');
      continue;
    }
    try {
      const bytes = await file.arrayBuffer();
      const copy = bytes.slice(0);
      const { model, project } = await loader.request<'loaded'>({ type: 'load', fileName: file.name, bytes: copy }, [
        copy,
      ]);
      const first = plate.items.length === 0;
      for (const el of earlier) el.remove();
      if (project) {
        await openProject(file.name, project);
        if (first) frameObjects();
        continue;
      }
      const it = plate.add(file.name, bytes, model!);
      for (const w of it.model.warnings) message('warning', `${it.name}: ${w}`);
      for (const p of plate.problems(it)) message('warning', `${it.name}: ${p}`);
      invalidate();
      refreshObjects();
      if (first) frameObjects();
    } catch (e) {
      message('error', `${file.name}: ${errorText(e)}`, 'open');
    }
  }
}

/**
 * A project: its print settings into the print's panel (replacing the current ones, as importing a
 * settings file does), its objects onto the plate where it put them, with their settings, volumes and
 * layer ranges.
 */
async function openProject(fileName: string, p: LoadedProject): Promise<void> {
  if (p.printSettings) {
    try {
      store.fromJson(
        p.printSettings,
        infill.shipped.map((s) => s.name),
      );
      await infill.init();
      message('info', `Print settings from ${fileName}`);
    } catch (e) {
      message('error', `${fileName}: its print settings are not used: ${errorText(e)}`);
    }
  }
  for (const o of p.objects) {
    const it = plate.add(fileName, null, o.model, 'own', o.name);
    it.settings = { ...o.settings };
    if (o.layerHeightProfile) it.layerHeightProfile = o.layerHeightProfile;
    objectPanel.adopt(
      it,
      o.volumes.map((v) => ({
        kind: v.kind,
        name: v.name,
        shape: 'mesh' as const,
        ...boxOf(v.mesh),
        source: v.mesh,
        settings: { ...v.settings },
      })),
      o.layerRanges.map((r) => ({ fromZ: r.fromZ, toZ: r.toZ, settings: { ...r.settings } })),
    );
    for (const w of o.model.warnings) message('warning', `${it.name}: ${w}`);
    for (const pr of plate.problems(it)) message('warning', `${it.name}: ${pr}`);
  }
  for (const w of p.warnings) message('warning', `${fileName}: ${w}`);
  invalidate();
  refreshObjects();
}

ui.saveProject.addEventListener('click', async () => {
  if (plate.items.length === 0) return;
  // the settings file's: the presets and the settings changed (the library saves the placement ones as done)
  const printSettings = store.toJson();
  try {
    const { bytes } = await loader.request<'saved'>({
      type: 'save',
      items: plate.sliceItems(),
      options: store.options(),
      printSettings,
    });
    saveFile(`${plate.items[0].name}.3mf`, bytes, 'model/3mf');
    if (store.custom?.source === 'file')
      message('info', `The loaded infiller ${store.custom.fileName ?? store.custom.name} is not part of the project.`);
  } catch (e) {
    message('error', `Saving the project failed: ${errorText(e)}`);
  }
});

ui.open.addEventListener('change', () => {
  const files = [...(ui.open.files ?? [])];
  ui.open.value = '';
  void openFiles(files);
});

// drag and drop anywhere on the page
let dragDepth = 0;
const hasFiles = (e: DragEvent) => [...(e.dataTransfer?.types ?? [])].includes('Files');
window.addEventListener('dragenter', (e) => {
  if (!hasFiles(e)) return;
  e.preventDefault();
  dragDepth++;
  ui.drop.hidden = false;
});
window.addEventListener('dragover', (e) => {
  if (!hasFiles(e)) return;
  e.preventDefault();
  if (e.dataTransfer) e.dataTransfer.dropEffect = 'copy';
});
window.addEventListener('dragleave', () => {
  dragDepth = Math.max(0, dragDepth - 1);
  if (dragDepth === 0) ui.drop.hidden = true;
});
window.addEventListener('drop', (e) => {
  if (!hasFiles(e)) return;
  e.preventDefault();
  dragDepth = 0;
  ui.drop.hidden = true;
  void openFiles([...(e.dataTransfer?.files ?? [])]);
});

// ── settings ─────────────────────────────────────────────────────────────────
const { printers, filaments } = listPresets();
ui.printer.replaceChildren(...printers.map((p) => h('option', { value: p.id }, p.name)));
ui.filament.replaceChildren(...filaments.map((f) => h('option', { value: f.id }, f.name)));
ui.printer.value = store.printer;
ui.filament.value = store.filament;
ui.printer.addEventListener('change', () => {
  store.printer = ui.printer.value;
  store.changed();
});
ui.filament.addEventListener('change', () => {
  store.filament = ui.filament.value;
  store.changed();
});

const panel = buildSettingsPanel(byId('settings'), byId<HTMLInputElement>('settings-filter'), printSource(store), {
  idPrefix: 'set-',
  resetTitle: 'Back to the preset value',
  infillSlot: true,
  invalid: invalidFields,
});
invalidFields.onChange(() => updateSliceButton());
store.onChange(panel.refresh);
const infill = new InfillPanel(
  panel.infillSlot,
  store,
  async (spec) => (await loader.request<'infiller'>({ type: 'infiller', spec })).info,
  invalidFields,
);
void infill.init();

let settingsError: string | null = null;
store.onChange(() => {
  ui.printer.value = store.printer;
  ui.filament.value = store.filament;
  try {
    cfg = store.config();
    settingsError = null;
  } catch (e) {
    settingsError = errorText(e);
  }
  plate.setBed(bedShape(cfg));
  if (viewer?.setBed(plate.bed)) frameObjects();
  invalidate();
  // the selected object's settings show what they inherit from the print's
  refreshObjects();
});

ui.exportSettings.addEventListener('click', () => {
  saveFile('strata-settings.json', JSON.stringify(store.toJson(), null, 2) + '\n', 'application/json');
  if (store.custom?.source === 'file')
    message(
      'info',
      `The loaded infiller ${store.custom.fileName ?? store.custom.name} is not part of the settings file: give it to strata slice with --infill-shader or --infill-image.`,
    );
});
ui.importSettings.addEventListener('change', async () => {
  const file = ui.importSettings.files?.[0];
  ui.importSettings.value = '';
  if (!file) return;
  let obj: unknown;
  try {
    obj = JSON.parse(await file.text());
  } catch (e) {
    message('error', `${file.name} is not valid JSON: ${errorText(e)}`);
    return;
  }
  try {
    store.fromJson(
      obj,
      infill.shipped.map((s) => s.name),
    );
    panel.clearInvalid();
    await infill.init();
    message('info', `Settings from ${file.name}`);
  } catch (e) {
    message('error', `${file.name}: ${errorText(e)}`);
  }
});
ui.resetSettings.addEventListener('click', () => {
  store.overrides = {};
  store.custom = null;
  panel.clearInvalid();
  store.changed();
  void infill.init();
});

// ── slicing ──────────────────────────────────────────────────────────────────
/** The plate or settings changed: the last result no longer matches. */
function invalidate(): void {
  if (!result) return;
  result = null;
  ui.download.disabled = true;
  ui.viewPreview.disabled = true;
  ui.resultCard.hidden = true;
  toolpaths?.clear();
  setView('model');
}

function updateSliceButton(): void {
  ui.slice.disabled = slicing || plate.items.length === 0 || settingsError !== null;
  ui.saveProject.disabled = plate.items.length === 0;
  const bad = invalidFields.first();
  ui.slice.title =
    settingsError ??
    (plate.items.length === 0 ? 'Open a model first' : bad ? `A setting is not valid: ${bad.why}` : '');
  ui.download.title = bad && result ? `A setting is not valid: ${bad.why}` : '';
}

/**
 * Whether a refused field holds back `what` (Slice, Download): the slicer still has the value before
 * it, so the G-code would not be what the panel shows. Says which field, and shows it.
 */
function refusedForInvalidField(what: string): boolean {
  const bad = invalidFields.first();
  if (!bad) return false;
  message('error', `${what}: a setting is not valid. ${bad.why}. Correct it or reset it with ↺.`, 'slice');
  bad.input.closest('details')?.setAttribute('open', '');
  bad.input.scrollIntoView({ block: 'center' });
  bad.input.focus({ preventScroll: true });
  return true;
}

const STAGE_WORDS: Readonly<Record<string, string>> = {
  slicing: 'Slicing',
  planning: 'Planning',
  writing: 'Writing G-code',
};

function setSlicing(on: boolean): void {
  slicing = on;
  // the last stage's words would keep their width in the top bar
  if (!on) ui.jobText.textContent = '';
  ui.cancel.classList.toggle('off', !on);
  ui.slice.classList.toggle('off', on);
  ui.job.classList.toggle('off', !on);
  ui.progress.value = 0;
  updateSliceButton();
}

async function slice(): Promise<void> {
  if (slicing || plate.items.length === 0) return;
  if (refusedForInvalidField('Not sliced')) return;
  if (settingsError) {
    message('error', settingsError, 'slice');
    return;
  }
  clearMessages('slice');
  invalidate();
  setFaceMode(false);
  setSlicing(true);
  ui.jobText.textContent = 'Preparing…';
  performance.mark('strata:slice-start');
  try {
    const custom = await infill.spec();
    const items = plate.sliceItems();
    const name = plate.gcodeName();
    const reply = await slicerWorker.request<'sliced'>(
      { type: 'slice', items, options: store.options(), custom },
      [],
      (stage, fraction) => {
        // the last of these marks where slicing ended and the hand-over of the result began
        performance.mark('strata:slice-progress');
        ui.progress.value = Math.round(fraction * 100);
        ui.jobText.textContent = `${STAGE_WORDS[stage] ?? stage} ${Math.round(fraction * 100)} %`;
      },
    );
    showResult(reply, name);
    performance.mark('strata:slice-done');
  } catch (e) {
    performance.mark('strata:slice-done');
    if (e instanceof Cancelled) message('info', 'Slicing cancelled.', 'slice');
    else message('error', `Slicing failed: ${errorText(e)}`, 'slice');
  } finally {
    setSlicing(false);
  }
}

function showResult(r: Extract<FromWorker, { type: 'sliced' }>, name: string): void {
  result = { gcode: r.gcode, stats: r.stats, warnings: r.warnings, name };
  ui.download.disabled = false;
  ui.viewPreview.disabled = false;
  const s = r.stats;
  ui.stats.replaceChildren(
    h('dt', {}, 'Print time'),
    h('dd', {}, duration(s.printTimeSeconds)),
    h('dt', {}, 'Filament'),
    h('dd', {}, `${metres(s.filamentMm)} · ${grams(s.filamentGrams)}`),
    h('dt', {}, 'Layers'),
    h('dd', { id: 'stat-layers' }, String(s.layers)),
    h('dt', {}, 'Sliced in'),
    h('dd', {}, `${s.sliceSeconds.toFixed(1)} s on ${s.threads} thread${s.threads === 1 ? '' : 's'}`),
    h('dt', {}, 'G-code'),
    h('dd', {}, `${name}, ${(r.gcode.byteLength / 1024 / 1024).toFixed(1)} MB`),
  );
  if (r.warnings.length) ui.stats.append(h('ul', { class: 'warnings' }, ...r.warnings.map((w) => h('li', {}, w))));
  ui.resultCard.hidden = false;
  // the preview is drawn in a task of its own, after the result is announced
  const shown = result;
  setTimeout(() => {
    if (!preview || result !== shown) return;
    preview.show(r.preview);
    setView('preview');
  }, 0);
}

ui.slice.addEventListener('click', () => void slice());
ui.cancel.addEventListener('click', () => slicerWorker.cancel());
ui.download.addEventListener('click', () => {
  if (!result || refusedForInvalidField('Not downloaded')) return;
  saveFile(result.name, result.gcode, 'text/x-gcode');
});
setupSendPanel({
  after: ui.download,
  current: () => (result && !refusedForInvalidField('Not sent') ? { name: result.name, gcode: result.gcode } : null),
});

// the page is ready: tests and people can start
refreshObjects();
document.documentElement.dataset.ready = 'true';
