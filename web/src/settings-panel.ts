/**
 * The settings panel, built from the schema: one collapsible group per stage (in schema order),
 * one field per setting with its unit, range and description; changed settings are marked and can
 * be reset. A new setting in the schema appears here with no edit.
 */
import { SCHEMA, SETTING_KEYS, type SettingDef, type SettingKey } from '../../src/settings/schema.js';
import type { Config } from '../../src/settings/resolve.js';
import { h } from './dom.js';
import { labelOf } from './format.js';
import type { SettingsStore } from './settings.js';

/** Friendlier titles for some stages; any other stage is titled from its name. */
const STAGE_TITLES: Readonly<Record<string, string>> = {
  machine: 'Printer',
  mesh: 'Placement',
  slice: 'Layers',
  walls: 'Walls and speeds',
  skin: 'Top and bottom',
  infill: 'Infill',
  adhesion: 'Adhesion',
  support: 'Support',
  travel: 'Travel and retraction',
  cooling: 'Cooling and temperature',
  gcode: 'Filament and G-code',
  runtime: 'Slicing',
};

/** Where known stages go in the panel (most used first); any other stage follows in schema order. */
const STAGE_ORDER = ['slice', 'walls', 'skin', 'infill', 'support', 'adhesion', 'cooling', 'travel', 'machine', 'gcode', 'mesh', 'runtime'];

/** Groups open at first. */
const OPEN_STAGES = new Set(['slice', 'walls', 'infill', 'adhesion', 'support']);

function rangeText(def: SettingDef): string {
  if (def.type === 'number' || def.type === 'integer') return `${def.min}–${def.max}${def.unit && def.unit !== 'count' ? ' ' + def.unit : ''}`;
  return '';
}

function stepOf(def: SettingDef): string {
  if (def.type === 'integer') return '1';
  if (def.type !== 'number') return 'any';
  const span = def.max - def.min;
  return span <= 5 ? '0.01' : span <= 50 ? '0.1' : '1';
}

interface Field {
  key: SettingKey;
  row: HTMLElement;
  input: HTMLInputElement | HTMLSelectElement | HTMLTextAreaElement;
  error: HTMLElement;
  searchText: string;
}

export interface SettingsPanel {
  /** Show the store's values (after presets or settings changed elsewhere). */
  refresh(): void;
  /** The element custom-infill controls go into (inside the infill group, after the pattern). */
  infillSlot: HTMLElement;
}

export function buildSettingsPanel(container: HTMLElement, filter: HTMLInputElement, store: SettingsStore): SettingsPanel {
  const fields: Field[] = [];
  const groups = new Map<string, { details: HTMLDetailsElement; body: HTMLElement; count: HTMLElement; fields: Field[] }>();
  const problem = h('p', { class: 'settings-error', role: 'alert', hidden: true });
  container.append(problem);
  const infillSlot = h('div', { class: 'infill-custom' });

  const rank = (stage: string) => {
    const i = STAGE_ORDER.indexOf(stage);
    return i < 0 ? STAGE_ORDER.length : i;
  };
  const keys = [...SETTING_KEYS].sort((a, b) => rank(SCHEMA[a].stage) - rank(SCHEMA[b].stage));
  for (const key of keys) {
    const def: SettingDef = SCHEMA[key];
    let g = groups.get(def.stage);
    if (!g) {
      const count = h('span', { class: 'count' });
      const body = h('div', { class: 'group-body' });
      const details = h('details', { class: 'group', open: OPEN_STAGES.has(def.stage) }, h('summary', {}, STAGE_TITLES[def.stage] ?? labelOf(def.stage), count), body);
      g = { details, body, count, fields: [] };
      groups.set(def.stage, g);
      container.append(details);
    }
    const id = `set-${key}`;
    const label = labelOf(key);
    const helpId = `${id}-help`;
    let input: Field['input'];
    if (def.type === 'boolean') {
      input = h('input', { id, type: 'checkbox', 'aria-describedby': helpId });
    } else if (def.type === 'enum') {
      input = h('select', { id, 'aria-describedby': helpId }, ...def.values.map((v) => h('option', { value: v }, v)));
    } else if (def.type === 'string') {
      input = h('textarea', { id, 'aria-describedby': helpId, spellcheck: 'false', rows: 6, maxlength: def.maxLength });
    } else {
      input = h('input', { id, type: 'number', min: def.min, max: def.max, step: stepOf(def), inputmode: 'decimal', 'aria-describedby': helpId, placeholder: def.nullable ? 'auto' : undefined });
    }
    const reset = h('button', { type: 'button', class: 'reset', title: 'Back to the preset value', 'aria-label': `Reset ${label}` }, '↺');
    const unit = def.unit && def.unit !== 'count' ? h('span', { class: 'unit' }, def.unit) : h('span', { class: 'unit' });
    const range = rangeText(def);
    const help = h('p', { class: 'help', id: helpId }, def.description, range ? h('span', { class: 'range' }, ` (${range})`) : null);
    const error = h('p', { class: 'error', role: 'alert', hidden: true });
    const wide = def.type === 'string';
    const row = h(
      'div',
      { class: `setting${wide ? ' wide' : ''}`, 'data-key': key },
      h('label', { for: id, title: key }, label),
      wide ? input : h('div', { class: 'control' }, input, unit, reset),
      wide ? h('div', { class: 'control' }, reset) : null,
      help,
      error,
    );
    g.body.append(row);
    if (key === 'infillPattern') g.body.append(infillSlot);
    const field: Field = { key, row, input, error, searchText: `${key} ${label} ${def.description}`.toLowerCase() };
    fields.push(field);
    g.fields.push(field);

    const commit = () => {
      const value = readValue(def, input);
      try {
        store.set(key, value);
        error.hidden = true;
        row.classList.remove('invalid');
      } catch (e) {
        error.textContent = e instanceof Error ? e.message.replace(/^setting /, '') : String(e);
        error.hidden = false;
        row.classList.add('invalid');
      }
    };
    input.addEventListener('change', commit);
    reset.addEventListener('click', () => {
      error.hidden = true;
      row.classList.remove('invalid');
      store.reset(key);
    });
  }

  filter.addEventListener('input', () => {
    const q = filter.value.trim().toLowerCase();
    for (const f of fields) f.row.classList.toggle('hidden-by-filter', q !== '' && !f.searchText.includes(q));
    for (const g of groups.values()) {
      const any = g.fields.some((f) => !f.row.classList.contains('hidden-by-filter'));
      g.details.hidden = !any;
      if (q && any) g.details.open = true;
    }
  });

  const refresh = () => {
    let cfg: Config;
    try {
      cfg = store.config();
      problem.hidden = true;
    } catch (e) {
      problem.textContent = e instanceof Error ? e.message : String(e);
      problem.hidden = false;
      cfg = store.base();
    }
    for (const g of groups.values()) {
      const n = g.fields.filter((f) => f.key in store.overrides).length;
      g.count.textContent = n ? `${n} changed` : '';
    }
    for (const f of fields) {
      f.row.classList.toggle('changed', f.key in store.overrides);
      if (f.row.classList.contains('invalid') || document.activeElement === f.input) continue;
      writeValue(SCHEMA[f.key], f.input, f.key in store.overrides ? store.overrides[f.key] : cfg[f.key]);
    }
  };
  store.onChange(refresh);
  refresh();
  return { refresh, infillSlot };
}

function readValue(def: SettingDef, input: Field['input']): unknown {
  if (def.type === 'boolean') return (input as HTMLInputElement).checked;
  if (def.type === 'enum' || def.type === 'string') return input.value;
  const t = input.value.trim();
  if (t === '') return def.nullable ? null : '';
  return Number(t);
}

function writeValue(def: SettingDef, input: Field['input'], value: unknown): void {
  if (def.type === 'boolean') (input as HTMLInputElement).checked = value === true;
  else if (value === null || value === undefined) input.value = '';
  else input.value = String(value);
}
