/**
 * The toolpath preview: every extrusion segment is one instance of a small bead profile (top and two
 * slanted sides) at its own width and height, placed and lit in the vertex shader from the worker's
 * typed arrays, so nothing is built per segment on the page thread. Layers, feature visibility and
 * colours are uniforms, and the colour is the feature's or a ramp over one number per segment (speed,
 * fan, width or layer time): moving a slider or hiding a feature redraws without touching the data.
 * The arrays are drawn in chunks, so a range of layers skips the chunks outside it and cuts the top one
 * short, move by move when a move limit is set. A draft mode, for frames drawn while a slider is
 * dragged, draws the layers below the top one from a coarse copy: the outside (outer walls, support,
 * skirt) of every k-th layer as beads k layers tall, a few thousand instances in all, and the few top
 * layers from a small copy made for the frame. Without a GPU the vertices are most of a frame's cost,
 * and an instance outside the layers shown still costs its vertices (WebGL 2 cannot start a draw at an
 * instance), so a draft frame draws no more than those.
 */
import {
  BufferAttribute,
  Color,
  ConeGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  InstancedBufferAttribute,
  InstancedBufferGeometry,
  InstancedInterleavedBuffer,
  InterleavedBufferAttribute,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  Points,
  Scene,
  ShaderMaterial,
  Vector3,
  type Camera,
  type Object3D,
  type WebGLRenderer,
} from 'three';
import {
  FEATURE_COLOURS,
  FEATURE_TYPES,
  RETRACTION_STRIDE,
  SEGMENT_STRIDE,
  TRAVEL_STRIDE,
  type PreviewArrays,
} from 'strata-slicer';

/** Instances per draw call (and per upload). */
const CHUNK = 1 << 16;
const NF = FEATURE_TYPES.length;

/** What the toolpaths are coloured by. */
export const COLOUR_BY = ['feature', 'speed', 'fan', 'width', 'layer-time'] as const;
export type ColourBy = (typeof COLOUR_BY)[number];

/** The colour ramp for numbers, low to high (blue, cyan, green, yellow, red), as the legend draws it too. */
export const RAMP = ['#2c4bd6', '#1fb5d1', '#3dbb4c', '#f0c419', '#d7301f'];

/** Features drawn in the coarse copy: what shows the print's outside. */
const COARSE_FEATURES = new Set(['WALL-OUTER', 'SUPPORT', 'SUPPORT-INTERFACE', 'SKIRT', 'BRIM', 'RAFT']);
const COARSE_INDEX = FEATURE_TYPES.map((f) => COARSE_FEATURES.has(f));
/** Most instances in the coarse copy. */
const COARSE_BUDGET = 2500;

const BEAD_VERTEX = /* glsl */ `
attribute vec4 aSeg;
attribute vec3 aBead;
attribute vec2 aKind;
attribute float aValue;
uniform float uLo;
uniform float uHi;
uniform float uTop;
uniform float uVisible[${NF}];
uniform vec3 uColor[${NF}];
uniform float uMode;
uniform float uMin;
uniform float uSpan;
uniform vec3 uRamp[${RAMP.length}];
varying vec3 vColor;
vec3 ramp(float t) {
  float x = clamp(t, 0.0, 1.0) * ${(RAMP.length - 1).toFixed(1)};
  int i = int(min(x, ${(RAMP.length - 2).toFixed(1)}));
  return mix(uRamp[i], uRamp[i + 1], x - float(i));
}
void main() {
  int f = int(aKind.x + 0.5);
  if (aKind.y < uLo - 0.5 || aKind.y > uHi + 0.5 || uVisible[f] < 0.5) {
    vColor = vec3(0.0);
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  vec2 a = aSeg.xy, b = aSeg.zw;
  vec2 d = b - a;
  float len = max(length(d), 1e-6);
  vec2 t = d / len;
  vec2 n = vec2(-t.y, t.x);
  float w = aBead.y, h = aBead.z;
  vec2 p = mix(a - t * (0.5 * w), b + t * (0.5 * w), position.x) + n * (position.y * w);
  vec3 world = vec3(p, aBead.x + position.z * h);
  vec3 nw = normalize(vec3(t * normal.x + n * normal.y, normal.z));
  float light = 0.5 + 0.5 * max(dot(nw, normalize(vec3(-0.35, -0.6, 0.72))), 0.0);
  float top = aKind.y > uTop - 0.5 ? 1.08 : 1.0;
  vec3 base = uMode < 0.5 ? uColor[f] : ramp((aValue - uMin) / uSpan);
  vColor = base * light * top;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(world, 1.0);
}`;

const LINE_VERTEX = /* glsl */ `
attribute vec3 aFrom;
attribute vec3 aTo;
attribute float aLayer;
uniform float uLo;
uniform float uHi;
uniform float uSize;
void main() {
  if (aLayer < uLo - 0.5 || aLayer > uHi + 0.5) {
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  gl_PointSize = uSize;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(mix(aFrom, aTo, position.x), 1.0);
}`;

const COLOUR_FRAGMENT = /* glsl */ `
varying vec3 vColor;
void main() {
  gl_FragColor = vec4(vColor, 1.0);
  #include <colorspace_fragment>
}`;

const FLAT_FRAGMENT = /* glsl */ `
uniform vec3 uTint;
void main() {
  gl_FragColor = vec4(uTint, 1.0);
  #include <colorspace_fragment>
}`;

/** The bead's cross-section swept along x from 0 to 1: a top and two sides leaning in. */
function beadGeometry(): { position: BufferAttribute; normal: BufferAttribute; index: BufferAttribute } {
  const s = 0.5,
    b = 0.36;
  // prettier-ignore
  const position = [
    0,
    -s,
    0,
    1,
    -s,
    0,
    1,
    s,
    0,
    0,
    s,
    0, // top
    0,
    s,
    0,
    1,
    s,
    0,
    1,
    b,
    -1,
    0,
    b,
    -1, // left side
    0,
    -b,
    -1,
    1,
    -b,
    -1,
    1,
    -s,
    0,
    0,
    -s,
    0, // right side
  ];
  const up = [0, 0, 1],
    left = [0, 0.94, 0.34],
    right = [0, -0.94, 0.34];
  const normal = [
    ...up,
    ...up,
    ...up,
    ...up,
    ...left,
    ...left,
    ...left,
    ...left,
    ...right,
    ...right,
    ...right,
    ...right,
  ];
  const index = [0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11];
  return {
    position: new Float32BufferAttribute(position, 3),
    normal: new Float32BufferAttribute(normal, 3),
    index: new BufferAttribute(new Uint16Array(index), 1),
  };
}

type Kind = 'bead' | 'coarse' | 'travel' | 'retract';

interface Chunk {
  object: Object3D;
  geometry: InstancedBufferGeometry;
  /** First instance (in the whole array) and count. */
  start: number;
  count: number;
  firstLayer: number;
  lastLayer: number;
  /** Per-layer offsets of the array this chunk belongs to. */
  offsets: Uint32Array;
  /** Each instance's move number within its layer (not for the coarse copy). */
  moves: Uint32Array | null;
  /** The number coloured by, one per instance (beads). */
  value?: InstancedBufferAttribute;
  kind: Kind;
}

/** The coarse copy of a print: records as the segments' (heights k layers), with its own layer offsets. */
interface Coarse {
  data: Float32Array;
  /** Which segment each record copies. */
  source: Uint32Array;
  offsets: Uint32Array;
  /** Layers per record. */
  k: number;
}

/** Every k-th layer's outside (COARSE_FEATURES), each bead k layers tall, k as small as the budget allows. */
export function coarseCopy(a: PreviewArrays, budget = COARSE_BUDGET): Coarse {
  const n = a.layerZ.length;
  const outside = COARSE_INDEX;
  const perLayer = new Uint32Array(n);
  for (let i = 0; i < n; i++) {
    for (let s = a.layerSegments[i]; s < a.layerSegments[i + 1]; s++)
      if (outside[a.segments[s * SEGMENT_STRIDE + 7]]) perLayer[i]++;
  }
  // runs of rising layers: the whole print, or in sequential printing each object (Z goes down between them)
  const runStart = new Uint32Array(n);
  for (let i = 1; i < n; i++) runStart[i] = a.layerZ[i] < a.layerZ[i - 1] ? i : runStart[i - 1];
  const runEnds = (i: number) => i === n - 1 || runStart[i + 1] === i + 1;
  const kept = (k: number, i: number) => i % k === k - 1 || runEnds(i);
  let k = 1;
  for (;;) {
    let total = 0;
    for (let i = 0; i < n; i++) if (kept(k, i)) total += perLayer[i];
    if (total <= budget || k >= n) break;
    k++;
  }
  const source: number[] = [];
  const offsets = new Uint32Array(n + 1);
  for (let i = 0; i < n; i++) {
    offsets[i] = source.length;
    if (!kept(k, i)) continue;
    for (let s = a.layerSegments[i]; s < a.layerSegments[i + 1]; s++)
      if (outside[a.segments[s * SEGMENT_STRIDE + 7]]) source.push(s);
  }
  offsets[n] = source.length;
  const data = new Float32Array(source.length * SEGMENT_STRIDE);
  for (let r = 0; r < source.length; r++) {
    const o = source[r] * SEGMENT_STRIDE;
    data.set(a.segments.subarray(o, o + SEGMENT_STRIDE), r * SEGMENT_STRIDE);
    const li = a.segments[o + 8];
    // down to the top of the layer below the group it stands for (the bed when the group starts its object)
    const below = li - k >= runStart[li] ? a.layerZ[li - k] : 0;
    data[r * SEGMENT_STRIDE + 6] = Math.max(a.segments[o + 6], a.layerZ[li] - below);
  }
  return { data, source: Uint32Array.from(source), offsets, k };
}

/** The first index in [from, to) whose move is at least `move` (moves increase along a layer). */
function firstAtLeast(moves: Uint32Array, from: number, to: number, move: number): number {
  let lo = from,
    hi = to;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (moves[mid] < move) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** One move of a layer, in words for the move slider. */
export interface MoveInfo {
  kind: 'extrude' | 'travel';
  /** Feature index (extrusions). */
  feature?: number;
  widthMm?: number;
  speed?: number;
  fan?: number;
  from: [number, number, number];
  to: [number, number, number];
}

export class ToolpathView {
  readonly group = new Group();
  readonly colours: Color[] = FEATURE_TYPES.map((f) => new Color(FEATURE_COLOURS[f]));
  #bead = beadGeometry();
  #lineBase = new Float32BufferAttribute([0, 0, 0, 1, 0, 0], 3);
  #pointBase = new Float32BufferAttribute([0, 0, 0], 3);
  #range = { lo: 0, hi: 0 };
  /** Moves of the top layer shown (null: all). */
  #moveLimit: number | null = null;
  #draft = false;
  #chunks: Chunk[] = [];
  #travel = new Group();
  #retract = new Group();
  #coarseGroup = new Group();
  #data: PreviewArrays | null = null;
  #coarse: Coarse | null = null;
  #colourBy: ColourBy = 'feature';
  /** The numbers coloured by, per segment (for the draft's copy of the top layers). */
  #valueCache: Float32Array = new Float32Array(0);
  /** The draft's copy of the top layers: its mesh, data and values, grown as needed. */
  #window: {
    mesh: Mesh;
    geometry: InstancedBufferGeometry;
    data: InstancedInterleavedBuffer;
    value: InstancedBufferAttribute;
  } | null = null;
  /** Where the nozzle is after the last move shown, when the top layer is cut short. */
  #tool = new Mesh(
    new ConeGeometry(0.45, 1.6, 16).rotateX(-Math.PI / 2).translate(0, 0, 0.8),
    new MeshBasicMaterial({ color: '#111827' }),
  );
  readonly beadMaterial = this.#makeBeadMaterial();
  readonly coarseMaterial = this.#makeBeadMaterial();
  readonly travelMaterial = this.#lineMaterial('#9467bd', 1);
  readonly retractMaterial = this.#lineMaterial('#c2185b', 5);

  constructor(private requestRender: () => void) {
    this.group.add(this.#travel, this.#retract, this.#coarseGroup, this.#tool);
    this.#travel.visible = false;
    this.#retract.visible = false;
    this.#coarseGroup.visible = false;
    this.#tool.visible = false;
  }

  #makeBeadMaterial(): ShaderMaterial {
    return new ShaderMaterial({
      vertexShader: BEAD_VERTEX,
      fragmentShader: COLOUR_FRAGMENT,
      side: DoubleSide,
      uniforms: {
        uLo: { value: 0 },
        uHi: { value: 0 },
        uTop: { value: 0 },
        uVisible: { value: FEATURE_TYPES.map(() => 1) },
        uColor: { value: this.colours },
        uMode: { value: 0 },
        uMin: { value: 0 },
        uSpan: { value: 1 },
        uRamp: { value: RAMP.map((c) => new Color(c)) },
      },
    });
  }

  /** Compile the shaders now (on a hidden instance of each kind), not when the first result arrives. */
  warmUp(renderer: WebGLRenderer, camera: Camera): void {
    const a = emptyArrays();
    const scene = new Scene();
    const chunks = this.#chunks;
    this.#chunks = [];
    const values = new Float32Array(1);
    this.#addChunk('bead', a.segments, SEGMENT_STRIDE, 0, 1, a.layerSegments, a.segmentMove, values);
    this.#addChunk('travel', a.travels, TRAVEL_STRIDE, 0, 1, a.layerTravels, a.travelMove);
    this.#addChunk('retract', a.retractions, RETRACTION_STRIDE, 0, 1, a.layerRetractions, a.retractionMove);
    for (const c of this.#chunks) scene.add(c.object);
    renderer.compile(scene, camera);
    for (const c of this.#chunks) c.geometry.dispose();
    this.#chunks = chunks;
  }

  #lineMaterial(colour: string, size: number): ShaderMaterial {
    return new ShaderMaterial({
      vertexShader: LINE_VERTEX,
      fragmentShader: FLAT_FRAGMENT,
      uniforms: {
        uLo: { value: 0 },
        uHi: { value: 0 },
        uSize: { value: size * Math.min(window.devicePixelRatio || 1, 2) },
        uTint: { value: new Color(colour) },
      },
    });
  }

  clear(): void {
    for (const c of this.#chunks) {
      c.object.parent?.remove(c.object);
      c.geometry.dispose();
    }
    this.#chunks = [];
    this.#data = null;
    this.#coarse = null;
    this.#tool.visible = false;
    if (this.#window) this.#window.mesh.visible = false;
  }

  /** Show a new result (three.js uploads the arrays on the next draw). */
  setData(a: PreviewArrays): void {
    this.clear();
    this.#data = a;
    this.#coarse = coarseCopy(a);
    const values = this.#values(this.#colourBy);
    this.#valueCache = values;
    const plan = (
      kind: Kind,
      data: Float32Array,
      stride: number,
      offsets: Uint32Array,
      moves: Uint32Array | null,
      perInstance?: Float32Array,
    ) => {
      const total = data.length / stride;
      for (let start = 0; start < total; start += CHUNK) {
        const count = Math.min(CHUNK, total - start);
        this.#addChunk(
          kind,
          data.subarray(start * stride, (start + count) * stride),
          stride,
          start,
          count,
          offsets,
          moves,
          perInstance?.subarray(start, start + count),
        );
      }
    };
    plan('bead', a.segments, SEGMENT_STRIDE, a.layerSegments, a.segmentMove, values);
    plan('coarse', this.#coarse.data, SEGMENT_STRIDE, this.#coarse.offsets, null, this.#coarseValues(values));
    plan('travel', a.travels, TRAVEL_STRIDE, a.layerTravels, a.travelMove);
    plan('retract', a.retractions, RETRACTION_STRIDE, a.layerRetractions, a.retractionMove);
    this.#applyRange();
    this.requestRender();
  }

  #addChunk(
    kind: Kind,
    data: Float32Array,
    stride: number,
    start: number,
    count: number,
    offsets: Uint32Array,
    moves: Uint32Array | null,
    values?: Float32Array,
  ): void {
    const g = new InstancedBufferGeometry();
    const buf = new InstancedInterleavedBuffer(data, stride, 1);
    let object: Object3D;
    let layerAt: number;
    let value: InstancedBufferAttribute | undefined;
    if (kind === 'bead' || kind === 'coarse') {
      g.setIndex(this.#bead.index);
      g.setAttribute('position', this.#bead.position);
      g.setAttribute('normal', this.#bead.normal);
      g.setAttribute('aSeg', new InterleavedBufferAttribute(buf, 4, 0));
      g.setAttribute('aBead', new InterleavedBufferAttribute(buf, 3, 4));
      g.setAttribute('aKind', new InterleavedBufferAttribute(buf, 2, 7));
      value = new InstancedBufferAttribute(values ?? new Float32Array(count), 1);
      g.setAttribute('aValue', value);
      object = new Mesh(g, kind === 'bead' ? this.beadMaterial : this.coarseMaterial);
      layerAt = 8;
      (kind === 'bead' ? this.group : this.#coarseGroup).add(object);
    } else if (kind === 'travel') {
      g.setAttribute('position', this.#lineBase);
      g.setAttribute('aFrom', new InterleavedBufferAttribute(buf, 3, 0));
      g.setAttribute('aTo', new InterleavedBufferAttribute(buf, 3, 3));
      g.setAttribute('aLayer', new InterleavedBufferAttribute(buf, 1, 6));
      object = new LineSegments(g, this.travelMaterial);
      layerAt = 6;
      this.#travel.add(object);
    } else {
      g.setAttribute('position', this.#pointBase);
      g.setAttribute('aFrom', new InterleavedBufferAttribute(buf, 3, 0));
      g.setAttribute('aTo', new InterleavedBufferAttribute(buf, 3, 0));
      g.setAttribute('aLayer', new InterleavedBufferAttribute(buf, 1, 3));
      object = new Points(g, this.retractMaterial);
      layerAt = 3;
      this.#retract.add(object);
    }
    g.instanceCount = count;
    object.frustumCulled = false;
    object.matrixAutoUpdate = false;
    this.#chunks.push({
      object,
      geometry: g,
      start,
      count,
      firstLayer: data[layerAt],
      lastLayer: data[(count - 1) * stride + layerAt],
      offsets,
      moves,
      value,
      kind,
    });
  }

  /** Show layers lo..hi (inclusive); the move limit is dropped. */
  setRange(lo: number, hi: number): void {
    this.#range = { lo, hi };
    this.#applyRange();
    this.requestRender();
  }

  /** Show the top layer only up to (not including) move `m` (null: all of it). */
  setMoveLimit(m: number | null): void {
    this.#moveLimit = m;
    this.#applyRange();
    this.requestRender();
  }

  /** Draft frames (while a slider is dragged): the layers below the top one from the coarse copy. */
  setDraft(on: boolean): void {
    if (this.#draft === on) return;
    this.#draft = on;
    this.#applyRange();
    this.requestRender();
  }

  get coarseLayers(): number {
    return this.#coarse?.k ?? 1;
  }

  /**
   * Chunks wholly outside the range are skipped; the top chunk draws only up to the last layer shown
   * (and the move limit); in draft mode the full arrays draw the top layer and the coarse copy the rest.
   */
  #applyRange(): void {
    const { lo, hi } = this.#range;
    // in draft mode the coarse copy draws up to its last layer below the top one (each of its beads stands
    // for the k layers up to it), and the full arrays the few layers from there to the top
    const k = this.coarseLayers;
    const coarseTo = this.#draft ? Math.floor(hi / k) * k - 1 : lo - 1;
    const fullLo = Math.max(lo, coarseTo + 1);
    for (const m of [this.beadMaterial, this.travelMaterial, this.retractMaterial]) {
      m.uniforms.uLo.value = fullLo;
      m.uniforms.uHi.value = hi;
    }
    this.beadMaterial.uniforms.uTop.value = hi;
    this.coarseMaterial.uniforms.uLo.value = lo;
    this.coarseMaterial.uniforms.uHi.value = coarseTo;
    this.coarseMaterial.uniforms.uTop.value = hi;
    this.#coarseGroup.visible = coarseTo >= lo;
    this.#fillWindow(this.#draft ? fullLo : -1, hi);
    for (const c of this.#chunks) {
      const [from, to] = c.kind === 'coarse' ? [lo, coarseTo] : [fullLo, hi];
      const inRange = to >= from && c.lastLayer >= from && c.firstLayer <= to && !(this.#draft && c.kind === 'bead');
      c.object.visible = inRange;
      if (!inRange) continue;
      let end = c.offsets[Math.min(to + 1, c.offsets.length - 1)];
      if (this.#moveLimit !== null && c.moves && to === hi)
        end = firstAtLeast(c.moves, c.offsets[hi], c.offsets[hi + 1], this.#moveLimit);
      c.geometry.instanceCount = Math.max(0, Math.min(c.count, end - c.start));
    }
    this.#placeTool();
  }

  /**
   * The draft's copy of layers from..to, drawn instead of the bead chunks: the top layer whole (cut at the
   * move limit), the layers between the coarse copy's top and it by their outside only; from < 0: none.
   */
  #fillWindow(from: number, to: number): void {
    const a = this.#data;
    if (from < 0 || !a) {
      if (this.#window) this.#window.mesh.visible = false;
      return;
    }
    const picked: number[] = [];
    for (let s = a.layerSegments[from]; s < a.layerSegments[to]; s++)
      if (COARSE_INDEX[a.segments[s * SEGMENT_STRIDE + 7]]) picked.push(s);
    const topStart = a.layerSegments[to];
    let end = a.layerSegments[to + 1];
    if (this.#moveLimit !== null) end = firstAtLeast(a.segmentMove, topStart, end, this.#moveLimit);
    const count = picked.length + Math.max(0, end - topStart);
    let w = this.#window;
    if (!w || w.value.count < count) {
      if (w) {
        this.group.remove(w.mesh);
        w.geometry.dispose();
      }
      const capacity = Math.max(4096, Math.ceil(count * 1.5));
      const geometry = new InstancedBufferGeometry();
      const data = new InstancedInterleavedBuffer(new Float32Array(capacity * SEGMENT_STRIDE), SEGMENT_STRIDE, 1);
      const value = new InstancedBufferAttribute(new Float32Array(capacity), 1);
      geometry.setIndex(this.#bead.index);
      geometry.setAttribute('position', this.#bead.position);
      geometry.setAttribute('normal', this.#bead.normal);
      geometry.setAttribute('aSeg', new InterleavedBufferAttribute(data, 4, 0));
      geometry.setAttribute('aBead', new InterleavedBufferAttribute(data, 3, 4));
      geometry.setAttribute('aKind', new InterleavedBufferAttribute(data, 2, 7));
      geometry.setAttribute('aValue', value);
      const mesh = new Mesh(geometry, this.beadMaterial);
      mesh.frustumCulled = false;
      mesh.matrixAutoUpdate = false;
      this.group.add(mesh);
      w = this.#window = { mesh, geometry, data, value };
    }
    const data = w.data.array as Float32Array,
      values = w.value.array as Float32Array,
      v = this.#valueCache;
    picked.forEach((s, r) => {
      data.set(a.segments.subarray(s * SEGMENT_STRIDE, (s + 1) * SEGMENT_STRIDE), r * SEGMENT_STRIDE);
      if (v.length) values[r] = v[s];
    });
    data.set(a.segments.subarray(topStart * SEGMENT_STRIDE, end * SEGMENT_STRIDE), picked.length * SEGMENT_STRIDE);
    if (v.length) values.set(v.subarray(topStart, end), picked.length);
    w.data.addUpdateRange(0, count * SEGMENT_STRIDE);
    w.data.needsUpdate = true;
    w.value.addUpdateRange(0, count);
    w.value.needsUpdate = true;
    w.geometry.instanceCount = count;
    w.mesh.visible = count > 0;
  }

  /** The tool where the last move shown ends, when the top layer is shown only in part. */
  #placeTool(): void {
    const a = this.#data;
    const m = this.#moveLimit;
    const hi = this.#range.hi;
    this.#tool.visible = false;
    if (!a || m === null || m >= a.layerMoves[hi] || m === 0) return;
    const info = this.moveInfo(hi, m - 1);
    if (!info) return;
    this.#tool.position.set(...info.to);
    this.#tool.visible = true;
  }

  /** Move `k` of layer `li` (numbered from 0), or null. */
  moveInfo(li: number, k: number): MoveInfo | null {
    const a = this.#data;
    if (!a || li < 0 || li >= a.layerZ.length) return null;
    const s = firstAtLeast(a.segmentMove, a.layerSegments[li], a.layerSegments[li + 1], k);
    if (s < a.layerSegments[li + 1] && a.segmentMove[s] === k) {
      const o = s * SEGMENT_STRIDE,
        d = a.segments;
      return {
        kind: 'extrude',
        feature: d[o + 7],
        widthMm: d[o + 5],
        speed: a.segmentSpeed[s],
        fan: a.segmentFan[s],
        from: [d[o], d[o + 1], d[o + 4]],
        to: [d[o + 2], d[o + 3], d[o + 4]],
      };
    }
    const t = firstAtLeast(a.travelMove, a.layerTravels[li], a.layerTravels[li + 1], k);
    if (t < a.layerTravels[li + 1] && a.travelMove[t] === k) {
      const o = t * TRAVEL_STRIDE,
        d = a.travels;
      return { kind: 'travel', from: [d[o], d[o + 1], d[o + 2]], to: [d[o + 3], d[o + 4], d[o + 5]] };
    }
    return null;
  }

  /** The box of layer `li`'s extrusions (mm), or null when it has none. */
  layerBounds(li: number): { min: Vector3; max: Vector3 } | null {
    const a = this.#data;
    if (!a || li < 0 || li >= a.layerZ.length || a.layerSegments[li] === a.layerSegments[li + 1]) return null;
    const min = new Vector3(Infinity, Infinity, a.layerZ[li]),
      max = new Vector3(-Infinity, -Infinity, a.layerZ[li]);
    for (let s = a.layerSegments[li]; s < a.layerSegments[li + 1]; s++) {
      const o = s * SEGMENT_STRIDE;
      for (const [x, y] of [
        [a.segments[o], a.segments[o + 1]],
        [a.segments[o + 2], a.segments[o + 3]],
      ]) {
        min.x = Math.min(min.x, x);
        min.y = Math.min(min.y, y);
        max.x = Math.max(max.x, x);
        max.y = Math.max(max.y, y);
      }
    }
    return { min, max };
  }

  /** Colour by features, or by a number on the ramp; returns the numbers' range (null for features). */
  setColourBy(mode: ColourBy): { min: number; max: number } | null {
    this.#colourBy = mode;
    const a = this.#data;
    let range: { min: number; max: number } | null = null;
    if (a && mode !== 'feature') {
      const values = this.#values(mode);
      this.#valueCache = values;
      const coarse = this.#coarseValues(values);
      range = rangeOf(values);
      for (const c of this.#chunks) {
        if (!c.value) continue;
        (c.value.array as Float32Array).set((c.kind === 'bead' ? values : coarse).subarray(c.start, c.start + c.count));
        c.value.needsUpdate = true;
      }
    }
    for (const m of [this.beadMaterial, this.coarseMaterial]) {
      m.uniforms.uMode.value = mode === 'feature' ? 0 : 1;
      m.uniforms.uMin.value = range?.min ?? 0;
      m.uniforms.uSpan.value = range ? Math.max(range.max - range.min, 1e-6) : 1;
    }
    this.requestRender();
    return range;
  }

  /** One number per segment for a colouring (zeros for features). */
  #values(mode: ColourBy): Float32Array {
    const a = this.#data;
    if (!a) return new Float32Array(0);
    const n = a.segments.length / SEGMENT_STRIDE;
    if (mode === 'speed') return a.segmentSpeed;
    if (mode === 'fan') return a.segmentFan.map((v) => v * 100);
    const out = new Float32Array(n);
    if (mode === 'width') for (let s = 0; s < n; s++) out[s] = a.segments[s * SEGMENT_STRIDE + 5];
    else if (mode === 'layer-time')
      for (let s = 0; s < n; s++) out[s] = a.layerSeconds[a.segments[s * SEGMENT_STRIDE + 8]];
    return out;
  }

  #coarseValues(values: Float32Array): Float32Array {
    const c = this.#coarse;
    if (!c || values.length === 0) return new Float32Array(c?.source.length ?? 0);
    return Float32Array.from(c.source, (s) => values[s]);
  }

  setFeatureVisible(index: number, on: boolean): void {
    for (const m of [this.beadMaterial, this.coarseMaterial])
      (m.uniforms.uVisible.value as number[])[index] = on ? 1 : 0;
    this.requestRender();
  }

  setTravel(on: boolean): void {
    this.#travel.visible = on;
    this.requestRender();
  }

  setRetractions(on: boolean): void {
    this.#retract.visible = on;
    this.requestRender();
  }
}

/** The smallest and largest of some numbers. */
function rangeOf(values: Float32Array): { min: number; max: number } {
  let min = Infinity,
    max = -Infinity;
  for (const v of values) {
    if (v < min) min = v;
    if (v > max) max = v;
  }
  return min <= max ? { min, max } : { min: 0, max: 0 };
}

/** One instance of each kind, on layer -1 (never shown). */
function emptyArrays(): PreviewArrays {
  return {
    layerZ: new Float32Array(0),
    segments: Float32Array.of(0, 0, 1, 0, 0, 0.4, 0.2, 0, -1),
    layerSegments: Uint32Array.of(0, 1),
    travels: Float32Array.of(0, 0, 0, 1, 0, 0, -1),
    layerTravels: Uint32Array.of(0, 1),
    retractions: Float32Array.of(0, 0, 0, -1),
    layerRetractions: Uint32Array.of(0, 1),
    featureLengthMm: new Float64Array(NF),
    segmentSpeed: new Float32Array(1),
    segmentFan: new Float32Array(1),
    segmentMove: new Uint32Array(1),
    travelMove: new Uint32Array(1),
    retractionMove: new Uint32Array(1),
    layerMoves: new Uint32Array(0),
    layerSeconds: new Float32Array(0),
  };
}
