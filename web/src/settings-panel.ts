/**
 * A settings panel, built from the schema: one collapsible group per stage (most used first), one
 * field per setting with its unit, range and description; settings set here are marked and can be
 * reset. The print's panel lists every setting; an object's, a modifier's or a layer range's lists
 * those that may vary there (the library's SETTING_SCOPE). A new setting in the schema appears with no edit.
 */
import { SCHEMA, SETTING_KEYS, type SettingDef, type SettingKey } from 'strata-slicer';
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
const STAGE_ORDER = [
  'slice',
  'walls',
  'skin',
  'infill',
  'support',
  'adhesion',
  'cooling',
  'travel',
  'machine',
  'gcode',
  'mesh',
  'runtime',
];

/** Groups open at first. */
const OPEN_STAGES = new Set(['slice', 'walls', 'infill', 'adhesion', 'support']);

function rangeText(def: SettingDef): string {
  if (def.type === 'number' || def.type === 'integer')
    return `${def.min}–${def.max}${def.unit && def.unit !== 'count' ? ' ' + def.unit : ''}`;
  return '';
}

function stepOf(def: SettingDef): string {
  if (def.type === 'integer') return '1';
  if (def.type !== 'number') return 'any';
  const span = def.max - def.min;
  return span <= 5 ? '0.01' : span <= 50 ? '0.1' : '1';
}

/**
 * The fields, in every panel, whose text was refused (out of range, not a number): the slicer still
 * has the value before, so Slice and Download wait until each is corrected or reset, and name it.
 */
export class InvalidFields {
  #fields = new Map<HTMLElement, string>();
  #listeners: Array<() => void> = [];

  /** Mark a field refused, with why in words; `why` null: it is valid again. */
  set(input: HTMLElement, why: string | null): void {
    const had = this.#fields.get(input);
    if (why === null) this.#fields.delete(input);
    else this.#fields.set(input, why);
    if (had !== (why ?? undefined)) for (const fn of this.#listeners) fn();
  }

  /** The first refused field (in the order they were refused) and why, or null. */
  first(): { input: HTMLElement; why: string } | null {
    for (const [input, why] of this.#fields) return { input, why };
    return null;
  }

  onChange(fn: () => void): void {
    this.#listeners.push(fn);
  }
}

interface Field {
  key: SettingKey;
  row: HTMLElement;
  input: HTMLInputElement | HTMLSelectElement | HTMLTextAreaElement;
  error: HTMLElement;
  searchText: string;
  /** Clear the field's refusal. */
  valid(): void;
}

/** What a panel shows and changes: the print's settings, or an object's, a modifier's, a layer range's. */
export interface PanelSource {
  /** The settings listed, in schema order. */
  keys: readonly SettingKey[];
  /** Whether a setting is set here (marked as changed, with its reset button). */
  isSet(key: SettingKey): boolean;
  /** Every value shown (set here, else inherited), and what is wrong with them together, if anything. */
  values(): { values: Readonly<Partial<Record<SettingKey, unknown>>>; problem: string | null };
  /** Set one (throws a StrataError naming the problem when the value is not allowed). */
  set(key: SettingKey, value: unknown): void;
  reset(key: SettingKey): void;
}

export interface PanelOptions {
  /** Prefix of the fields' element ids (unique on the page). */
  idPrefix: string;
  /** Added to each field's accessible name ("Infill density (object)"), so panels side by side differ. */
  nameSuffix?: string;
  /** The reset button's tooltip. */
  resetTitle: string;
  /** Groups open at first (default: the common ones). */
  open?: (stage: string) => boolean;
  /** Put the custom-infill controls' slot after the infill pattern (the print's panel). */
  infillSlot?: boolean;
  /** Where refused fields are told (Slice and Download wait for them). */
  invalid?: InvalidFields;
}

export interface SettingsPanel {
  /** Show the source's values (after they changed elsewhere). */
  refresh(): void;
  /** Drop what was typed into refused fields and show the source's values (the panel is replaced, or everything was reset). */
  clearInvalid(): void;
  /** The element custom-infill controls go into (inside the infill group, after the pattern). */
  infillSlot: HTMLElement;
}

export function buildSettingsPanel(
  container: HTMLElement,
  filter: HTMLInputElement,
  source: PanelSource,
  opts: PanelOptions,
): SettingsPanel {
  const fields: Field[] = [];
  const groups = new Map<
    string,
    { details: HTMLDetailsElement; body: HTMLElement; count: HTMLElement; fields: Field[] }
  >();
  const problem = h('p', { class: 'settings-error', role: 'alert', hidden: true });
  container.append(problem);
  const infillSlot = h('div', { class: 'infill-custom' });
  const isOpen = opts.open ?? ((stage: string) => OPEN_STAGES.has(stage));

  const rank = (stage: string) => {
    const i = STAGE_ORDER.indexOf(stage);
    return i < 0 ? STAGE_ORDER.length : i;
  };
  const keys = [...source.keys].sort((a, b) => rank(SCHEMA[a].stage) - rank(SCHEMA[b].stage));
  for (const key of keys) {
    const def: SettingDef = SCHEMA[key];
    let g = groups.get(def.stage);
    if (!g) {
      const count = h('span', { class: 'count' });
      const body = h('div', { class: 'group-body' });
      const details = h(
        'details',
        { class: 'group', open: isOpen(def.stage) },
        h('summary', {}, STAGE_TITLES[def.stage] ?? labelOf(def.stage), count),
        body,
      );
      g = { details, body, count, fields: [] };
      groups.set(def.stage, g);
      container.append(details);
    }
    const id = `${opts.idPrefix}${key}`;
    const label = labelOf(key);
    const name = opts.nameSuffix ? `${label} ${opts.nameSuffix}` : undefined;
    const helpId = `${id}-help`;
    let input: Field['input'];
    if (def.type === 'boolean') {
      input = h('input', { id, type: 'checkbox', 'aria-describedby': helpId, 'aria-label': name });
    } else if (def.type === 'enum') {
      input = h(
        'select',
        { id, 'aria-describedby': helpId, 'aria-label': name },
        ...def.values.map((v) => h('option', { value: v }, v)),
      );
    } else if (def.type === 'string') {
      input = h('textarea', {
        id,
        'aria-describedby': helpId,
        'aria-label': name,
        spellcheck: 'false',
        rows: 6,
        maxlength: def.maxLength,
      });
    } else {
      input = h('input', {
        id,
        type: 'number',
        min: def.min,
        max: def.max,
        step: stepOf(def),
        inputmode: 'decimal',
        'aria-describedby': helpId,
        'aria-label': name,
        placeholder: def.nullable ? 'auto' : undefined,
      });
    }
    const reset = h(
      'button',
      {
        type: 'button',
        class: 'reset',
        title: opts.resetTitle,
        'aria-label': `Reset ${label}${opts.nameSuffix ? ' ' + opts.nameSuffix : ''}`,
      },
      '↺',
    );
    const unit =
      def.unit && def.unit !== 'count' ? h('span', { class: 'unit' }, def.unit) : h('span', { class: 'unit' });
    const range = rangeText(def);
    const help = h(
      'p',
      { class: 'help', id: helpId },
      def.description,
      range ? h('span', { class: 'range' }, ` (${range})`) : null,
    );
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
    if (key === 'infillPattern' && opts.infillSlot) g.body.append(infillSlot);
    const field: Field = {
      key,
      row,
      input,
      error,
      searchText: `${key} ${label} ${def.description}`.toLowerCase(),
      valid: () => {},
    };
    fields.push(field);
    g.fields.push(field);

    const fieldName = name ?? label;
    const commit = () => {
      const value = readValue(def, input);
      try {
        field.valid();
        source.set(key, value);
      } catch (e) {
        const why = e instanceof Error ? e.message.replace(/^setting /, '') : String(e);
        error.textContent = why;
        error.hidden = false;
        row.classList.add('invalid');
        input.setAttribute('aria-invalid', 'true');
        opts.invalid?.set(input, `${fieldName}: ${why}`);
      }
    };
    field.valid = () => {
      error.hidden = true;
      row.classList.remove('invalid');
      input.removeAttribute('aria-invalid');
      opts.invalid?.set(input, null);
    };
    input.addEventListener('change', commit);
    reset.addEventListener('click', () => {
      field.valid();
      source.reset(key);
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
    const { values, problem: wrong } = source.values();
    problem.textContent = wrong ?? '';
    problem.hidden = wrong === null;
    for (const g of groups.values()) {
      const n = g.fields.filter((f) => source.isSet(f.key)).length;
      g.count.textContent = n ? `${n} changed` : '';
    }
    for (const f of fields) {
      f.row.classList.toggle('changed', source.isSet(f.key));
      if (f.row.classList.contains('invalid') || document.activeElement === f.input) continue;
      writeValue(SCHEMA[f.key], f.input, values[f.key]);
    }
  };
  refresh();
  const clearInvalid = () => {
    for (const f of fields) f.valid();
    refresh();
  };
  return { refresh, clearInvalid, infillSlot };
}

/** The print's settings: presets and the settings the user changed, kept by the store. */
export function printSource(store: SettingsStore): PanelSource {
  return {
    keys: SETTING_KEYS,
    isSet: (key) => key in store.overrides,
    values: () => {
      try {
        return { values: { ...store.config().settings, ...store.overrides }, problem: null };
      } catch (e) {
        return {
          values: { ...store.base().settings, ...store.overrides },
          problem: e instanceof Error ? e.message : String(e),
        };
      }
    },
    set: (key, value) => store.set(key, value),
    reset: (key) => store.reset(key),
  };
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
