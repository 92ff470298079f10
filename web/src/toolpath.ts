/**
 * The toolpath preview: every extrusion segment is one instance of a small bead profile (top and two
 * slanted sides), placed and lit in the vertex shader from the worker's typed arrays, so nothing is
 * built per segment on the page thread. Layers, feature visibility and colours are uniforms: moving
 * the layer slider or hiding a feature redraws without touching the data. The arrays are drawn in
 * chunks, so a range of layers skips the chunks outside it and cuts the top one short.
 */
import {
  BufferAttribute,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  InstancedBufferGeometry,
  InstancedInterleavedBuffer,
  InterleavedBufferAttribute,
  LineSegments,
  Mesh,
  Points,
  Scene,
  ShaderMaterial,
  type Camera,
  type Object3D,
  type WebGLRenderer,
} from 'three';
import { FEATURE_TYPES } from '../../src/plan/types.js';
import { FEATURE_COLOURS } from '../../src/preview/svg.js';
import { RETRACTION_STRIDE, SEGMENT_STRIDE, TRAVEL_STRIDE, type PreviewArrays } from '../../src/preview/plan-arrays.js';

/** Instances per draw call (and per upload). */
const CHUNK = 1 << 16;
const NF = FEATURE_TYPES.length;

const BEAD_VERTEX = /* glsl */ `
attribute vec4 aSeg;
attribute vec3 aBead;
attribute vec2 aKind;
uniform float uLo;
uniform float uHi;
uniform float uVisible[${NF}];
uniform vec3 uColor[${NF}];
varying vec3 vColor;
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
  float top = aKind.y > uHi - 0.5 ? 1.08 : 1.0;
  vColor = uColor[f] * light * top;
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
  const s = 0.5, b = 0.36;
  // prettier-ignore
  const position = [
    0, -s, 0, 1, -s, 0, 1, s, 0, 0, s, 0, // top
    0, s, 0, 1, s, 0, 1, b, -1, 0, b, -1, // left side
    0, -b, -1, 1, -b, -1, 1, -s, 0, 0, -s, 0, // right side
  ];
  const up = [0, 0, 1], left = [0, 0.94, 0.34], right = [0, -0.94, 0.34];
  const normal = [...up, ...up, ...up, ...up, ...left, ...left, ...left, ...left, ...right, ...right, ...right, ...right];
  const index = [0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10, 8, 10, 11];
  return { position: new Float32BufferAttribute(position, 3), normal: new Float32BufferAttribute(normal, 3), index: new BufferAttribute(new Uint16Array(index), 1) };
}

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
  kind: 'bead' | 'travel' | 'retract';
}

export class ToolpathView {
  readonly group = new Group();
  readonly colours: Color[] = FEATURE_TYPES.map((f) => new Color(FEATURE_COLOURS[f]));
  #bead = beadGeometry();
  #lineBase = new Float32BufferAttribute([0, 0, 0, 1, 0, 0], 3);
  #pointBase = new Float32BufferAttribute([0, 0, 0], 3);
  #range = { lo: 0, hi: 0 };
  #chunks: Chunk[] = [];
  #travel = new Group();
  #retract = new Group();
  readonly beadMaterial = new ShaderMaterial({
    vertexShader: BEAD_VERTEX,
    fragmentShader: COLOUR_FRAGMENT,
    side: DoubleSide,
    uniforms: {
      uLo: { value: 0 },
      uHi: { value: 0 },
      uVisible: { value: FEATURE_TYPES.map(() => 1) },
      uColor: { value: this.colours },
    },
  });
  readonly travelMaterial = this.#lineMaterial('#9467bd', 1);
  readonly retractMaterial = this.#lineMaterial('#c2185b', 5);

  constructor(private requestRender: () => void) {
    this.group.add(this.#travel, this.#retract);
    this.#travel.visible = false;
    this.#retract.visible = false;
  }

  /** Compile the shaders now (on a hidden instance of each kind), not when the first result arrives. */
  warmUp(renderer: WebGLRenderer, camera: Camera): void {
    const a = emptyArrays();
    const scene = new Scene();
    const chunks = this.#chunks;
    this.#chunks = [];
    this.#addChunk('bead', a.segments, SEGMENT_STRIDE, 0, 1, a.layerSegments);
    this.#addChunk('travel', a.travels, TRAVEL_STRIDE, 0, 1, a.layerTravels);
    this.#addChunk('retract', a.retractions, RETRACTION_STRIDE, 0, 1, a.layerRetractions);
    for (const c of this.#chunks) scene.add(c.object);
    renderer.compile(scene, camera);
    for (const c of this.#chunks) c.geometry.dispose();
    this.#chunks = chunks;
  }

  #lineMaterial(colour: string, size: number): ShaderMaterial {
    return new ShaderMaterial({
      vertexShader: LINE_VERTEX,
      fragmentShader: FLAT_FRAGMENT,
      uniforms: { uLo: { value: 0 }, uHi: { value: 0 }, uSize: { value: size * Math.min(window.devicePixelRatio || 1, 2) }, uTint: { value: new Color(colour) } },
    });
  }

  clear(): void {
    for (const c of this.#chunks) {
      c.object.parent?.remove(c.object);
      c.geometry.dispose();
    }
    this.#chunks = [];
  }

  /** Show a new result (three.js uploads the arrays on the next draw). */
  setData(a: PreviewArrays): void {
    this.clear();
    const plan = (kind: Chunk['kind'], data: Float32Array, stride: number, offsets: Uint32Array) => {
      const total = data.length / stride;
      for (let start = 0; start < total; start += CHUNK) {
        const count = Math.min(CHUNK, total - start);
        this.#addChunk(kind, data.subarray(start * stride, (start + count) * stride), stride, start, count, offsets);
      }
    };
    plan('bead', a.segments, SEGMENT_STRIDE, a.layerSegments);
    plan('travel', a.travels, TRAVEL_STRIDE, a.layerTravels);
    plan('retract', a.retractions, RETRACTION_STRIDE, a.layerRetractions);
    this.#applyRange();
    this.requestRender();
  }

  #addChunk(kind: Chunk['kind'], data: Float32Array, stride: number, start: number, count: number, offsets: Uint32Array): void {
    const g = new InstancedBufferGeometry();
    const buf = new InstancedInterleavedBuffer(data, stride, 1);
    let object: Object3D;
    let layerAt: number;
    if (kind === 'bead') {
      g.setIndex(this.#bead.index);
      g.setAttribute('position', this.#bead.position);
      g.setAttribute('normal', this.#bead.normal);
      g.setAttribute('aSeg', new InterleavedBufferAttribute(buf, 4, 0));
      g.setAttribute('aBead', new InterleavedBufferAttribute(buf, 3, 4));
      g.setAttribute('aKind', new InterleavedBufferAttribute(buf, 2, 7));
      object = new Mesh(g, this.beadMaterial);
      layerAt = 8;
      this.group.add(object);
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
    this.#chunks.push({ object, geometry: g, start, count, firstLayer: data[layerAt], lastLayer: data[(count - 1) * stride + layerAt], offsets, kind });
  }

  /** Show layers lo..hi (inclusive). */
  setRange(lo: number, hi: number): void {
    this.#range = { lo, hi };
    for (const m of [this.beadMaterial, this.travelMaterial, this.retractMaterial]) {
      m.uniforms.uLo.value = lo;
      m.uniforms.uHi.value = hi;
    }
    this.#applyRange();
    this.requestRender();
  }

  /** Chunks wholly outside the range are skipped; the top chunk draws only up to the last layer shown. */
  #applyRange(): void {
    const { lo, hi } = this.#range;
    for (const c of this.#chunks) {
      const inRange = c.lastLayer >= lo && c.firstLayer <= hi;
      c.object.visible = inRange;
      if (!inRange) continue;
      const end = c.offsets[Math.min(hi + 1, c.offsets.length - 1)];
      c.geometry.instanceCount = Math.max(0, Math.min(c.count, end - c.start));
    }
  }

  setFeatureVisible(index: number, on: boolean): void {
    (this.beadMaterial.uniforms.uVisible.value as number[])[index] = on ? 1 : 0;
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
  };
}
