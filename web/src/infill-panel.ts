/**
 * Custom infill controls (inside the settings' infill group): the infillers shipped with Strata, or
 * a shader.glsl / cells.png the user loads, with the infiller's ui_ parameters. The shader compiler
 * loads in the worker the first time one is chosen; a shader that does not compile is shown in words.
 */
import type { CustomInfillSpec } from '../../src/infill/patterns/custom.js';
import { h } from './dom.js';
import type { InfillerDescription } from './protocol.js';
import type { CustomChoice, SettingsStore } from './settings.js';
import type { InvalidFields } from './settings-panel.js';

export interface ShippedInfiller {
  name: string;
  file: 'shader.glsl' | 'cells.png';
  preview: boolean;
}

/** Largest infiller file read, bytes. */
const MAX_INFILLER_BYTES = 16 * 1024 * 1024;

export class InfillPanel {
  shipped: ShippedInfiller[] = [];
  #files = new Map<string, { shader?: string; image?: Uint8Array }>();
  #select = h('select', { id: 'custom-infill', 'aria-label': 'Custom infill' });
  #fileInput = h('input', {
    id: 'infill-file',
    type: 'file',
    class: 'visually-hidden',
    accept: '.glsl,.frag,.txt,.png,image/png',
    'aria-label': 'Load infill shader or image',
  });
  #preview = h('img', { alt: '', hidden: true });
  #params = h('div', { class: 'grid2' });
  #status = h('p', { class: 'muted small', 'aria-live': 'polite' });
  #error = h('p', { class: 'settings-error', role: 'alert', hidden: true });
  #describing = 0;

  constructor(
    slot: HTMLElement,
    private store: SettingsStore,
    private describe: (spec: CustomInfillSpec) => Promise<InfillerDescription>,
    /** Where a refused parameter field is told (Slice and Download wait for it). */
    private invalid?: InvalidFields,
  ) {
    slot.append(
      h(
        'label',
        { class: 'field', for: 'custom-infill' },
        h('span', {}, 'Custom infill (IceSL infiller, replaces the pattern)'),
      ),
      h(
        'div',
        { class: 'row' },
        this.#select,
        h('label', { class: 'button small', for: 'infill-file' }, 'Load shader.glsl or cells.png'),
        this.#fileInput,
      ),
      h('div', { class: 'row' }, this.#preview, this.#status),
      this.#params,
      this.#error,
    );
    this.#select.addEventListener('change', () => void this.#choose(this.#select.value));
    this.#fileInput.addEventListener('change', () => {
      const f = this.#fileInput.files?.[0];
      this.#fileInput.value = '';
      if (f) void this.loadFile(f);
    });
  }

  async init(): Promise<void> {
    try {
      const r = await fetch(new URL('./infillers/index.json', import.meta.url));
      if (r.ok) this.shipped = (await r.json()) as ShippedInfiller[];
    } catch {
      this.shipped = [];
    }
    this.#fillSelect();
    if (this.store.custom) await this.#activate(this.store.custom, false);
  }

  #fillSelect(): void {
    const c = this.store.custom;
    this.#select.replaceChildren(
      h('option', { value: '' }, 'None: the pattern above'),
      h(
        'optgroup',
        { label: 'Shipped with Strata' },
        ...this.shipped.map((s) => h('option', { value: `shipped:${s.name}` }, s.name)),
      ),
    );
    if (c?.source === 'file')
      this.#select.append(
        h('optgroup', { label: 'Loaded' }, h('option', { value: `file:${c.name}` }, c.fileName ?? c.name)),
      );
    this.#select.value = c ? `${c.source}:${c.name}` : '';
  }

  /** The spec for the slicer, with the files' contents (fetched for shipped ones). */
  async spec(): Promise<CustomInfillSpec | null> {
    const c = this.store.custom;
    if (!c) return null;
    const files = c.source === 'shipped' ? await this.#shippedFiles(c.name) : { shader: c.shader, image: c.image };
    return { name: c.name, ...files, params: { ...c.params } };
  }

  async #shippedFiles(name: string): Promise<{ shader?: string; image?: Uint8Array }> {
    const known = this.#files.get(name);
    if (known) return known;
    const s = this.shipped.find((x) => x.name === name);
    if (!s) throw new Error(`no shipped infiller is called "${name}"`);
    const r = await fetch(new URL(`./infillers/${name}/${s.file}`, import.meta.url));
    if (!r.ok) throw new Error(`the infiller ${name} could not be fetched (HTTP ${r.status})`);
    const files =
      s.file === 'shader.glsl' ? { shader: await r.text() } : { image: new Uint8Array(await r.arrayBuffer()) };
    this.#files.set(name, files);
    return files;
  }

  async #choose(value: string): Promise<void> {
    if (!value) {
      this.store.custom = null;
      this.#show(null, null);
      this.store.changed();
      return;
    }
    const [source, ...rest] = value.split(':');
    const name = rest.join(':');
    const prev = this.store.custom;
    if (source === 'file' && prev?.source === 'file') await this.#activate(prev, true);
    else await this.#activate({ source: 'shipped', name, params: prev?.name === name ? prev.params : {} }, true);
  }

  async loadFile(file: File): Promise<void> {
    if (file.size > MAX_INFILLER_BYTES) {
      this.#fail(`${file.name} is larger than ${MAX_INFILLER_BYTES / 1024 / 1024} MB`);
      return;
    }
    const bytes = new Uint8Array(await file.arrayBuffer());
    const isPng = bytes.length >= 8 && bytes[0] === 0x89 && bytes[1] === 0x50 && bytes[2] === 0x4e && bytes[3] === 0x47;
    const stem = file.name.replace(/\.[^.]*$/, '') || 'custom';
    const choice: CustomChoice = isPng
      ? { source: 'file', name: stem, fileName: file.name, image: bytes, params: {} }
      : { source: 'file', name: stem, fileName: file.name, shader: new TextDecoder().decode(bytes), params: {} };
    await this.#activate(choice, true);
  }

  /** Compile and describe the infiller in the worker; on success it becomes the store's choice. */
  async #activate(choice: CustomChoice, announce: boolean): Promise<void> {
    const ticket = ++this.#describing;
    this.#error.hidden = true;
    this.#status.textContent = `Loading ${choice.fileName ?? choice.name}…`;
    let info: InfillerDescription;
    try {
      const files =
        choice.source === 'shipped'
          ? await this.#shippedFiles(choice.name)
          : { shader: choice.shader, image: choice.image };
      info = await this.describe({ name: choice.name, ...files, params: choice.params });
    } catch (e) {
      if (ticket !== this.#describing) return;
      this.#fail(`${choice.fileName ?? choice.name}: ${e instanceof Error ? e.message : String(e)}`);
      return;
    }
    if (ticket !== this.#describing) return;
    // parameters the infiller no longer has are dropped
    const names = new Set(info.params.map((p) => p.name));
    choice.params = Object.fromEntries(Object.entries(choice.params).filter(([k]) => names.has(k)));
    this.store.custom = choice;
    this.#fillSelect();
    this.#show(choice, info);
    if (announce) this.store.changed();
  }

  #fail(message: string): void {
    this.#error.textContent = message;
    this.#error.hidden = false;
    this.#status.textContent = this.store.custom ? `Still using ${this.store.custom.name}.` : '';
    this.#fillSelect();
  }

  #show(choice: CustomChoice | null, info: InfillerDescription | null): void {
    // the fields replaced take what was typed into them along
    for (const old of this.#params.querySelectorAll('input')) this.invalid?.set(old, null);
    this.#error.hidden = true;
    this.#params.replaceChildren();
    const shipped = choice?.source === 'shipped' ? this.shipped.find((s) => s.name === choice.name) : undefined;
    this.#preview.hidden = !shipped?.preview;
    if (shipped?.preview) this.#preview.src = new URL(`./infillers/${shipped.name}/preview.png`, import.meta.url).href;
    if (!choice || !info) {
      this.#status.textContent = '';
      return;
    }
    const warn = info.warnings.length ? ` ${info.warnings.join('; ')}` : '';
    this.#status.textContent = `${info.kind === 'shader' ? 'Shader' : 'Cell image'} ${choice.name}: ${info.params.length} parameter${info.params.length === 1 ? '' : 's'}.${warn}`;
    for (const p of info.params) {
      const id = `infill-param-${p.name}`;
      const value = choice.params[p.name] ?? p.default;
      const input =
        p.type === 'bool'
          ? h('input', { id, type: 'checkbox', checked: value === true })
          : h('input', { id, type: 'number', step: p.type === 'int' ? '1' : 'any', value: String(value) });
      input.addEventListener('change', () => {
        const v = p.type === 'bool' ? input.checked : input.value.trim() === '' ? NaN : Number(input.value);
        if (typeof v === 'number' && (!Number.isFinite(v) || (p.type === 'int' && !Number.isInteger(v)))) {
          const why = `${p.name} must be ${p.type === 'int' ? 'a whole number' : 'a number'}`;
          this.#error.textContent = why;
          this.#error.hidden = false;
          input.setAttribute('aria-invalid', 'true');
          this.invalid?.set(input, `Infill parameter ${p.name.replace(/^ui_/, '')}: ${why}`);
          return;
        }
        this.#error.hidden = true;
        input.removeAttribute('aria-invalid');
        this.invalid?.set(input, null);
        if (v === p.default) delete choice.params[p.name];
        else choice.params[p.name] = v;
        this.store.changed();
      });
      this.#params.append(
        h('label', { class: 'field', for: id, title: p.tooltip }, h('span', {}, p.name.replace(/^ui_/, '')), input),
      );
    }
  }
}
