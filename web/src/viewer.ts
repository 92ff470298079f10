/**
 * The 3D view (three.js): the printer's bed with its grid and build volume, the objects on it
 * (pick, drag to move, pick a face to lay it down) and their volumes (translucent, coloured by kind;
 * pick one of the selected object's), orbit/zoom/pan. Bed coordinates, Z up, mm.
 * It draws only when something changed, so it costs nothing while a slice runs.
 */
import {
  AmbientLight,
  BoxGeometry,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  EdgesGeometry,
  Group,
  HemisphereLight,
  LineBasicMaterial,
  LineSegments,
  type Matrix4,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  Plane,
  PlaneGeometry,
  Raycaster,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { BedShape } from './plate.js';

export interface ViewObject {
  id: number;
  positions: Float32Array;
  normals: Float32Array;
  /** Column-major 4×4 model → bed. */
  matrix: Matrix4;
  /** Bed XY of its footprint centre, mm. */
  centre: [number, number];
  selected: boolean;
  problem: boolean;
  /** Drawn translucent, so the volumes inside show. */
  seeThrough: boolean;
}

/** A volume of an object: drawn translucent in its kind's colour, with its object's matrix. */
export interface ViewVolume {
  objectId: number;
  volumeId: number;
  /** Changes when the volume's shape, place or size does (its triangles are then asked for again). */
  shapeKey: string;
  arrays(): { positions: Float32Array; normals: Float32Array };
  matrix: Matrix4;
  colour: string;
  selected: boolean;
  /** Whether a click can pick it (its object is the selected one). */
  pickable: boolean;
}

export interface ViewerEvents {
  /** An object (or none) was clicked. */
  pick(id: number | null): void;
  /** A volume of the selected object was clicked. */
  pickVolume(objectId: number, volumeId: number): void;
  /** An object is dragged to a new footprint centre (bed XY, mm); `done` at the end. */
  drag(id: number, centre: [number, number], done: boolean): void;
  /** In lay-on-face mode, a face was clicked: its normal in model coordinates. */
  face(id: number, normal: [number, number, number]): void;
}

const COLOURS = {
  object: new Color('#4f8fc9'),
  selected: new Color('#2fb3a3'),
  problem: new Color('#e0605a'),
  bed: new Color('#fbfcfd'),
  grid: new Color('#d3d9df'),
  gridMajor: new Color('#b6bfc8'),
  volume: new Color('#8fa1b3'),
};

export class Viewer {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera = new PerspectiveCamera(40, 1, 0.5, 20000);
  readonly controls: OrbitControls;
  /** Toolpaths go here (shown in preview mode). */
  readonly toolpaths = new Group();
  #bed = new Group();
  #objects = new Group();
  #meshes = new Map<number, Mesh>();
  #volumes = new Map<string, Mesh>();
  #pending = false;
  #raycaster = new Raycaster();
  #faceMode = false;
  #bedShape: BedShape | null = null;

  constructor(
    private container: HTMLElement,
    private events: ViewerEvents,
  ) {
    this.renderer = new WebGLRenderer({ antialias: true, powerPreference: 'high-performance' });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setClearColor(0x000000, 0);
    container.append(this.renderer.domElement);
    this.renderer.domElement.setAttribute('aria-label', '3D view of the build plate');
    this.renderer.domElement.setAttribute('role', 'img');
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.screenSpacePanning = true;
    this.controls.addEventListener('change', () => this.render());
    this.scene.add(new HemisphereLight(0xffffff, 0x8d99a6, 1.6));
    this.scene.add(new AmbientLight(0xffffff, 0.35));
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.set(-0.5, -0.8, 1.2);
    this.scene.add(sun);
    const fill = new DirectionalLight(0xffffff, 0.5);
    fill.position.set(0.8, 0.6, 0.4);
    this.scene.add(fill);
    this.scene.add(this.#bed, this.#objects, this.toolpaths);
    new ResizeObserver(() => this.#resize()).observe(container);
    this.#resize();
    this.#pointer();
  }

  /**
   * Draft frames, while a slider is dragged: drawn at half the resolution (without a GPU the pixels are
   * most of a frame's cost), and at the full one again when it rests.
   */
  setDraft(on: boolean): void {
    const full = Math.min(window.devicePixelRatio || 1, 2);
    const ratio = on ? full / 2 : full;
    if (this.renderer.getPixelRatio() === ratio) return;
    this.renderer.setPixelRatio(ratio);
    this.render();
  }

  /** Draw on the next frame (once, however often asked). */
  render(): void {
    if (this.#pending) return;
    this.#pending = true;
    requestAnimationFrame(() => {
      this.#pending = false;
      this.renderer.render(this.scene, this.camera);
    });
  }

  #resize(): void {
    const w = Math.max(1, this.container.clientWidth),
      h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  setMode(mode: 'model' | 'preview'): void {
    this.#objects.visible = mode === 'model';
    this.toolpaths.visible = mode === 'preview';
    this.render();
  }

  setFaceMode(on: boolean): void {
    this.#faceMode = on;
    this.renderer.domElement.style.cursor = on ? 'crosshair' : '';
  }

  /** Show this bed; returns whether it changed (the view then looks at the whole bed). */
  setBed(b: BedShape): boolean {
    const first = this.#bedShape === null;
    const changed =
      !this.#bedShape ||
      ['width', 'depth', 'height', 'originAtCenter'].some(
        (k) => this.#bedShape![k as keyof BedShape] !== b[k as keyof BedShape],
      );
    this.#bedShape = b;
    if (!changed) return false;
    for (const c of [...this.#bed.children]) {
      this.#bed.remove(c);
      const m = c as Mesh;
      m.geometry?.dispose();
    }
    const x0 = b.originAtCenter ? -b.width / 2 : 0,
      y0 = b.originAtCenter ? -b.depth / 2 : 0;
    const plate = new Mesh(
      new PlaneGeometry(b.width, b.depth),
      new MeshStandardMaterial({ color: COLOURS.bed, roughness: 0.95 }),
    );
    plate.position.set(x0 + b.width / 2, y0 + b.depth / 2, -0.05);
    this.#bed.add(plate);
    // grid: 10 mm lines, darker every 50 mm, from the origin
    const minor: number[] = [],
      major: number[] = [];
    for (let x = Math.ceil(x0 / 10) * 10; x <= x0 + b.width + 1e-6; x += 10)
      (Math.round(x) % 50 === 0 ? major : minor).push(x, y0, 0, x, y0 + b.depth, 0);
    for (let y = Math.ceil(y0 / 10) * 10; y <= y0 + b.depth + 1e-6; y += 10)
      (Math.round(y) % 50 === 0 ? major : minor).push(x0, y, 0, x0 + b.width, y, 0);
    for (const [pts, colour] of [
      [minor, COLOURS.grid],
      [major, COLOURS.gridMajor],
    ] as const) {
      const g = new BufferGeometry();
      g.setAttribute('position', new BufferAttribute(new Float32Array(pts), 3));
      this.#bed.add(new LineSegments(g, new LineBasicMaterial({ color: colour })));
    }
    const volume = new LineSegments(
      new EdgesGeometry(new BoxGeometry(b.width, b.depth, b.height)),
      new LineBasicMaterial({ color: COLOURS.volume, transparent: true, opacity: 0.55 }),
    );
    volume.position.set(x0 + b.width / 2, y0 + b.depth / 2, b.height / 2);
    this.#bed.add(volume);
    if (first || changed) this.home();
    return true;
  }

  /** Look at the bed from the front, a little above. */
  home(): void {
    const b = this.#bedShape;
    if (!b) return;
    const cx = b.originAtCenter ? 0 : b.width / 2,
      cy = b.originAtCenter ? 0 : b.depth / 2;
    const span = Math.max(b.width, b.depth);
    this.controls.target.set(cx, cy, Math.min(b.height, span) * 0.12);
    this.camera.position.set(cx, cy - span * 1.15, span * 0.8);
    this.controls.update();
    this.render();
  }

  /** Aim at a box (mm) so it fills the view, seen from the current direction; at least `minRadius` mm around. */
  frame(min: Vector3, max: Vector3, minRadius = 5): void {
    const centre = min.clone().add(max).multiplyScalar(0.5);
    const r = Math.max(minRadius, min.distanceTo(max) / 2);
    const dir = this.camera.position.clone().sub(this.controls.target).normalize();
    const dist = (r / Math.sin((this.camera.fov * Math.PI) / 360)) * 1.15;
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).addScaledVector(dir, dist);
    this.controls.update();
    this.render();
  }

  /** Take out of the view (and free) the meshes of `shown` whose key is not kept. */
  #prune<K>(shown: Map<K, Mesh>, keep: ReadonlySet<K>): void {
    for (const [k, mesh] of shown) {
      if (keep.has(k)) continue;
      this.#objects.remove(mesh);
      mesh.geometry.dispose();
      (mesh.material as MeshStandardMaterial).dispose();
      shown.delete(k);
    }
  }

  setObjects(list: ViewObject[]): void {
    this.#prune(this.#meshes, new Set(list.map((o) => o.id)));
    for (const o of list) {
      let mesh = this.#meshes.get(o.id);
      if (!mesh) {
        mesh = new Mesh(
          geometry(o.positions, o.normals),
          new MeshStandardMaterial({ color: COLOURS.object, roughness: 0.6, metalness: 0.05 }),
        );
        mesh.matrixAutoUpdate = false;
        mesh.userData.id = o.id;
        this.#meshes.set(o.id, mesh);
        this.#objects.add(mesh);
      }
      mesh.matrix.copy(o.matrix);
      mesh.userData.centre = o.centre;
      mesh.matrixWorldNeedsUpdate = true;
      const material = mesh.material as MeshStandardMaterial;
      material.color.copy(o.problem ? COLOURS.problem : o.selected ? COLOURS.selected : COLOURS.object);
      if (material.transparent !== o.seeThrough) {
        // drawn after the volumes inside it, over them
        material.transparent = o.seeThrough;
        material.opacity = o.seeThrough ? 0.4 : 1;
        material.depthWrite = !o.seeThrough;
        material.needsUpdate = true;
        mesh.renderOrder = o.seeThrough ? 2 : 0;
      }
    }
    this.render();
  }

  setVolumes(list: ViewVolume[]): void {
    const key = (v: ViewVolume) => `${v.objectId}:${v.volumeId}`;
    this.#prune(this.#volumes, new Set(list.map(key)));
    for (const v of list) {
      let mesh = this.#volumes.get(key(v));
      if (!mesh) {
        mesh = new Mesh(
          new BufferGeometry(),
          new MeshStandardMaterial({ transparent: true, depthWrite: false, roughness: 0.7 }),
        );
        mesh.matrixAutoUpdate = false;
        mesh.renderOrder = 1;
        mesh.userData = { objectId: v.objectId, volumeId: v.volumeId };
        this.#volumes.set(key(v), mesh);
        this.#objects.add(mesh);
      }
      if (mesh.userData.shapeKey !== v.shapeKey) {
        const { positions, normals } = v.arrays();
        mesh.geometry.dispose();
        mesh.geometry = geometry(positions, normals);
        mesh.userData.shapeKey = v.shapeKey;
      }
      mesh.userData.pickable = v.pickable;
      mesh.matrix.copy(v.matrix);
      mesh.matrixWorldNeedsUpdate = true;
      const material = mesh.material as MeshStandardMaterial;
      material.color.set(v.colour);
      material.opacity = v.selected ? 0.8 : 0.5;
      material.emissive.set(v.selected ? v.colour : '#000000');
      material.emissiveIntensity = v.selected ? 0.35 : 0;
    }
    this.render();
  }

  #ndc(e: PointerEvent): Vector2 {
    const r = this.renderer.domElement.getBoundingClientRect();
    return new Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
  }

  #hit(e: PointerEvent) {
    if (!this.#objects.visible) return null;
    this.#raycaster.setFromCamera(this.#ndc(e), this.camera);
    return this.#raycaster.intersectObjects([...this.#meshes.values()], false)[0] ?? null;
  }

  /** The nearest volume of the selected object under the pointer. */
  #hitVolume(e: PointerEvent): Mesh | null {
    if (!this.#objects.visible) return null;
    const pickable = [...this.#volumes.values()].filter((m) => m.userData.pickable);
    if (pickable.length === 0) return null;
    this.#raycaster.setFromCamera(this.#ndc(e), this.camera);
    return (this.#raycaster.intersectObjects(pickable, false)[0]?.object as Mesh | undefined) ?? null;
  }

  #bedPoint(e: PointerEvent): Vector3 | null {
    this.#raycaster.setFromCamera(this.#ndc(e), this.camera);
    return this.#raycaster.ray.intersectPlane(new Plane(new Vector3(0, 0, 1), 0), new Vector3());
  }

  /** Click picks, drag on an object moves it, drag elsewhere orbits. */
  #pointer(): void {
    const el = this.renderer.domElement;
    let drag: { id: number; grab: Vector3; start: [number, number]; moved: boolean; pointer: number } | null = null;
    let down: { x: number; y: number } | null = null;
    el.addEventListener('pointerdown', (e) => {
      down = { x: e.clientX, y: e.clientY };
      if (e.button !== 0) return;
      const volume = this.#faceMode ? null : this.#hitVolume(e);
      if (volume) {
        this.events.pickVolume(volume.userData.objectId as number, volume.userData.volumeId as number);
        return;
      }
      const hit = this.#hit(e);
      if (!hit) return;
      const id = hit.object.userData.id as number;
      if (this.#faceMode) {
        const n = hit.face?.normal;
        if (n) this.events.face(id, [n.x, n.y, n.z]);
        this.controls.enabled = false;
        return;
      }
      this.events.pick(id);
      const p = this.#bedPoint(e);
      if (!p) return;
      const centre = this.#meshes.get(id)!.userData.centre as [number, number];
      drag = {
        id,
        grab: p.sub(new Vector3(centre[0], centre[1], 0)),
        start: centre,
        moved: false,
        pointer: e.pointerId,
      };
      this.controls.enabled = false;
      el.setPointerCapture(e.pointerId);
    });
    el.addEventListener('pointermove', (e) => {
      if (!drag || e.pointerId !== drag.pointer) return;
      const p = this.#bedPoint(e);
      if (!p) return;
      drag.moved = true;
      this.events.drag(drag.id, [round1(p.x - drag.grab.x), round1(p.y - drag.grab.y)], false);
    });
    const end = (e: PointerEvent) => {
      if (drag && e.pointerId === drag.pointer) {
        if (drag.moved) {
          const p = this.#bedPoint(e);
          this.events.drag(drag.id, p ? [round1(p.x - drag.grab.x), round1(p.y - drag.grab.y)] : drag.start, true);
        }
        drag = null;
      }
      this.controls.enabled = true;
    };
    el.addEventListener('pointerup', (e) => {
      const click = down && Math.hypot(e.clientX - down.x, e.clientY - down.y) < 4;
      if (click && !drag && !this.#faceMode && e.button === 0 && !this.#hit(e) && !this.#hitVolume(e))
        this.events.pick(null);
      end(e);
    });
    el.addEventListener('pointercancel', end);
  }
}

/** Triangles to draw: corners and their normals. */
function geometry(positions: Float32Array, normals: Float32Array): BufferGeometry {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(positions, 3));
  g.setAttribute('normal', new BufferAttribute(normals, 3));
  g.computeBoundingSphere();
  return g;
}

/** Dragged positions snap to 0.1 mm. */
function round1(v: number): number {
  return Math.round(v * 10) / 10;
}
