/** Numbers as the page shows them. */

export function duration(seconds: number): string {
  const s = Math.round(seconds);
  const h = Math.floor(s / 3600),
    m = Math.floor((s % 3600) / 60),
    sec = s % 60;
  return h ? `${h} h ${m} min` : m ? `${m} min ${sec} s` : `${sec} s`;
}

export function metres(mm: number): string {
  return `${(mm / 1000).toFixed(2)} m`;
}

export function grams(g: number): string {
  return `${g.toFixed(1)} g`;
}

/** Lengths in a legend: mm below a metre, else metres. */
export function length(mm: number): string {
  return mm < 1000 ? `${Math.round(mm)} mm` : `${(mm / 1000).toFixed(1)} m`;
}

/** A size in mm with one decimal. */
export function mm1(v: number): string {
  const s = v.toFixed(1);
  return s === '-0.0' ? '0.0' : s;
}

/** "layerHeight" → "Layer height". */
export function labelOf(key: string): string {
  const words = key
    .replace(/([a-z0-9])([A-Z])/g, '$1 $2')
    .replace(/([A-Z])([A-Z][a-z])/g, '$1 $2')
    .toLowerCase();
  return words[0].toUpperCase() + words.slice(1);
}
