/**
 * Top and bottom surfaces of a layer from the model alone: the parts of the layer's section that are not covered
 * by every section within the skin thickness above (top) or below (bottom).
 */
import type { Spans } from './spans.js';
import { spansBoolean } from './spans.js';

export interface SkinRegions {
  top: Spans;
  bottom: Spans;
}

/**
 * `above` and `below` are the sections at the next layers' mid-heights, nearest first; a missing layer (past the
 * model, or below the bed) is an empty region, which makes the whole section exposed.
 */
export function skinRegions(section: Spans, above: Spans[], below: Spans[]): SkinRegions {
  return { top: exposed(section, above), bottom: exposed(section, below) };
}

function exposed(section: Spans, neighbours: Spans[]): Spans {
  if (neighbours.length === 0) return spansBoolean(section, section, 'subtract');
  let covered = neighbours[0]!;
  for (let k = 1; k < neighbours.length; k++) covered = spansBoolean(covered, neighbours[k]!, 'intersect');
  return spansBoolean(section, covered, 'subtract');
}
