/**
 * The order of a group's entries: by their role's rank in the role table (paths/roles.ts), walls among
 * themselves by the wallOrder setting.
 */
import type { PathEntry } from '../paths/types.js';
import type { Config } from '../settings/resolve.js';

/** Sort a group's entries into print order (stable: entries of one rank keep the builder's order). */
export function sortEntries(entries: readonly PathEntry[], wallOrder: Config['wallOrder']): PathEntry[] {
  if (entries.length < 2) return entries.slice();
  const wallKey = (e: PathEntry) => (e.wall ?? 0) * (wallOrder === 'inner-first' ? -1 : 1);
  const before = (a: PathEntry, b: PathEntry) =>
    a.style.rank - b.style.rank || (a.role === 'wall' && b.role === 'wall' ? wallKey(a) - wallKey(b) : 0);
  // most groups come in print order already (a tree branch's wall, then its line): the stable sort would keep them
  let sorted = true;
  for (let i = 1; i < entries.length && sorted; i++) sorted = before(entries[i - 1], entries[i]) <= 0;
  if (sorted) return entries.slice();
  return entries
    .map((e, i) => ({ e, i }))
    .sort((a, b) => before(a.e, b.e) || a.i - b.i)
    .map((x) => x.e);
}
