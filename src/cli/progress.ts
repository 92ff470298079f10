/** A one-line progress bar for a terminal stream. */
export interface ProgressBar {
  update(fraction: number, label: string): void;
  done(): void;
}

export function progressBar(stream: NodeJS.WriteStream, width = 30): ProgressBar {
  let last = -1;
  let finished = false;
  return {
    update(fraction, label) {
      if (finished) return;
      const pct = Math.max(0, Math.min(100, Math.floor(fraction * 100)));
      if (pct === last) return;
      last = pct;
      const filled = Math.round((pct / 100) * width);
      stream.write(
        `\r[${'#'.repeat(filled)}${'.'.repeat(width - filled)}] ${String(pct).padStart(3)}% ${label.padEnd(10)}`,
      );
    },
    done() {
      if (finished) return;
      finished = true;
      if (last >= 0) stream.write('\r' + ' '.repeat(width + 20) + '\r');
    },
  };
}
