/**
 * Debug and documentation pictures: one layer of the toolpath plan as SVG, paths coloured by
 * feature type, travels dashed. Pure: returns the SVG text.
 */
import type { Pt } from '../geometry/types.js';
import type { FeatureType, LayerPlan } from '../plan/types.js';

/** A colour (`#rrggbb`) for each feature type, as the previews draw them (the web page's too). */
export const FEATURE_COLOURS: Readonly<Record<FeatureType, string>> = {
  'WALL-OUTER': '#d62728',
  'WALL-INNER': '#2ca02c',
  SKIN: '#ff9f1c',
  FILL: '#1f77b4',
  BRIDGE: '#e377c2',
  SUPPORT: '#17becf',
  'SUPPORT-INTERFACE': '#0e7c86',
  SKIRT: '#7f7f7f',
  BRIM: '#7f7f7f',
  RAFT: '#8c564b',
  IRONING: '#bcbd22',
};

export interface SvgOptions {
  /** Show travels as thin dashed lines. */
  travel?: boolean;
  /** Output width in pixels (height follows the aspect ratio). */
  widthPx?: number;
  /** Margin around the paths, mm. */
  marginMm?: number;
  title?: string;
}

function fmt(v: number): string {
  return (Math.round(v * 1000) / 1000).toString();
}

/** SVG of one layer plan, in mm with Y up (flipped for the screen). */
export function layerToSvg(layer: LayerPlan, opts: SvgOptions = {}): string {
  const margin = opts.marginMm ?? 2;
  let minX = Infinity,
    minY = Infinity,
    maxX = -Infinity,
    maxY = -Infinity;
  for (const s of layer.steps) {
    if (s.kind !== 'extrude') continue;
    for (const p of s.points) {
      if (p.x < minX) minX = p.x;
      if (p.y < minY) minY = p.y;
      if (p.x > maxX) maxX = p.x;
      if (p.y > maxY) maxY = p.y;
    }
  }
  if (minX === Infinity) minX = minY = maxX = maxY = 0;
  const x0 = minX / 1000 - margin,
    y0 = minY / 1000 - margin;
  const w = (maxX - minX) / 1000 + 2 * margin,
    h = (maxY - minY) / 1000 + 2 * margin;
  const px = opts.widthPx ?? 800;
  const X = (p: Pt) => fmt(p.x / 1000 - x0);
  const Y = (p: Pt) => fmt(h - (p.y / 1000 - y0));
  const out: string[] = [];
  out.push(
    `<svg xmlns="http://www.w3.org/2000/svg" width="${px}" height="${Math.round((px * h) / w)}" viewBox="0 0 ${fmt(w)} ${fmt(h)}">`,
  );
  out.push(`<rect width="100%" height="100%" fill="#ffffff"/>`);
  if (opts.title) out.push(`<title>${opts.title.replace(/[<&>]/g, '')}</title>`);
  let at: Pt | null = null;
  for (const s of layer.steps) {
    if (s.kind === 'travel') {
      if (opts.travel && at) {
        const d = [at, ...s.points].map((p, i) => `${i ? 'L' : 'M'}${X(p)} ${Y(p)}`).join('');
        out.push(`<path d="${d}" fill="none" stroke="#9467bd" stroke-width="0.06" stroke-dasharray="0.3 0.3"/>`);
      }
      at = s.points[s.points.length - 1];
      continue;
    }
    // arc segments (arc fitting) as SVG arcs: the screen's Y is flipped, so counter-clockwise on the bed is
    // the SVG's positive sweep; arcs turn at most half a turn, so never the large arc
    const segment = (p: Pt, i: number, from: Pt): string => {
      const arc = s.arcs?.[i];
      if (!arc) return `L${X(p)} ${Y(p)}`;
      const r = fmt(Math.hypot(from.x - arc.cx, from.y - arc.cy) / 1000);
      return `A${r} ${r} 0 0 ${arc.clockwise ? 0 : 1} ${X(p)} ${Y(p)}`;
    };
    const n = s.points.length;
    if (s.widths) {
      // widths that vary: each segment a stroke of its mean width, round-capped so the strokes join
      const w = s.widths;
      const last = s.closed ? n : n - 1;
      for (let i = 1; i <= last; i++) {
        const a = s.points[i - 1]!,
          k = i % n,
          b = s.points[k]!;
        const width = fmt((w[i - 1]! + w[k]!) / 2);
        out.push(
          `<path d="M${X(a)} ${Y(a)}${segment(b, i, a)}" fill="none" stroke="${FEATURE_COLOURS[s.feature]}" stroke-width="${width}" stroke-linecap="round" stroke-opacity="0.85"/>`,
        );
      }
      at = s.closed ? s.points[0] : s.points[n - 1];
      continue;
    }
    let d = n ? `M${X(s.points[0]!)} ${Y(s.points[0]!)}` : '';
    for (let i = 1; i < n; i++) d += segment(s.points[i]!, i, s.points[i - 1]!);
    if (s.closed && n > 0) d += s.arcs?.[n] ? segment(s.points[0]!, n, s.points[n - 1]!) : 'Z';
    out.push(
      `<path d="${d}" fill="none" stroke="${FEATURE_COLOURS[s.feature]}" stroke-width="${fmt(s.width)}" stroke-linejoin="round" stroke-linecap="round" stroke-opacity="0.85"/>`,
    );
    at = s.closed ? s.points[0] : s.points[s.points.length - 1];
  }
  out.push('</svg>');
  return out.join('\n');
}
