import * as THREE from 'three';
import type { Fixtures, FixtureModule } from '../fixtures';
import { buildLuminaireModel } from '../luminaires/buildLuminaireModel';
import { l3dLuminaireModel } from '../luminaires/l3dLuminaireModel';
import type { LuminaireModel, LuminairePart, PartFrame } from '../luminaires/luminaireModel';
import { trackPieces } from '../luminaires/trackParts';
import { emitterPhotometry } from '../luminaires/viewLuminance';
import { HOUSING, glowToward, hardwareMaterial, setEmitterWeight, type Emitter, type HardwareState, type ModuleEntry } from './hardwareState';

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

/** A module's luminaire model: its L3D body, else the built one. */
function moduleModel(m: FixtureModule): LuminaireModel {
  return m.body ? l3dLuminaireModel(m.body, m).model : buildLuminaireModel({ kind: m.kind, opening: m.light?.opening ?? null, length: m.length, mount: m.mount, ...(m.stand ? { stand: m.stand } : {}) });
}

/**
 * The centre of a part's bounding box (its frame's coordinates): where the eye's direction is taken
 * from. Not the mean of its vertices: a fan-triangulated disc repeats its first rim vertex, which
 * would pull the mean 1/(n+2) of the radius toward it.
 */
function partCentre(p: LuminairePart): THREE.Vector3 {
  return p.positions.length > 0 ? new THREE.Box3().setFromArray(p.positions).getCenter(new THREE.Vector3()) : new THREE.Vector3();
}

/**
 * An emitter face of a module: its own material (its glow is the module's), the photometry it
 * shows toward the eye (luminaires/viewLuminance.ts) and the area of its side's luminous surface;
 * its luminance is set before each draw from the camera drawing it.
 */
function emitterOf(s: HardwareState, m: FixtureModule, model: LuminaireModel, part: LuminairePart, mesh: THREE.Mesh): Emitter {
  // An emitter in lux mode (and off) shows the housing's colour.
  const material = hardwareMaterial(s, { flat: HOUSING.flat, reflectance: HOUSING.reflectance, emitter: true });
  s.emitterMaterials.push(material);
  const side = part.side ?? -1;
  const area = side === 1 ? (model.emitterAreaUp ?? model.emitterArea) : model.emitterArea;
  const emitter: Emitter = { material, photometry: m.light ? emitterPhotometry(m.light.photometry, m.orientation) : null, side, area, centre: partCentre(part), weight: [0, 0, 0], luminance: 0 };
  mesh.material = material;
  mesh.onBeforeRender = (_renderer, _scene, camera) => glowToward(emitter, mesh, camera);
  return emitter;
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
  const model = moduleModel(m);
  const entry: ModuleEntry = { meshes: [], all: [], emitters: [] };
  const frames = new Map<PartFrame, THREE.Group>();
  for (const part of model.parts) {
    const frame = frameGroup(s, frames, part.frame, m, model);
    const mesh = new THREE.Mesh(partGeometry(part), part.role === 'cable' ? s.cable : s.housing);
    mesh.name = `module:${m.id}`;
    frame.add(mesh);
    entry.all.push(mesh);
    if (part.role === 'emitter') entry.emitters.push(emitterOf(s, m, model, part, mesh));
    else {
      mesh.userData.material = mesh.material;
      entry.meshes.push(mesh);
    }
  }
  setEmitterWeight(entry.emitters, m.on && m.light ? m.light.weight : [0, 0, 0]);
  s.modules.set(m.id, entry);
}
