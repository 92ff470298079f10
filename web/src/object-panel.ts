/**
 * The selected object's own settings, volumes and layer ranges. A list names what the object holds
 * (its settings, each volume, each layer range); the chosen entry is edited below it: a volume's name,
 * centre and size (in the object's own axes, from its centre and bottom), a layer range's heights,
 * and the settings that may vary there (settings/scope.ts) in a settings panel like the print's,
 * showing what they inherit and marking what is set here. Volumes are added as a box, a cylinder or
 * a mesh file.
 */
import {
  SETTING_KEYS,
  SETTING_SCOPE,
  checkSettingScope,
  resolveScopedConfig,
  validateSetting,
  type ScopeUse,
  type SettingKey,
} from 'strata-slicer';
import { h } from './dom.js';
import { mm1 } from './format.js';
import type { Plate, PlateItem } from './plate.js';
import type { LoadedModel } from './protocol.js';
import { buildSettingsPanel, type InvalidFields, type PanelSource, type SettingsPanel } from './settings-panel.js';
import type { Overrides, SettingsStore } from './settings.js';
import {
  boxOf,
  KIND_INFO,
  SHAPE_LABELS,
  VOLUME_KINDS,
  type PlateRange,
  type PlateVolume,
  type VolumeKind,
  type VolumeShape,
} from './volumes.js';

/** Settings an object may have of its own, and those a modifier or a layer range may. */
const OBJECT_KEYS = SETTING_KEYS.filter((k) => SETTING_SCOPE[k] === 'object' || SETTING_SCOPE[k] === 'region');
const REGION_KEYS = SETTING_KEYS.filter((k) => SETTING_SCOPE[k] === 'region');
/** A layer range may also set what is the same for every object at one height (the layer height). */
const RANGE_KEYS = SETTING_KEYS.filter((k) => SETTING_SCOPE[k] === 'region' || SETTING_SCOPE[k] === 'layer');

/** Largest volume mesh file read, bytes. */
const MAX_VOLUME_BYTES = 128 * 1024 * 1024;

/** Smallest volume size, mm. */
const MIN_SIZE = 0.01;

export type PartTarget = { kind: 'object' } | { kind: 'volume'; id: number } | { kind: 'range'; id: number };

export interface ObjectPanelHost {
  plate: Plate;
  store: SettingsStore;
  /**
   * What changed: the part chosen (the 3D view highlights it), volumes (redraw them) or settings; for
   * the last two the last slice is out of date.
   */
  changed(what: 'selection' | 'volumes' | 'settings'): void;
  message(kind: 'error' | 'warning' | 'info', text: string): void;
  /** Read a mesh file (in the worker); null when it could not be read (the host says why). */
  loadMesh(file: File): Promise<LoadedModel | null>;
  /** Where refused setting fields are told. */
  invalid: InvalidFields;
}

export class ObjectPanel {
  target: PartTarget = { kind: 'object' };
  #item: PlateItem | null = null;
  #nextId = 1;
  #card: HTMLElement;
  #title: HTMLElement;
  #list = h('ul', { class: 'part-list', 'aria-label': 'What the object holds' });
  #editor = h('div', { class: 'part-editor' });
  #settings = h('div', { class: 'settings' });
  #filter = h('input', { type: 'search', placeholder: 'Find a setting', 'aria-label': 'Find an object setting' });
  #note = h('p', { class: 'muted small' });
  #kind = h(
    'select',
    { 'aria-label': 'Volume type' },
    ...VOLUME_KINDS.map((k) => h('option', { value: k }, KIND_INFO[k].label)),
  );
  #shape = h(
    'select',
    { 'aria-label': 'Volume shape' },
    h('option', { value: 'box' }, 'Box'),
    h('option', { value: 'cylinder' }, 'Cylinder'),
    h('option', { value: 'mesh' }, 'Mesh file…'),
  );
  #file = h('input', {
    type: 'file',
    class: 'visually-hidden',
    accept: '.stl,.obj,.3mf',
    'aria-label': 'Volume mesh file',
    tabindex: -1,
  });
  #panel: SettingsPanel | null = null;
  #shown = '';

  constructor(
    card: HTMLElement,
    private host: ObjectPanelHost,
  ) {
    this.#card = card;
    this.#title = h('span', { class: 'object-name' });
    const addVolume = h('button', { type: 'button', class: 'button small' }, 'Add volume');
    const addRange = h('button', { type: 'button', class: 'button small' }, 'Add layer range');
    card.append(
      h('div', { class: 'card-head' }, h('h2', { id: 'object-card-title' }, 'Object settings'), this.#title),
      this.#list,
      h('div', { class: 'row add-row' }, this.#kind, this.#shape),
      h('div', { class: 'row' }, addVolume, addRange, this.#file),
      this.#editor,
      this.#note,
      this.#filter,
      this.#settings,
    );
    addVolume.addEventListener('click', () => {
      if (this.#shape.value === 'mesh') this.#file.click();
      else this.#addVolume(this.#kind.value as VolumeKind, this.#shape.value as 'box' | 'cylinder');
    });
    this.#file.addEventListener('change', () => {
      const f = this.#file.files?.[0];
      this.#file.value = '';
      if (f) void this.#addMeshVolume(this.#kind.value as VolumeKind, f);
    });
    addRange.addEventListener('click', () => this.#addRange());
  }

  /** Show this object (none: the card hides); a different object starts at its own settings. */
  show(item: PlateItem | null): void {
    if (item !== this.#item) this.target = { kind: 'object' };
    this.#item = item;
    this.#card.hidden = !item;
    if (!item) {
      // a hidden panel's refused fields hold nothing back
      this.#panel?.clearInvalid();
      return;
    }
    if (this.target.kind === 'volume' && !this.#volume()) this.target = { kind: 'object' };
    if (this.target.kind === 'range' && !this.#range()) this.target = { kind: 'object' };
    this.#title.textContent = item.name;
    this.#renderList();
    this.#renderEditor();
  }

  /** Edit this volume of this object (picked in the 3D view). */
  selectVolume(item: PlateItem, volumeId: number): void {
    this.#item = item;
    this.target = { kind: 'volume', id: volumeId };
    this.show(item);
  }

  /** Delete the volume or layer range being edited (the Delete key); false when the object's own settings are. */
  deleteSelected(): boolean {
    const it = this.#item,
      v = this.#volume(),
      r = this.#range();
    if (!it || (!v && !r)) return false;
    if (v) it.volumes = it.volumes.filter((x) => x !== v);
    if (r) it.layerRanges = it.layerRanges.filter((x) => x !== r);
    this.#choose({ kind: 'object' }, 'volumes');
    return true;
  }

  /** The volume being edited, if any (the 3D view highlights it). */
  get selectedVolume(): number | null {
    return this.target.kind === 'volume' ? this.target.id : null;
  }

  #volume(): PlateVolume | undefined {
    const t = this.target;
    return t.kind === 'volume' ? this.#item?.volumes.find((v) => v.id === t.id) : undefined;
  }

  #range(): PlateRange | undefined {
    const t = this.target;
    return t.kind === 'range' ? this.#item?.layerRanges.find((r) => r.id === t.id) : undefined;
  }

  #choose(target: PartTarget, what: 'selection' | 'volumes' = 'selection'): void {
    this.target = target;
    this.#renderList();
    this.#renderEditor();
    this.host.changed(what);
  }

  // ── the list ───────────────────────────────────────────────────────────────
  #renderList(): void {
    const it = this.#item!;
    const count = (o: Overrides) => Object.keys(o).length;
    const entry = (target: PartTarget, current: boolean, swatch: string | null, name: string, meta: string) => {
      const b = h(
        'button',
        { type: 'button', 'aria-current': String(current) },
        swatch ? h('span', { class: 'swatch', style: `background:${swatch}` }) : null,
        h('span', { class: 'name' }, name),
        h('span', { class: 'meta' }, meta),
      );
      b.addEventListener('click', () => this.#choose(target));
      return h('li', {}, b);
    };
    const settingsMeta = (n: number) => (n ? `${n} setting${n === 1 ? '' : 's'}` : '');
    const t = this.target;
    this.#list.replaceChildren(
      entry(
        { kind: 'object' },
        t.kind === 'object',
        null,
        'Object',
        settingsMeta(count(it.settings)) || 'as the print',
      ),
      ...it.volumes.map((v) =>
        entry(
          { kind: 'volume', id: v.id },
          t.kind === 'volume' && t.id === v.id,
          KIND_INFO[v.kind].colour,
          v.name,
          [SHAPE_LABELS[v.shape], settingsMeta(count(v.settings))].filter(Boolean).join(', '),
        ),
      ),
      ...it.layerRanges.map((r) =>
        entry(
          { kind: 'range', id: r.id },
          t.kind === 'range' && t.id === r.id,
          null,
          `Layers ${mm1(r.fromZ)}–${mm1(r.toZ)} mm`,
          settingsMeta(count(r.settings)),
        ),
      ),
    );
  }

  // ── the editor ─────────────────────────────────────────────────────────────
  /**
   * Show the chosen part's editor and settings; only when another part is chosen are they built anew
   * (the fields keep focus, scroll and open groups while the user works in them).
   */
  #renderEditor(): void {
    const it = this.#item!;
    const v = this.#volume(),
      r = this.#range();
    const shown = `${it.id}:${this.target.kind}:${v?.id ?? r?.id ?? ''}`;
    if (shown === this.#shown) {
      this.#panel?.refresh();
      return;
    }
    this.#shown = shown;
    // what was typed into the panel being replaced is dropped with it
    this.#panel?.clearInvalid();
    if (v) this.#volumeEditor(it, v);
    else if (r) this.#rangeEditor(it, r);
    else this.#editor.replaceChildren();
    this.#settings.replaceChildren();
    this.#panel = null;
    // a new search box for the new list (the panel listens to the one it is given)
    const filter = h('input', {
      type: 'search',
      placeholder: 'Find a setting',
      'aria-label': 'Find an object setting',
    });
    this.#filter.replaceWith(filter);
    this.#filter = filter;
    const source = v
      ? v.kind === 'modifier'
        ? this.#source(it, 'modifier', v)
        : null
      : r
        ? this.#source(it, 'layer range', r)
        : this.#source(it, 'object', null);
    this.#filter.hidden = !source;
    this.#note.textContent = v
      ? KIND_INFO[v.kind].help + (v.kind === 'modifier' ? ' Its settings (those that may vary inside an object):' : '')
      : r
        ? 'Settings for the layers whose height lies in the range (those that may vary inside an object):'
        : 'Settings for this object only, over the print’s (unchanged ones show what it inherits):';
    if (!source) return;
    const suffix = v ? '(modifier)' : r ? '(layer range)' : '(object)';
    const panel = buildSettingsPanel(this.#settings, this.#filter, source, {
      idPrefix: 'obj-set-',
      nameSuffix: suffix,
      resetTitle: v || r ? 'Back to the object’s value' : 'Back to the print’s value',
      open: (stage) => stage === 'infill' || stage === 'walls',
      invalid: this.host.invalid,
    });
    this.#panel = panel;
  }

  /** A number field with a visible label (its accessible name) that calls `set` with valid numbers. */
  #numberField(
    label: string,
    unit: string,
    value: number,
    min: number,
    max: number,
    set: (v: number) => void,
  ): HTMLElement {
    const input = h('input', {
      type: 'number',
      step: 'any',
      inputmode: 'decimal',
      min,
      max,
      value: String(round3(value)),
    });
    input.addEventListener('change', () => {
      const n = Number(input.value);
      if (input.value.trim() === '' || !Number.isFinite(n) || n < min || n > max) {
        this.host.message('error', `${label} must be a number from ${min} to ${max} ${unit}`);
        input.value = String(round3(value));
        return;
      }
      set(n);
    });
    return h('label', { class: 'field' }, h('span', {}, label, ' ', h('em', {}, unit)), input);
  }

  #volumeEditor(it: PlateItem, v: PlateVolume): void {
    const o = this.host.plate.origin(it);
    const axes = ['X', 'Y', 'Z'] as const;
    const name = h('input', { type: 'text', value: v.name, maxlength: 100, 'aria-label': 'Volume name' });
    name.addEventListener('change', () => {
      const n = name.value.trim();
      if (n) v.name = n;
      name.value = v.name;
      this.#renderList();
      this.host.changed('settings');
    });
    const del = h('button', { type: 'button', class: 'button small danger' }, 'Delete volume');
    del.addEventListener('click', () => {
      it.volumes = it.volumes.filter((x) => x !== v);
      this.#choose({ kind: 'object' }, 'volumes');
    });
    const moved = () => {
      this.#renderList();
      this.host.changed('volumes');
    };
    this.#editor.replaceChildren(
      h(
        'div',
        { class: 'row' },
        h('span', { class: 'swatch', style: `background:${KIND_INFO[v.kind].colour}` }),
        h('strong', {}, `${KIND_INFO[v.kind].label}, ${SHAPE_LABELS[v.shape]}`),
      ),
      h('label', { class: 'field' }, h('span', {}, 'Name'), name),
      h(
        'p',
        { class: 'muted small' },
        'Centre from the object’s centre (X, Y) and bottom (Z), in its own axes; it turns, scales and moves with the object.',
      ),
      h(
        'div',
        { class: 'grid3' },
        ...axes.map((a, k) =>
          this.#numberField(
            `Centre ${a}`,
            'mm',
            v.centre[k] - o[k],
            -10000,
            10000,
            (n) => ((v.centre[k] = o[k] + n), moved()),
          ),
        ),
        ...axes.map((a, k) =>
          this.#numberField(`Size ${a}`, 'mm', v.size[k], MIN_SIZE, 10000, (n) => ((v.size[k] = n), moved())),
        ),
      ),
      h('div', { class: 'row' }, del),
    );
  }

  #rangeEditor(it: PlateItem, r: PlateRange): void {
    const del = h('button', { type: 'button', class: 'button small danger' }, 'Delete layer range');
    del.addEventListener('click', () => {
      it.layerRanges = it.layerRanges.filter((x) => x !== r);
      this.#choose({ kind: 'object' }, 'volumes');
    });
    const edited = (k: 'fromZ' | 'toZ') => (n: number) => {
      const from = k === 'fromZ' ? n : r.fromZ,
        to = k === 'toZ' ? n : r.toZ;
      const other = it.layerRanges.find((o) => o !== r && o.fromZ < to && from < o.toZ);
      if (from >= to || other) {
        const why = other
          ? `it would overlap the range ${mm1(other.fromZ)}–${mm1(other.toZ)} mm`
          : 'it must start below where it ends';
        this.host.message('error', `Layers ${from}–${to} mm: ${why}`);
        this.#rangeEditor(it, r);
        return;
      }
      r[k] = n;
      it.layerRanges.sort((a, b) => a.fromZ - b.fromZ || a.toZ - b.toZ);
      this.#renderList();
      this.host.changed('settings');
    };
    this.#editor.replaceChildren(
      h('p', { class: 'muted small' }, 'Heights above the bed, mm: the layers from the first to below the second.'),
      h(
        'div',
        { class: 'grid2' },
        this.#numberField('From Z', 'mm', r.fromZ, 0, 10000, edited('fromZ')),
        this.#numberField('To Z', 'mm', r.toZ, 0, 10000, edited('toZ')),
      ),
      h('div', { class: 'row' }, del),
    );
  }

  // ── settings sources ───────────────────────────────────────────────────────
  /**
   * The object's own settings (`part` null), a modifier's or a layer range's: what they show when not
   * set here (the print's values, and for a part the object's over them), and what the slicer would
   * refuse in them, in its words.
   */
  #source(it: PlateItem, use: ScopeUse, part: PlateVolume | PlateRange | null): PanelSource {
    const own = part ? part.settings : it.settings;
    const { store } = this.host;
    const where = (): string => {
      if (!part) return `object "${it.name}"`;
      if ('kind' in part) return `${part.kind} "${part.name}" of "${it.name}"`;
      return `object "${it.name}" layers ${part.fromZ}–${part.toZ} mm`;
    };
    return {
      keys: !part ? OBJECT_KEYS : 'kind' in part ? REGION_KEYS : RANGE_KEYS,
      isSet: (key) => key in own,
      values: () => {
        let print;
        try {
          print = store.config();
        } catch {
          return { values: { ...store.base().settings, ...(part ? it.settings : {}), ...own }, problem: null };
        }
        const inherited = { ...print.settings, ...(part ? it.settings : {}) };
        try {
          const layers: Array<{ settings: Overrides; use: ScopeUse; where: string }> = [
            { settings: it.settings, use: 'object', where: `object "${it.name}"` },
          ];
          if (part) layers.push({ settings: part.settings, use, where: where() });
          const config = resolveScopedConfig(store.options(), layers);
          return { values: { ...config.settings, ...(part ? it.settings : {}), ...own }, problem: null };
        } catch (e) {
          return { values: { ...inherited, ...own }, problem: e instanceof Error ? e.message : String(e) };
        }
      },
      set: (key: SettingKey, value: unknown) => {
        checkSettingScope(key, use, where());
        own[key] = validateSetting(key, value, 'setting');
        this.#renderList();
        this.host.changed('settings');
      },
      reset: (key: SettingKey) => {
        delete own[key];
        this.#renderList();
        this.host.changed('settings');
      },
    };
  }

  // ── adding ─────────────────────────────────────────────────────────────────
  #nameFor(it: PlateItem, kind: VolumeKind): string {
    const used = new Set(it.volumes.map((v) => v.name));
    let n = 1;
    while (used.has(`${KIND_INFO[kind].label} ${n}`)) n++;
    return `${KIND_INFO[kind].label} ${n}`;
  }

  #add(it: PlateItem, v: Omit<PlateVolume, 'id' | 'settings'>): void {
    const volume: PlateVolume = { ...v, id: this.#nextId++, settings: {} };
    it.volumes.push(volume);
    this.#choose({ kind: 'volume', id: volume.id }, 'volumes');
  }

  /** A box or cylinder in the middle of the object, half its size. */
  #addVolume(kind: VolumeKind, shape: 'box' | 'cylinder'): void {
    const it = this.#item;
    if (!it) return;
    const o = this.host.plate.origin(it);
    const b = this.host.plate.modelBox(it);
    const size = [0, 1, 2].map((k) => round3(Math.max(MIN_SIZE, (b.max[k] - b.min[k]) / 2))) as [
      number,
      number,
      number,
    ];
    const centre: [number, number, number] = [o[0], o[1], o[2] + round3((b.max[2] - b.min[2]) / 2)];
    this.#add(it, { kind, shape, name: this.#nameFor(it, kind), centre, size });
  }

  /**
   * A volume from a mesh file: kept at its own coordinates when it meets the object there (made for
   * it), else put in the object's middle.
   */
  async #addMeshVolume(kind: VolumeKind, file: File): Promise<void> {
    const it = this.#item;
    if (!it) return;
    if (file.size > MAX_VOLUME_BYTES) {
      this.host.message('error', `${file.name} is larger than ${MAX_VOLUME_BYTES / 1024 / 1024} MB`);
      return;
    }
    const model = await this.host.loadMesh(file);
    if (!model || this.#item !== it) return;
    const source = { positions: model.vertices, indices: model.indices };
    const box = boxOf(source);
    const b = this.host.plate.modelBox(it);
    const meets = [0, 1, 2].every(
      (k) => box.centre[k] + box.size[k] / 2 >= b.min[k] && box.centre[k] - box.size[k] / 2 <= b.max[k],
    );
    const centre = meets ? box.centre : ([0, 1, 2].map((k) => (b.min[k] + b.max[k]) / 2) as [number, number, number]);
    const size = box.size.map((s) => Math.max(MIN_SIZE, s)) as [number, number, number];
    const base = file.name.replace(/\.[^.]*$/, '');
    this.#add(it, { kind, shape: 'mesh' as VolumeShape, name: base || this.#nameFor(it, kind), centre, size, source });
    if (!meets) this.host.message('info', `${file.name} lay outside ${it.name}: it is placed in the object’s middle.`);
  }

  /** A layer range over the middle third of the object's height, or above the last one (ranges do not overlap). */
  #addRange(): void {
    const it = this.#item;
    if (!it) return;
    const height = this.host.plate.size(it)[2];
    const tenth = (v: number) => Math.round(v * 10) / 10;
    let fromZ = tenth(height / 3);
    let toZ = Math.max(fromZ + 0.1, tenth((2 * height) / 3));
    if (it.layerRanges.some((o) => o.fromZ < toZ && fromZ < o.toZ)) {
      fromZ = Math.max(...it.layerRanges.map((o) => o.toZ));
      toZ = tenth(fromZ + Math.max(1, height / 6));
    }
    const r: PlateRange = { id: this.#nextId++, fromZ, toZ, settings: {} };
    it.layerRanges.push(r);
    it.layerRanges.sort((a, b) => a.fromZ - b.fromZ || a.toZ - b.toZ);
    this.#choose({ kind: 'range', id: r.id }, 'volumes');
  }

  /** Take a project's volumes and layer ranges into an object (ids given here). */
  adopt(it: PlateItem, volumes: Array<Omit<PlateVolume, 'id'>>, ranges: Array<Omit<PlateRange, 'id'>>): void {
    it.volumes = volumes.map((v) => ({ ...v, id: this.#nextId++ }));
    it.layerRanges = ranges.map((r) => ({ ...r, id: this.#nextId++ }));
  }
}

function round3(v: number): number {
  return Math.round(v * 1000) / 1000;
}
