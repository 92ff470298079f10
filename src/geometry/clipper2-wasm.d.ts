// The package ships its types beside its builds rather than in them: the ES build's default export is the
// factory those types describe.
declare module 'clipper2-wasm/dist/es/clipper2z.js' {
  import type { MainModule } from 'clipper2-wasm/dist/clipper2z.js';
  const factory: (options?: object) => Promise<MainModule>;
  export default factory;
}
