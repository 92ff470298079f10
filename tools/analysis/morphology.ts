/**
 * Exact disc morphology and connected components on bitmaps (0/1 bytes, row-major, `cols` × `rows`): growing,
 * shrinking and closing by a Euclidean radius through a distance transform (a row sweep, then the lower envelope
 * of parabolas down each column), so the cost is linear in the cells whatever the radius.
 */

/** Squared distance of an empty row or column to anything: larger than any real distance in a window. */
const FAR = 2 ** 40;

/**
 * Squared distance, in cells², from each cell's centre to the centre of the nearest cell whose value is nonzero
 * (`of` = 1) or zero (`of` = 0); FAR when there is none. A sweep down and up the columns (row by row, so memory is
 * read in order) gives each cell's distance along its column; the lower envelope of parabolas along each row then
 * gives the 2D distance.
 */
export function squaredDistance(bitmap: Uint8Array, cols: number, rows: number, of: 0 | 1): Float32Array {
  const g = new Float32Array(cols * rows);
  const last = new Float64Array(cols).fill(-FAR);
  for (let j = 0, k = 0; j < rows; j++) {
    for (let i = 0; i < cols; i++, k++) {
      if ((bitmap[k]! !== 0 ? 1 : 0) === of) last[i] = j;
      g[k] = j - last[i]!;
    }
  }
  last.fill(2 * FAR);
  for (let j = rows - 1; j >= 0; j--) {
    for (let i = 0, k = j * cols; i < cols; i++, k++) {
      if ((bitmap[k]! !== 0 ? 1 : 0) === of) last[i] = j;
      const d = Math.min(g[k]!, last[i]! - j);
      g[k] = d >= FAR ? FAR : d * d;
    }
  }
  // Along each row: d(i) = min over i' of g(i') + (i - i')², by the lower envelope of parabolas.
  const f = new Float64Array(cols);
  const v = new Int32Array(cols);
  const z = new Float64Array(cols + 1);
  for (let j = 0; j < rows; j++) {
    const base = j * cols;
    let any = false;
    let all = true;
    for (let i = 0; i < cols; i++) {
      const x = g[base + i]!;
      f[i] = x;
      if (x < FAR) any = true;
      if (x !== 0) all = false;
    }
    if (!any || all) continue;
    let k = 0;
    v[0] = 0;
    z[0] = -Infinity;
    z[1] = Infinity;
    for (let q = 1; q < cols; q++) {
      const fq = f[q]! + q * q;
      let vk = v[k]!;
      let s = (fq - (f[vk]! + vk * vk)) / (2 * (q - vk));
      while (s <= z[k]!) {
        k--;
        vk = v[k]!;
        s = (fq - (f[vk]! + vk * vk)) / (2 * (q - vk));
      }
      k++;
      v[k] = q;
      z[k] = s;
      z[k + 1] = Infinity;
    }
    k = 0;
    for (let q = 0; q < cols; q++) {
      while (z[k + 1]! < q) k++;
      const dq = q - v[k]!;
      const d = dq * dq + f[v[k]!]!;
      g[base + q] = d < FAR ? d : FAR;
    }
  }
  return g;
}

/** Radii (cells) up to this are grown and shrunk by visiting the disc's offsets; larger ones by distance transform. */
const SMALL_RADIUS_CELLS = 2;

/** Offsets [di, dj] of the lattice points within r of the origin. */
function discOffsets(r: number): [number, number][] {
  const out: [number, number][] = [];
  const n = Math.floor(r);
  for (let dj = -n; dj <= n; dj++) {
    for (let di = -n; di <= n; di++) if (di * di + dj * dj <= r * r + 1e-9) out.push([di, dj]);
  }
  return out;
}

/**
 * Small radii: a cell of the result is set when any (`all` false: dilation) or every (`all` true: erosion) cell
 * of the disc around it is set; beyond the window cells count as `outside`.
 */
function byOffsets(
  bitmap: Uint8Array,
  cols: number,
  rows: number,
  r: number,
  all: boolean,
  outside: 0 | 1,
): Uint8Array {
  const offsets = discOffsets(r);
  const n = Math.floor(r);
  const out = new Uint8Array(cols * rows);
  for (let j = 0; j < rows; j++) {
    for (let i = 0; i < cols; i++) {
      const k = j * cols + i;
      if (all && bitmap[k] === 0) continue;
      const inner = i >= n && j >= n && i < cols - n && j < rows - n;
      let hit = all;
      for (const [di, dj] of offsets) {
        const v =
          inner || (i + di >= 0 && j + dj >= 0 && i + di < cols && j + dj < rows)
            ? bitmap[k + dj * cols + di] !== 0
              ? 1
              : 0
            : outside;
        if (all ? v === 0 : v === 1) {
          hit = !all;
          break;
        }
      }
      out[k] = hit ? 1 : 0;
    }
  }
  return out;
}

/** Cells within `r` cells (centre to centre) of a set cell. */
export function dilate(bitmap: Uint8Array, cols: number, rows: number, r: number): Uint8Array {
  if (r <= SMALL_RADIUS_CELLS) return byOffsets(bitmap, cols, rows, r, false, 0);
  const d = squaredDistance(bitmap, cols, rows, 1);
  const out = new Uint8Array(cols * rows);
  const r2 = r * r + 1e-9;
  for (let k = 0; k < out.length; k++) out[k] = d[k]! <= r2 ? 1 : 0;
  return out;
}

/**
 * Set cells farther than `r` cells from every unset cell of the window; beyond the window counts as set, or with
 * `outsideSet` false as unset.
 */
export function erode(bitmap: Uint8Array, cols: number, rows: number, r: number, outsideSet = true): Uint8Array {
  if (r <= SMALL_RADIUS_CELLS) return byOffsets(bitmap, cols, rows, r, true, outsideSet ? 1 : 0);
  const d = squaredDistance(bitmap, cols, rows, 0);
  const out = new Uint8Array(cols * rows);
  const r2 = r * r + 1e-9;
  for (let k = 0; k < out.length; k++) {
    if (bitmap[k] === 0 || d[k]! <= r2) continue;
    if (!outsideSet) {
      const i = k % cols;
      const j = (k - i) / cols;
      const edge = Math.min(i + 1, j + 1, cols - i, rows - j);
      if (edge * edge <= r2) continue;
    }
    out[k] = 1;
  }
  return out;
}

/** Morphological closing by a disc of `r` cells: fills gaps narrower than about 2r, grows nothing outward. */
export function close(bitmap: Uint8Array, cols: number, rows: number, r: number): Uint8Array {
  return erode(dilate(bitmap, cols, rows, r), cols, rows, r);
}

/**
 * Closings by `r` cells grown by any amount up to r, taken as growing by r and shrinking by r - grow (the same
 * wherever the closed region is locally convex, slightly larger in its concave corners): `within(k, grow)` says
 * whether cell k is in the one grown by `grow` cells. Two distance transforms serve every amount.
 */
export function grownClosings(
  bitmap: Uint8Array,
  cols: number,
  rows: number,
  r: number,
): (k: number, grow: number) => boolean {
  const grown = dilate(bitmap, cols, rows, r);
  const d = squaredDistance(grown, cols, rows, 0);
  return (k, grow) => {
    const keep = Math.max(0, r - grow);
    return grown[k] !== 0 && d[k]! > keep * keep + 1e-9;
  };
}

/** Clears (in place) every 8-connected component of set cells with fewer than `minCells` cells. */
export function dropSmallComponents(bitmap: Uint8Array, cols: number, rows: number, minCells: number): void {
  if (minCells <= 1) return;
  const seen = new Uint8Array(bitmap.length);
  const stack: number[] = [];
  const members: number[] = [];
  for (let start = 0; start < bitmap.length; start++) {
    if (bitmap[start] === 0 || seen[start] !== 0) continue;
    members.length = 0;
    stack.push(start);
    seen[start] = 1;
    while (stack.length > 0) {
      const k = stack.pop()!;
      members.push(k);
      const i = k % cols;
      const j = (k - i) / cols;
      for (let dj = -1; dj <= 1; dj++) {
        const jj = j + dj;
        if (jj < 0 || jj >= rows) continue;
        for (let di = -1; di <= 1; di++) {
          const ii = i + di;
          if (ii < 0 || ii >= cols) continue;
          const q = jj * cols + ii;
          if (bitmap[q] !== 0 && seen[q] === 0) {
            seen[q] = 1;
            stack.push(q);
          }
        }
      }
    }
    if (members.length < minCells) for (const k of members) bitmap[k] = 0;
  }
}
