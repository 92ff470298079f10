/**
 * Preview controls: the layer slider (one layer, or every layer up to it), the legend with one
 * toggle per feature type (named by its `;TYPE:` marker, from FEATURE_TYPES and TYPE_MARKERS), and
 * travel and retraction toggles.
 */
import { TYPE_MARKERS } from '../../src/gcode/move-writer.js';
import { FEATURE_TYPES } from '../../src/plan/types.js';
import { FEATURE_COLOURS } from '../../src/preview/svg.js';
import type { PreviewArrays } from '../../src/preview/plan-arrays.js';
import { byId, h } from './dom.js';
import { length } from './format.js';
import type { ToolpathView } from './toolpath.js';

/** The legend's name for a feature: its `;TYPE:` marker, and the feature when they differ (brim is written as SKIRT). */
export function legendName(i: number): string {
  const f = FEATURE_TYPES[i];
  const marker = TYPE_MARKERS[f];
  return marker === f ? marker : `${marker} (${f.toLowerCase()})`;
}

export class PreviewPanel {
  #slider = byId<HTMLInputElement>('layer');
  #label = byId('layer-label');
  #legend = byId('legend');
  #travel = byId<HTMLInputElement>('show-travel');
  #retract = byId<HTMLInputElement>('show-retract');
  #layerZ: Float32Array = new Float32Array(0);
  #hidden = new Set<number>();

  constructor(private view: ToolpathView) {
    this.#slider.addEventListener('input', () => this.#apply());
    for (const r of document.querySelectorAll<HTMLInputElement>('input[name="layer-mode"]')) r.addEventListener('change', () => this.#apply());
    this.#travel.addEventListener('change', () => view.setTravel(this.#travel.checked));
    this.#retract.addEventListener('change', () => view.setRetractions(this.#retract.checked));
  }

  #mode(): 'single' | 'upto' {
    return document.querySelector<HTMLInputElement>('input[name="layer-mode"]:checked')?.value === 'single' ? 'single' : 'upto';
  }

  show(a: PreviewArrays): void {
    this.#layerZ = a.layerZ;
    const n = a.layerZ.length;
    this.#slider.max = String(Math.max(0, n - 1));
    this.#slider.value = String(Math.max(0, n - 1));
    this.#slider.setAttribute('aria-valuetext', '');
    this.#legend.replaceChildren(
      ...FEATURE_TYPES.flatMap((f, i) => {
        if (a.featureLengthMm[i] <= 0) return [];
        const box = h('input', { type: 'checkbox', checked: !this.#hidden.has(i), 'data-feature': f });
        box.addEventListener('change', () => {
          if (box.checked) this.#hidden.delete(i);
          else this.#hidden.add(i);
          this.view.setFeatureVisible(i, box.checked);
        });
        this.view.setFeatureVisible(i, !this.#hidden.has(i));
        return [h('li', {}, h('label', {}, box, h('span', { class: 'swatch', style: `background:${FEATURE_COLOURS[f]}` }), legendName(i), h('span', { class: 'len' }, length(a.featureLengthMm[i]))))];
      }),
    );
    this.view.setData(a);
    this.view.setTravel(this.#travel.checked);
    this.view.setRetractions(this.#retract.checked);
    this.#apply();
  }

  #apply(): void {
    const n = this.#layerZ.length;
    const v = Math.min(Number(this.#slider.value), n - 1);
    const lo = this.#mode() === 'single' ? v : 0;
    this.view.setRange(lo, v);
    const text = n ? `Layer ${v + 1} of ${n} · Z ${this.#layerZ[v].toFixed(2)} mm` : 'No layers';
    this.#label.textContent = text;
    this.#slider.setAttribute('aria-valuetext', text);
  }

  get layerCount(): number {
    return this.#layerZ.length;
  }
}
