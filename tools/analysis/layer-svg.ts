/**
 * A debug picture of one layer: the model section (gap-closing joins in red) under the extrusions coloured by
 * feature. Y points up as on the bed.
 */
import { FEATURE_NAMES } from './feature-names.js';
import type { GcodeLayer } from './gcode-types.js';
import type { SectionSegments } from './section-gaps.js';

const FEATURE_COLOURS: Record<(typeof FEATURE_NAMES)[number], string> = {
  UNKNOWN: '#888888',
  'WALL-OUTER': '#d62728',
  'WALL-INNER': '#2ca02c',
  SKIN: '#ff7f0e',
  FILL: '#1f77b4',
  SUPPORT: '#9467bd',
  SKIRT: '#8c564b',
  'PRIME-TOWER': '#e377c2',
  IRONING: '#bcbd22',
  CUSTOM: '#17becf',
  'SUPPORT-INTERFACE': '#5b3a8c',
  RAFT: '#7f7f7f',
};

export interface LayerSvgOptions {
  /** Pixels per mm, default 20. */
  scale?: number;
  /** Stroke width of extrusions in mm, default 0.4 (drawn at half opacity so overlaps show). */
  lineWidth?: number;
  /** Window [xmin, ymin, xmax, ymax] in mm; default: the section and extrusions. */
  window?: [number, number, number, number];
}

export function layerSvg(section: SectionSegments, layer: GcodeLayer, o: LayerSvgOptions = {}): string {
  const scale = o.scale ?? 20;
  const width = o.lineWidth ?? 0.4;
  const t = layer.extrusions;
  let [xmin, ymin, xmax, ymax] = o.window ?? [Infinity, Infinity, -Infinity, -Infinity];
  if (!o.window) {
    const grow = (x: number, y: number) => {
      xmin = Math.min(xmin, x);
      xmax = Math.max(xmax, x);
      ymin = Math.min(ymin, y);
      ymax = Math.max(ymax, y);
    };
    for (let i = 0; i < section.count; i++) grow(section.x0[i]!, section.y0[i]!);
    for (let i = 0; i < t.count; i++) grow(t.x1[i]!, t.y1[i]!);
    if (xmin > xmax) [xmin, ymin, xmax, ymax] = [0, 0, 1, 1];
    xmin -= 1;
    ymin -= 1;
    xmax += 1;
    ymax += 1;
  }
  const px = (x: number) => ((x - xmin) * scale).toFixed(1);
  const py = (y: number) => ((ymax - y) * scale).toFixed(1);
  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${Math.ceil((xmax - xmin) * scale)}" ` +
      `height="${Math.ceil((ymax - ymin) * scale)}">`,
    '<rect width="100%" height="100%" fill="white"/>',
  ];
  out.push(`<g stroke-width="${(0.05 * scale).toFixed(1)}">`);
  for (let i = 0; i < section.count; i++) {
    const colour = section.synthetic[i] ? 'red' : 'black';
    out.push(
      `<line x1="${px(section.x0[i]!)}" y1="${py(section.y0[i]!)}" x2="${px(section.x1[i]!)}" ` +
        `y2="${py(section.y1[i]!)}" stroke="${colour}"/>`,
    );
  }
  out.push('</g>', `<g stroke-width="${(width * scale).toFixed(1)}" stroke-linecap="round" stroke-opacity="0.5">`);
  for (let i = 0; i < t.count; i++) {
    out.push(
      `<line x1="${px(t.x0[i]!)}" y1="${py(t.y0[i]!)}" x2="${px(t.x1[i]!)}" y2="${py(t.y1[i]!)}" ` +
        `stroke="${FEATURE_COLOURS[FEATURE_NAMES[t.feature[i]!]!]}"/>`,
    );
  }
  out.push('</g>', '</svg>');
  return out.join('\n');
}
