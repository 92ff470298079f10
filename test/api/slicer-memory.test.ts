import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { setFlagsFromString } from 'node:v8';
import { runInNewContext } from 'node:vm';
import { Slicer } from '#strata/api/slicer.js';

// a full collection on demand, to see what the slice still holds
setFlagsFromString('--expose-gc');
const collect = runInNewContext('gc') as () => void;

const cube = new URL('../../../examples/calibration-cube.stl', import.meta.url);

for (const call of ['slice', 'sliceToSink', 'slicePlan'] as const) {
  test(`${call} lets the model file's bytes go once the model is read, before the G-code is written`, async () => {
    let bytes: Uint8Array | undefined = new Uint8Array(readFileSync(cube));
    const ref = new WeakRef(bytes);
    let freed: boolean | undefined;
    const onProgress = (p: { stage: string }) => {
      if (p.stage !== 'writing' || freed !== undefined) return;
      collect();
      freed = ref.deref() === undefined;
    };
    const s = new Slicer({ threads: 1 });
    const done =
      call === 'slice'
        ? s.slice(bytes, { onProgress })
        : call === 'sliceToSink'
          ? s.sliceToSink(bytes, () => {}, { onProgress })
          : s.slicePlan(bytes, { onProgress });
    bytes = undefined;
    const r = await done;
    assert.equal(r.stats.layers, 100);
    assert.equal(freed, true, 'the input was still alive while the G-code was written');
  });
}
