import * as THREE from 'three';
import type { Fixtures, FixtureModule } from '../fixtures';
import { buildLuminaireModel } from '../luminaires/buildLuminaireModel';
import { emitterLuminance } from '../luminaires/emitterLuminance';
import { l3dLuminaireModel } from '../luminaires/l3dLuminaireModel';
import type { LuminaireModel, LuminairePart, PartFrame } from '../luminaires/luminaireModel';
import { trackPieces } from '../luminaires/trackParts';
import { HOUSING, hardwareMaterial, setEmitterWeight, type HardwareState, type ModuleEntry } from './hardwareState';

const DEG = Math.PI / 180;

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

/** The rails, connectors and suspension wires of a configuration, added to the group. */
export function addTrack(s: HardwareState, fixtures: Fixtures): void {
  for (const piece of trackPieces(fixtures)) s.group.add(new THREE.Mesh(piece.geometry, piece.role === 'cable' ? s.cable : s.housing));
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
    s.group.add(new THREE.LineSegments(g, s.cable));
  }
}

/** A module's luminaire model (its L3D body, else the built one) and its emitters' luminance at full flux per side. */
function moduleModel(m: FixtureModule): { model: LuminaireModel; lum: { down: number; up: number } } {
  const model = m.body ? l3dLuminaireModel(m.body, m).model : buildLuminaireModel({ kind: m.kind, opening: m.light?.opening ?? null, length: m.length, mount: m.mount, ...(m.stand ? { stand: m.stand } : {}) });
  const lum = m.light ? { down: emitterLuminance(m.light.flux, model.emitterArea).down, up: emitterLuminance(m.light.flux, model.emitterAreaUp ?? model.emitterArea).up } : { down: 0, up: 0 };
  return { model, lum };
}

/** The group of a part's frame for this module, made on first use. */
function frameGroup(s: HardwareState, frames: Map<PartFrame, THREE.Group>, frame: PartFrame, m: FixtureModule, model: LuminaireModel): THREE.Group {
  let group = frames.get(frame);
  if (!group) {
    group = new THREE.Group();
    group.matrixAutoUpdate = false;
    group.matrix.copy(frameMatrix(frame, m, model));
    frames.set(frame, group);
    s.group.add(group);
  }
  return group;
}

/** One luminaire module's parts in their frames, its emitters at the module's weight, entered for picks and selection. */
export function addModule(s: HardwareState, m: FixtureModule): void {
  const { model, lum } = moduleModel(m);
  const entry: ModuleEntry = { meshes: [], all: [], emitters: [] };
  const frames = new Map<PartFrame, THREE.Group>();
  for (const part of model.parts) {
    const frame = frameGroup(s, frames, part.frame, m, model);
    let mat: THREE.ShaderMaterial;
    if (part.role === 'emitter') {
      // An emitter in lux mode (and off) shows the housing's colour.
      mat = hardwareMaterial(s, { flat: HOUSING.flat, reflectance: HOUSING.reflectance, emitter: true });
      s.emitterMaterials.push(mat);
      entry.emitters.push({ material: mat, luminance: part.side === 1 ? lum.up : lum.down });
    } else mat = part.role === 'cable' ? s.cable : s.housing;
    const mesh = new THREE.Mesh(partGeometry(part), mat);
    mesh.name = `module:${m.id}`;
    frame.add(mesh);
    entry.all.push(mesh);
    if (part.role !== 'emitter') {
      mesh.userData.material = mat;
      entry.meshes.push(mesh);
    }
  }
  setEmitterWeight(entry.emitters, m.on && m.light ? m.light.weight : [0, 0, 0]);
  s.modules.set(m.id, entry);
}
