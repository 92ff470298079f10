/**
 * A browser worker entry that listens at once and gets its handler from a dynamic import: the library waits
 * for its WebAssembly clipping engine while it loads, and a message that arrives before any listener exists
 * is lost. Messages that come meanwhile are kept and handed over, in order, once the handler is there.
 */
export function listenFirst<T>(
  scope: { onmessage: ((e: { data: T }) => void) | null },
  load: () => Promise<(msg: T) => void>,
): void {
  const early: T[] = [];
  let handle: ((msg: T) => void) | null = null;
  scope.onmessage = (e) => (handle ? handle(e.data) : early.push(e.data));
  void load().then((h) => {
    handle = h;
    for (const msg of early.splice(0)) h(msg);
  });
}
