/**
 * Working arrays made afresh for one call of a kernel that has no owner to keep them between calls (the infill's
 * scanline sweep): plain arrays, not typed arrays. A typed array of more than 64 bytes gets a buffer of its own
 * outside the JavaScript heap, which costs about half a microsecond to make and again to collect; a kernel that
 * makes several per call, thousands of times a slice, spends more on them than on its work. A plain array of
 * numbers lives on the heap, is made as cheaply as any small object, and reads and writes as fast in a kernel's
 * loop. (Kernels with an owner keep typed working arrays with it instead: the clip operations' offset, clip.ts.)
 */

/** n numbers, all 0 (whole numbers or not: an array of whole numbers widens itself on its first fraction). */
export function workArray(n: number): number[] {
  return new Array<number>(n).fill(0);
}
