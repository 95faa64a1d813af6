import * as THREE from 'three';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { luminaireFragment, luminaireVertex } from '../../../shaders/luminaireShading.glsl';
import type { SharedDisplayUniforms } from './createRoomSurfaces';
import type { FixtureModule, Fixtures } from './fixtures';
import { buildLuminaireModel } from './luminaires/buildLuminaireModel';
import { emitterLuminance } from './luminaires/emitterLuminance';
import { l3dLuminaireModel } from './luminaires/l3dLuminaireModel';
import type { LuminaireModel, LuminairePart, PartFrame } from './luminaires/luminaireModel';
import { trackPieces } from './luminaires/trackParts';

/**
 * Finishes (docs/viewer.md, "Luminaires"): housings, rails and connectors a dark matte grey
 * (ρ 0.06, black-grey powder coat; assumed), steel wire ρ 0.4 (assumed). The flat sRGB colours are
 * what lux mode and the selection draw.
 */
const HOUSING = { reflectance: 0.06, flat: [0.16, 0.16, 0.17] as Rgb };
const CABLE = { reflectance: 0.4, flat: [0.3, 0.3, 0.3] as Rgb };
/** The UI's accent blue (the plan's selection colour), for the selected module. */
const SELECTED: Rgb = [0.16, 0.56, 0.98];
const DEG = Math.PI / 180;

/** The drawn hardware (rails, connectors, cables, luminaire models with their glow) as a three.js group, rebuilt on each setFixtures. */
export interface RoomHardware {
  readonly group: THREE.Group;
  setFixtures(fixtures: Fixtures): void;
  /** Each module's weight now (dimming × colour, linear RGB) by id: the glow follows relights (live levels, crossfades). */
  setModuleWeights(weights: ReadonlyMap<string, Rgb>): void;
  /** The room's mean illuminance (RGB lux, area-weighted over its surfaces): what lights the housings. */
  setAmbient(illuminance: Rgb): void;
  /** Draw one module in the selection colour (null: none); kept across setFixtures. */
  setSelectedModule(id: string | null): void;
  /** The meshes a pick may hit, each named `module:<id>`. */
  moduleMeshes(): THREE.Mesh[];
  dispose(): void;
}

/** The world matrix of a part's frame (luminaireModel.ts) for a module. */
export function frameMatrix(frame: PartFrame, m: Pick<FixtureModule, 'centre' | 'heading' | 'orientation'>, model: Pick<LuminaireModel, 'pivot'>): THREE.Matrix4 {
  const at = new THREE.Matrix4().makeTranslation(...m.centre);
  if (frame === 'mount') return at.multiply(new THREE.Matrix4().makeRotationY(m.heading * DEG));
  const swivel = at.multiply(new THREE.Matrix4().makeRotationY(m.orientation.yaw * DEG));
  if (frame === 'swivel') return swivel;
  const [px, py, pz] = model.pivot;
  return swivel
    .multiply(new THREE.Matrix4().makeTranslation(px, py, pz))
    .multiply(new THREE.Matrix4().makeRotationX(m.orientation.pitch * DEG))
    .multiply(new THREE.Matrix4().makeRotationY(m.orientation.roll * DEG))
    .multiply(new THREE.Matrix4().makeTranslation(-px, -py, -pz));
}

function partGeometry(p: LuminairePart): THREE.BufferGeometry {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(p.positions, 3));
  g.setAttribute('normal', new THREE.BufferAttribute(p.normals, 3));
  g.setIndex(new THREE.BufferAttribute(p.indices, 1));
  return g;
}

/**
 * `shading.linear`: the parts write adapt·(L·exposure), the value before the tone curve
 * (luminaireShading.glsl.ts), for a float target; the view itself never sets it.
 */
export function createRoomHardware(display: SharedDisplayUniforms, shading: { linear?: boolean } = {}): RoomHardware {
  const group = new THREE.Group();
  const ambient = { value: new THREE.Vector3(0, 0, 0) };
  const material = (opts: { flat: Rgb; reflectance?: number; emitter?: boolean; selected?: boolean }) =>
    new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      vertexShader: luminaireVertex,
      fragmentShader: luminaireFragment(shading),
      // Open parts (a wire, the rail's channel) show their inner side; the shader flips its normal.
      side: THREE.DoubleSide,
      uniforms: {
        uExposure: display.uExposure,
        uAdapt: display.uAdapt,
        uMode: display.uMode,
        uAmbient: ambient,
        uEmitter: { value: opts.emitter ? 1 : 0 },
        uFlat: { value: opts.selected ? 1 : 0 },
        uColor: { value: new THREE.Vector3(...opts.flat) },
        uReflectance: { value: new THREE.Vector3().setScalar(opts.reflectance ?? 0) },
        uLuminance: { value: new THREE.Vector3(0, 0, 0) },
      },
    });
  const housing = material({ flat: HOUSING.flat, reflectance: HOUSING.reflectance });
  const cable = material({ flat: CABLE.flat, reflectance: CABLE.reflectance });
  const selectedMaterial = material({ flat: SELECTED, selected: true });
  let selected: string | null = null;
  /** Per module: its housing meshes, its emitter materials with their luminance at full weight per side. */
  let modules = new Map<string, { meshes: THREE.Mesh[]; all: THREE.Mesh[]; emitters: { material: THREE.ShaderMaterial; luminance: number }[] }>();
  const emitterMaterials: THREE.ShaderMaterial[] = [];
  const paint = () => {
    for (const [id, m] of modules) for (const mesh of m.meshes) mesh.material = id === selected ? selectedMaterial : (mesh.userData.material as THREE.ShaderMaterial);
  };
  const setWeight = (emitters: { material: THREE.ShaderMaterial; luminance: number }[], w: Rgb) => {
    for (const e of emitters) (e.material.uniforms.uLuminance.value as THREE.Vector3).set(...(w.map((c) => (Number.isFinite(c) && c > 0 ? c * e.luminance : 0)) as Rgb));
  };
  const clear = () => {
    group.traverse((o) => (o as THREE.Mesh).geometry?.dispose());
    group.clear();
    for (const m of emitterMaterials.splice(0)) m.dispose();
    modules = new Map();
  };
  const addModule = (m: FixtureModule) => {
    const model = m.body ? l3dLuminaireModel(m.body, m).model : buildLuminaireModel({ kind: m.kind, opening: m.light?.opening ?? null, length: m.length, mount: m.mount, ...(m.stand ? { stand: m.stand } : {}) });
    const lum = m.light ? { down: emitterLuminance(m.light.flux, model.emitterArea).down, up: emitterLuminance(m.light.flux, model.emitterAreaUp ?? model.emitterArea).up } : { down: 0, up: 0 };
    const entry = { meshes: [] as THREE.Mesh[], all: [] as THREE.Mesh[], emitters: [] as { material: THREE.ShaderMaterial; luminance: number }[] };
    const frames = new Map<PartFrame, THREE.Group>();
    for (const part of model.parts) {
      let frame = frames.get(part.frame);
      if (!frame) {
        frame = new THREE.Group();
        frame.matrixAutoUpdate = false;
        frame.matrix.copy(frameMatrix(part.frame, m, model));
        frames.set(part.frame, frame);
        group.add(frame);
      }
      let mat: THREE.ShaderMaterial;
      if (part.role === 'emitter') {
        // An emitter in lux mode (and off) shows the housing's colour.
        mat = material({ flat: HOUSING.flat, reflectance: HOUSING.reflectance, emitter: true });
        emitterMaterials.push(mat);
        entry.emitters.push({ material: mat, luminance: part.side === 1 ? lum.up : lum.down });
      } else mat = part.role === 'cable' ? cable : housing;
      const mesh = new THREE.Mesh(partGeometry(part), mat);
      mesh.name = `module:${m.id}`;
      frame.add(mesh);
      entry.all.push(mesh);
      if (part.role !== 'emitter') {
        mesh.userData.material = mat;
        entry.meshes.push(mesh);
      }
    }
    setWeight(entry.emitters, m.on && m.light ? m.light.weight : [0, 0, 0]);
    modules.set(m.id, entry);
  };
  return {
    group,
    setFixtures(fixtures) {
      clear();
      for (const piece of trackPieces(fixtures)) group.add(new THREE.Mesh(piece.geometry, piece.role === 'cable' ? cable : housing));
      // The wires are thinner than a pixel from most views: a one-pixel line along each keeps them visible.
      if (fixtures.cables.length > 0) {
        const g = new THREE.BufferGeometry();
        g.setAttribute(
          'position',
          new THREE.Float32BufferAttribute(
            fixtures.cables.flatMap((c) => [...c.top, ...c.bottom]),
            3,
          ),
        );
        g.setAttribute(
          'normal',
          new THREE.Float32BufferAttribute(
            fixtures.cables.flatMap(() => [1, 0, 0, 1, 0, 0]),
            3,
          ),
        );
        group.add(new THREE.LineSegments(g, cable));
      }
      for (const m of fixtures.modules) addModule(m);
      paint();
    },
    setModuleWeights(weights) {
      for (const [id, w] of weights) {
        const m = modules.get(id);
        if (m) setWeight(m.emitters, w);
      }
    },
    setAmbient(e) {
      ambient.value.set(...(e.map((c) => (Number.isFinite(c) && c > 0 ? c : 0)) as Rgb));
    },
    setSelectedModule(id) {
      selected = id;
      paint();
    },
    moduleMeshes() {
      return [...modules.values()].flatMap((m) => m.all);
    },
    dispose() {
      clear();
      housing.dispose();
      cable.dispose();
      selectedMaterial.dispose();
    },
  };
}
