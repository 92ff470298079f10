// Browser bundles only: jpeg-js's encoder returns `Buffer.from(bytes)` when it is loaded as a CommonJS
// module, as esbuild loads it; browsers have no Buffer, so the bundles give it this one, which makes a
// Uint8Array. esbuild's `inject` puts it in place of the free name `Buffer` in bundled code.
const from = (bytes) => Uint8Array.from(bytes);
export const Buffer = { from };
