/**
 * Preview controls, as PrusaSlicer's and Cura's: a vertical layer slider with two handles (the bottom
 * and top layers shown; "One layer" keeps them together), a horizontal slider through the top layer
 * move by move (the tool drawn where the last move shown ends), a button that frames the top layer,
 * and the legend: colour by feature (one toggle per feature type, named by its `;TYPE:` marker, from
 * FEATURE_TYPES and TYPE_MARKERS), or by speed, fan, line width or layer time on a colour ramp with its
 * scale; travel and retraction toggles.
 *
 * Dragging a slider draws draft frames (the layers below the top one coarse, at half the resolution),
 * so each step stays quick without a GPU; the full drawing follows once the slider rests.
 */
import { FEATURE_COLOURS, FEATURE_TYPES, TYPE_MARKERS, type PreviewArrays } from 'strata-slicer';
import { byId, h } from './dom.js';
import { length } from './format.js';
import { RAMP, type ColourBy, type ToolpathView } from './toolpath.js';

/** The legend's name for a feature: its `;TYPE:` marker, and the feature when they differ (brim is written as SKIRT). */
export function legendName(i: number): string {
  const f = FEATURE_TYPES[i];
  const marker = TYPE_MARKERS[f];
  return marker === f ? marker : `${marker} (${f.toLowerCase()})`;
}

/** How each colouring's numbers are written. */
const SCALES: Readonly<Record<Exclude<ColourBy, 'feature'>, (v: number) => string>> = {
  speed: (v) => `${Math.round(v)} mm/s`,
  fan: (v) => `${Math.round(v)} %`,
  width: (v) => `${v.toFixed(2)} mm`,
  'layer-time': (v) => (v >= 60 ? `${Math.floor(v / 60)} min ${Math.round(v % 60)} s` : `${v.toFixed(1)} s`),
};

/** A slider at rest this long (ms) gets the full drawing. */
const REFINE_AFTER_MS = 250;

export interface PreviewHost {
  /** Draft frames while a slider is dragged (the view draws at a lower resolution), or the full view back. */
  draft(on: boolean): void;
  /** Look at this box (mm) from where the camera is. */
  frame(min: [number, number, number], max: [number, number, number]): void;
}

export class PreviewPanel {
  #panel = byId('preview-panel');
  #top = byId<HTMLInputElement>('layer');
  #bottom = byId<HTMLInputElement>('layer-from');
  #one = byId<HTMLInputElement>('one-layer');
  #rail = byId('layer-rail');
  #topLabel = byId('layer-top');
  #bottomLabel = byId('layer-bottom');
  #label = byId('layer-label');
  #move = byId<HTMLInputElement>('move');
  #moveLabel = byId('move-label');
  #legendBox = byId<HTMLDetailsElement>('legend-box');
  #legend = byId('legend');
  #colourBy = byId<HTMLSelectElement>('colour-by');
  #scale = byId('scale');
  #travel = byId<HTMLInputElement>('show-travel');
  #retract = byId<HTMLInputElement>('show-retract');
  #data: PreviewArrays | null = null;
  #hidden = new Set<number>();
  #refine: ReturnType<typeof setTimeout> | null = null;

  constructor(
    private view: ToolpathView,
    private host: PreviewHost,
  ) {
    this.#top.addEventListener('input', () => this.#dragged(() => this.#layers('top')));
    this.#bottom.addEventListener('input', () => this.#dragged(() => this.#layers('bottom')));
    this.#move.addEventListener('input', () => this.#dragged(() => this.#moves()));
    this.#one.addEventListener('change', () => this.#layers('top'));
    this.#travel.addEventListener('change', () => view.setTravel(this.#travel.checked));
    this.#retract.addEventListener('change', () => view.setRetractions(this.#retract.checked));
    this.#colourBy.addEventListener('change', () => this.#colour());
    byId('frame-layer').addEventListener('click', () => this.frameLayer());
    // the legend starts folded on a narrow window, where it would cover the preview
    this.#legendBox.open = !window.matchMedia('(max-width: 900px)').matches;
  }

  show(a: PreviewArrays): void {
    this.#data = a;
    const n = a.layerZ.length;
    for (const s of [this.#top, this.#bottom]) s.max = String(Math.max(0, n - 1));
    this.#top.value = String(Math.max(0, n - 1));
    this.#bottom.value = '0';
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
        const swatch = h('span', { class: 'swatch' });
        swatch.style.background = FEATURE_COLOURS[f];
        return [
          h(
            'li',
            {},
            h('label', {}, box, swatch, legendName(i), h('span', { class: 'len' }, length(a.featureLengthMm[i]))),
          ),
        ];
      }),
    );
    this.view.setData(a);
    this.view.setTravel(this.#travel.checked);
    this.view.setRetractions(this.#retract.checked);
    this.#colour();
    this.#layers('top');
  }

  get layerCount(): number {
    return this.#data?.layerZ.length ?? 0;
  }

  /** Aim the camera at the top layer shown. */
  frameLayer(): void {
    const b = this.view.layerBounds(Number(this.#top.value));
    if (!b) return;
    this.host.frame([b.min.x, b.min.y, b.min.z], [b.max.x, b.max.y, b.max.z]);
  }

  /** A slider moved: draw a draft now, the full view once it rests. */
  #dragged(apply: () => void): void {
    if (this.#refine === null) {
      this.#panel.dataset.draft = 'true';
      this.view.setDraft(true);
      this.host.draft(true);
    } else clearTimeout(this.#refine);
    apply();
    this.#refine = setTimeout(() => {
      this.#refine = null;
      delete this.#panel.dataset.draft;
      this.view.setDraft(false);
      this.host.draft(false);
    }, REFINE_AFTER_MS);
  }

  /** The layer handles moved (`moved`: which one the user moved); the other follows where it must. */
  #layers(moved: 'top' | 'bottom'): void {
    const a = this.#data;
    if (!a) return;
    const n = a.layerZ.length;
    let top = Math.min(Number(this.#top.value), n - 1);
    let bottom = Math.min(Number(this.#bottom.value), n - 1);
    if (this.#one.checked) {
      if (moved === 'top') bottom = top;
      else top = bottom;
    } else if (bottom > top) {
      if (moved === 'top') bottom = top;
      else top = bottom;
    }
    this.#top.value = String(top);
    this.#bottom.value = String(bottom);
    this.#rail.style.setProperty('--lo', String(n > 1 ? bottom / (n - 1) : 0));
    this.#rail.style.setProperty('--hi', String(n > 1 ? top / (n - 1) : 1));
    this.view.setRange(bottom, top);
    const z = (i: number) => `Z ${a.layerZ[i].toFixed(2)} mm`;
    const text =
      n === 0
        ? 'No layers'
        : `Layer ${top + 1} of ${n} · ${z(top)}${bottom > 0 && bottom < top ? ` (from layer ${bottom + 1})` : ''}`;
    this.#label.textContent = text;
    this.#topLabel.textContent = String(top + 1);
    this.#bottomLabel.textContent = String(bottom + 1);
    this.#top.setAttribute('aria-valuetext', `layer ${top + 1} of ${n}, ${z(top)}`);
    this.#bottom.setAttribute('aria-valuetext', `layer ${bottom + 1} of ${n}, ${z(bottom)}`);
    // the move slider goes through the top layer, and starts at its end (all of it shown)
    const moves = a.layerMoves[top] ?? 0;
    this.#move.max = String(moves);
    this.#move.value = String(moves);
    this.#moves();
  }

  /** The move slider moved: the top layer up to that move, and what the last move shown is. */
  #moves(): void {
    const a = this.#data;
    if (!a) return;
    const top = Number(this.#top.value);
    const total = a.layerMoves[top] ?? 0;
    const m = Math.min(Number(this.#move.value), total);
    this.view.setMoveLimit(m >= total ? null : m);
    const info = m > 0 ? this.view.moveInfo(top, m - 1) : null;
    let text = `Move ${m} of ${total}`;
    if (info?.kind === 'extrude') {
      text += `: ${legendName(info.feature!)}, ${info.widthMm!.toFixed(2)} mm wide, ${Math.round(info.speed!)} mm/s, fan ${Math.round(info.fan! * 100)} %`;
    } else if (info) text += ': travel';
    this.#moveLabel.textContent = text;
    this.#move.setAttribute('aria-valuetext', text);
  }

  /** Colour by what the select says; the legend shows its scale. */
  #colour(): void {
    const mode = this.#colourBy.value as ColourBy;
    const range = this.view.setColourBy(mode);
    this.#legendBox.dataset.colourBy = mode;
    this.#scale.hidden = mode === 'feature';
    if (mode === 'feature' || !range) return;
    const write = SCALES[mode];
    const bar = h('div', { class: 'scale-bar' });
    bar.style.background = `linear-gradient(to right, ${RAMP.join(', ')})`;
    this.#scale.replaceChildren(
      bar,
      h(
        'div',
        { class: 'scale-ticks' },
        h('span', {}, write(range.min)),
        h('span', {}, write((range.min + range.max) / 2)),
        h('span', {}, write(range.max)),
      ),
    );
  }
}
