/** Grouping of ids by grid cell in flat arrays (a counting sort), for the point grids that are filled once. */

/** Ids 0 … n-1 by cell: cell c's ids are items[start[c] … start[c + 1]), in id order. `cellOf[i]` is id i's cell, below `cells`. */
export function bucketByCell(cellOf: Int32Array, cells: number): { start: Int32Array; items: Int32Array } {
  const n = cellOf.length;
  const start = new Int32Array(cells + 1);
  for (let i = 0; i < n; i++) start[cellOf[i] + 1]++;
  for (let c = 0; c < cells; c++) start[c + 1] += start[c];
  const fill = start.slice(0, cells);
  const items = new Int32Array(n);
  for (let i = 0; i < n; i++) items[fill[cellOf[i]]++] = i;
  return { start, items };
}
