// The encoder half of jpeg-js, imported on its own (the package's types cover only its index).
declare module 'jpeg-js/lib/encoder.js' {
  import type { RawImageData } from 'jpeg-js';
  export default function encode(
    image: RawImageData<Uint8Array | Uint8ClampedArray>,
    quality?: number,
  ): RawImageData<Uint8Array>;
}
