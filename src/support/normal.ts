/**
 * Normal support: columns straight down from every overhang. Working from the top layer down, the support of
 * layer j is what layer j+1 had plus the overhang that starts the top Z gap above j, merged where columns
 * come close (so they print as one area), less where the part is (grown by the XY gap). In 'everywhere'
 * placement a column stops on the part, the bottom Z gap above it; in 'buildPlate' placement a column that
 * would meet the part anywhere below is not printed at all.
 */
import { closing, difference, offset } from '../geometry/clip.js';
import { UM_PER_MM, type ExPolygon } from '../geometry/types.js';
import type { SupportAreas } from '../regions/types.js';
import { printable, type ModelLayers } from './model-layers.js';

/** Columns closer than this (mm) are merged into one support area. */
export const SUPPORT_JOIN_MM = 2;
/** Fresh overhang is widened by this many line widths, so thin slivers of it get a printable column. */
export const EXPAND_WIDTHS = 0.5;

/** Support areas of every layer, top down; yields after each layer. */
export function* normalSupport(model: ModelLayers): Generator<void, SupportAreas[]> {
  const cfg = model.cfg;
  const n = model.count;
  const out: SupportAreas[] = new Array(n);
  const w = model.widthUm;
  const xy = cfg.supportXYGap * UM_PER_MM;
  const join = (SUPPORT_JOIN_MM * UM_PER_MM) / 2;
  let carried: ExPolygon[] = [];
  for (let j = n - 1; j >= 0; j--) {
    // the first layer also holds the overhang within the top Z gap over it, with no gap (there is no room for one)
    // (with uneven layers, the overhang of every layer whose top Z gap ends at j: none, one or several)
    const over = model.overhangLayersOver(j);
    const rawFresh =
      j > 0
        ? over.length === 1
          ? model.overhang(over[0])
          : over.flatMap((m) => model.overhang(m))
        : [...model.gapOverhang(), ...over.flatMap((m) => model.overhang(m))];
    const fresh = rawFresh.length && EXPAND_WIDTHS > 0 ? offset(rawFresh, EXPAND_WIDTHS * w) : rawFresh;
    // merging columns closer than the join distance also unions the fresh overhang into them
    let s = fresh.length ? closing(carried.length ? [...carried, ...fresh] : fresh, join) : carried;
    if (s.length) {
      const blocked = model.collision(j);
      if (blocked.length) s = difference(s, blocked);
    }
    if (s.length && cfg.supportPlacement === 'buildPlate' && j > 0) {
      // a column must reach the bed: nothing above the part's shadow
      const shadow = model.shadow(j - 1);
      if (shadow.length) s = difference(s, offset(shadow, xy));
    }
    carried = s;
    let printed = s;
    const bottom = model.bottomGap(j);
    if (printed.length && cfg.supportPlacement === 'everywhere' && bottom > 0) {
      // the bottom Z gap: no support in the layers right above the part
      const under = model.sectionsBetween(j, -bottom, -1);
      if (under.length) printed = difference(printed, under);
    }
    // what lies below the last layer's support needs nothing more: only what is printed carries on
    carried = printed;
    printed = printable(printed, w);
    out[j] = { ...model.split(j, printed), whole: printed };
    model.release(j + model.maxTopGap + Math.max(cfg.supportInterfaceLayers, 1) + 1);
    yield;
  }
  return out;
}
