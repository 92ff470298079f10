/** Make file-supplied text safe for a one-line error message: no control characters, bounded length. */
export function printable(s: string, max = 60): string {
  const clean = s.replace(/[\u0000-\u001f\u007f-\u009f\u2028\u2029]/g, ' ');
  return clean.length > max ? `${clean.slice(0, max)}…` : clean;
}
