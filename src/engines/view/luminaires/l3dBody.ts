/**
 * A luminaire's real body from its L3D geometry (docs/gldf.md "L3D in the 3D view", docs/viewer.md
 * "Luminaires"): the OBJ parts (readL3dMeshes: metres, y up, joints at rest) posed by the joints
 * so the light-emitting object faces along the module's aim, placed so that object's centre is
 * the photometric centre, with the light-emitting objects drawn as the glowing faces.
 *
 * - **Photometric centre.** The first light-emitting object (depth first) that faces down with the
 *   joints at rest (else the first) is the one the photometry's axis belongs to: its centre, in the
 *   reference pose (aimed straight down), is the model's origin, where the baker puts the light.
 * - **Joints drive the aim.** The axes of the joints above that object (outermost first, at most
 *   two: a swivel and a tilt) are its degrees of freedom. For an aim they take the angles, within
 *   each axis's min–max, that turn the object's normal (its local −z, as the bottom face of the L3D
 *   example_000) closest to the beam's axis; where several do (straight down: any swivel), the
 *   swivel nearest the module's yaw, so the yoke turns as the generic spot's does. Past a joint's
 *   limit the head stops at it (the beam is the catalog's: the import takes the limits from the
 *   joints, so both agree).
 * - **DefaultRotation** is the pose of every joint axis the aim does not drive (a third axis, a
 *   joint beside the emitter's chain, a joint without axes); a driven axis takes the aim's angle.
 * - **Emitters.** Each light-emitting object is drawn as its Rectangle or Circle (a 48-gon of the
 *   circle's area), 0.5 mm proud of its plane along its normal; one facing up in the reference pose
 *   emits the upper hemisphere. Its area is the emitting area the glow divides the intensity toward
 *   the eye by (L = I/(A·cos θ), viewLuminance.ts). The LightEmittingSurfaces' OBJ faces are not drawn glowing:
 *   the objects are what the L3D declares as the luminous opening.
 */
import { GldfError } from '../../../core/gldf/GldfError';
import type { L3dGeometryNode, L3dJoint, L3dLightEmittingObject, L3dLuminaire, Vec3 } from '../../../core/gldf/readL3dStructure';
import { l3dLocalTransform, multiply, Z_UP_TO_Y_UP, type Affine, type L3dPartMesh } from '../../meshImport/readL3dMeshes';
import type { L3dEmittingSurfaceMesh } from '../../meshImport/readL3dEmittingFaces';
import { emitterRadius, PROUD } from './luminaireDimensions';
import { surfaceAreaBySide, surfaceEmitterParts } from './l3dSurfaceEmitters';
import type { LuminairePart } from './luminaireModel';

/** One aiming degree of freedom: a joint's axis with its limits (degrees). */
export interface L3dDof {
  joint: string;
  axis: 'x' | 'y' | 'z';
  min: number;
  max: number;
  /** Turns about the vertical in the reference pose: the swivel the module's yaw follows. */
  vertical: boolean;
}

/** Angles per joint (degrees about its local x, y, z). */
export type JointAngles = ReadonlyMap<string, Vec3>;

export interface L3dBody {
  luminaire: L3dLuminaire;
  /** Each part at rest (every joint at 0), as readL3dMeshes gives it. */
  parts: readonly L3dPartMesh[];
  dofs: readonly L3dDof[];
  /** The light-emitting object the photometry belongs to. */
  primary: string;
  /** That object (its shape is the near field's luminous opening, l3dOpening.ts). */
  primaryObject: L3dLightEmittingObject;
  /** That object's local x (its Rectangle's sizeX side) in the reference pose, luxbox frame of the body: which way the opening lies. */
  primaryAxisX: Vec3;
  /** Joint angles aiming straight down with the swivel at 0. */
  reference: JointAngles;
  /** The primary object's centre in the reference pose, in the rest meshes' frame: subtracted from every vertex. */
  origin: Vec3;
  /** The LightEmittingSurfaces' faces at rest (readL3dEmittingFaces): drawn glowing instead of the objects they belong to. */
  surfaces: readonly L3dEmittingSurfaceMesh[];
  /** The primary object's surfaces' vertices in the reference pose, less the origin (x y z each), or null when it has none: its opening (l3dOpening). */
  primarySurfacePoints: Float32Array | null;
  /** Emitting area facing down and up in the reference pose (m²). */
  emitterArea: { down: number; up: number };
  /** Height of the body's top above the photometric centre in the reference pose (m). */
  top: number;
}

const DEG = Math.PI / 180;
const AXIS_INDEX = { x: 0, y: 1, z: 2 } as const;
const CIRCLE_SEGMENTS = 48;

/** The frames (L3D, Z up, metres) of every geometry part, joint (turned by its angles) and light-emitting object for given joint angles. */
function frames(luminaire: L3dLuminaire, angles: JointAngles): Map<string, Affine> {
  const out = new Map<string, Affine>();
  const visit = (nodes: readonly L3dGeometryNode[], parent: Affine): void => {
    for (const node of nodes) {
      const frame = multiply(parent, l3dLocalTransform(node.position, node.rotation));
      out.set(node.partName, frame);
      for (const o of node.lightEmittingObjects) out.set(o.partName, multiply(frame, l3dLocalTransform(o.position, o.rotation)));
      for (const j of node.joints) {
        const joint = multiply(multiply(frame, l3dLocalTransform(j.position, j.rotation)), l3dLocalTransform([0, 0, 0], angles.get(j.partName) ?? [0, 0, 0]));
        out.set(j.partName, joint);
        visit(j.geometries, joint);
      }
    }
  };
  visit(luminaire.structure, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]);
  return out;
}

const apply = (m: Affine, p: readonly number[]): Vec3 => [0, 1, 2].map((r) => m[r * 4] * p[0] + m[r * 4 + 1] * p[1] + m[r * 4 + 2] * p[2] + m[r * 4 + 3]) as Vec3;
const turn = (m: Affine, v: readonly number[]): Vec3 => [0, 1, 2].map((r) => m[r * 4] * v[0] + m[r * 4 + 1] * v[1] + m[r * 4 + 2] * v[2]) as Vec3;

/** The inverse of a rigid transform (rotation and translation): [Rᵀ | −Rᵀ t]. */
function invertRigid(m: Affine): Affine {
  const r = [m[0], m[4], m[8], m[1], m[5], m[9], m[2], m[6], m[10]];
  const t = [m[3], m[7], m[11]];
  return [r[0], r[1], r[2], -(r[0] * t[0] + r[1] * t[1] + r[2] * t[2]), r[3], r[4], r[5], -(r[3] * t[0] + r[4] * t[1] + r[5] * t[2]), r[6], r[7], r[8], -(r[6] * t[0] + r[7] * t[1] + r[8] * t[2])];
}

interface Leo {
  object: L3dLightEmittingObject;
  /** Joints above it, outermost first. */
  chain: L3dJoint[];
}

function lightEmittingObjects(luminaire: L3dLuminaire): Leo[] {
  const out: Leo[] = [];
  const visit = (nodes: readonly L3dGeometryNode[], chain: L3dJoint[]): void => {
    for (const node of nodes) {
      for (const object of node.lightEmittingObjects) out.push({ object, chain });
      for (const j of node.joints) visit(j.geometries, [...chain, j]);
    }
  };
  visit(luminaire.structure, []);
  return out;
}

function defaults(luminaire: L3dLuminaire): Map<string, Vec3> {
  const out = new Map<string, Vec3>();
  const visit = (nodes: readonly L3dGeometryNode[]): void => {
    for (const node of nodes) {
      for (const j of node.joints) {
        out.set(j.partName, j.defaultRotation ? [...j.defaultRotation] : [0, 0, 0]);
        visit(j.geometries);
      }
    }
  };
  visit(luminaire.structure);
  return out;
}

/** Where a light-emitting object is and which way it faces (luxbox frame, before the origin is subtracted). */
function leoPose(f: Map<string, Affine>, name: string): { centre: Vec3; normal: Vec3; frame: Affine } {
  const frame = multiply(Z_UP_TO_Y_UP, f.get(name)!);
  return { centre: apply(frame, [0, 0, 0]), normal: turn(frame, [0, 0, -1]), frame };
}

function withAngles(base: JointAngles, dofs: readonly L3dDof[], values: readonly number[]): Map<string, Vec3> {
  const out = new Map<string, Vec3>([...base].map(([k, v]) => [k, [...v] as Vec3]));
  dofs.forEach((d, i) => {
    const a = out.get(d.joint) ?? [0, 0, 0];
    a[AXIS_INDEX[d.axis]] = values[i];
    out.set(d.joint, a);
  });
  return out;
}

/** Circular distance of two angles in degrees. */
function circular(a: number, b: number): number {
  const d = Math.abs(((((a - b) % 360) + 540) % 360) - 180);
  return d;
}

/**
 * The joint angles that turn the primary light-emitting object's normal closest to `direction`
 * (luxbox frame of the body, unit), each within its axis's limits; among equals, the vertical
 * swivel nearest `swivel` degrees. A grid over the limits (≤ 5° apart) then a pattern search
 * halving its step down to 10⁻⁵°.
 */
export function aimJoints(body: Pick<L3dBody, 'luminaire' | 'dofs' | 'primary'>, direction: Vec3, swivel = 0): Map<string, Vec3> {
  const base = defaults(body.luminaire);
  const dofs = body.dofs;
  if (dofs.length === 0) return base;
  const cost = (values: number[]): number => {
    const n = leoPose(frames(body.luminaire, withAngles(base, dofs, values)), body.primary).normal;
    const dot = Math.max(-1, Math.min(1, n[0] * direction[0] + n[1] * direction[1] + n[2] * direction[2]));
    // The swivel's pull is far below the error's slope at any visible tilt (sin t · π/180 per degree).
    const pull = dofs.reduce((s, d, i) => s + (d.vertical ? circular(values[i], swivel) : 0), 0);
    return Math.acos(dot) + 1e-7 * pull;
  };
  const samples = dofs.map((d) => {
    const n = Math.max(1, Math.ceil((d.max - d.min) / 5));
    const s = Array.from({ length: n + 1 }, (_, i) => d.min + ((d.max - d.min) * i) / n);
    if (d.vertical) s.push(Math.min(d.max, Math.max(d.min, ((((swivel - d.min) % 360) + 360) % 360) + d.min)));
    return s;
  });
  let best: number[] = dofs.map((d) => d.min);
  let bestCost = Infinity;
  const grid = (i: number, values: number[]): void => {
    if (i === dofs.length) {
      const c = cost(values);
      if (c < bestCost) [best, bestCost] = [[...values], c];
      return;
    }
    for (const v of samples[i]) grid(i + 1, [...values, v]);
  };
  grid(0, []);
  for (let step = 2.5; step > 1e-5;) {
    let improved = false;
    for (let i = 0; i < dofs.length; i++) {
      for (const s of [step, -step]) {
        const trial = [...best];
        trial[i] = Math.min(dofs[i].max, Math.max(dofs[i].min, trial[i] + s));
        const c = cost(trial);
        if (c < bestCost) {
          [best, bestCost, improved] = [trial, c, true];
        }
      }
    }
    if (!improved) step /= 2;
  }
  return withAngles(base, dofs, best);
}

/**
 * The light-emitting object the photometry belongs to: the one named `emitter` (a GLDF
 * EmitterObjectExternalName, catalog `modelEmitter`), else the first facing down at rest, else the first.
 */
function primaryObject(luminaire: L3dLuminaire, leos: Leo[], rest: Map<string, Affine>, emitter: string | undefined): Leo {
  if (emitter !== undefined) {
    const named = leos.find((l) => l.object.partName === emitter);
    if (!named) throw new GldfError(`${luminaire.source}: no LightEmittingObject '${emitter}' (it has ${leos.map((l) => `'${l.object.partName}'`).join(', ')})`);
    return named;
  }
  return leos.find((l) => leoPose(rest, l.object.partName).normal[1] < 0) ?? leos[0];
}

/**
 * Prepares an L3D luminaire's parts (readL3dMeshes) for drawing: its degrees of freedom, reference
 * pose, origin, emitting areas and height. `emitter` names the light-emitting object the
 * photometry belongs to (catalog `modelEmitter`); absent: the first facing down. `surfaces`
 * (readL3dEmittingFaces) glow instead of the objects they belong to, and their area is those
 * objects' emitting area.
 */
export function l3dBody(luminaire: L3dLuminaire, parts: readonly L3dPartMesh[], emitter?: string, surfaces: readonly L3dEmittingSurfaceMesh[] = []): L3dBody {
  const leos = lightEmittingObjects(luminaire);
  if (leos.length === 0) throw new GldfError(`${luminaire.source}: no LightEmittingObject: the photometric centre is unknown`);
  const rest = frames(luminaire, new Map());
  const primary = primaryObject(luminaire, leos, rest, emitter);
  const candidates: L3dDof[] = primary.chain.flatMap((j) => j.axes.map((a) => ({ joint: j.partName, axis: a.axis, min: a.min, max: a.max, vertical: false })));
  const dofs = candidates.slice(0, 2).map((d) => {
    // The axis in the luxbox frame at rest: vertical when within about 8° of y.
    const axis = turn(multiply(Z_UP_TO_Y_UP, rest.get(d.joint)!), [d.axis === 'x' ? 1 : 0, d.axis === 'y' ? 1 : 0, d.axis === 'z' ? 1 : 0]);
    return { ...d, vertical: Math.abs(axis[1]) > 0.99 };
  });
  const partial = { luminaire, dofs, primary: primary.object.partName };
  const reference = aimJoints(partial, [0, -1, 0], 0);
  const f = frames(luminaire, reference);
  const primaryPose = leoPose(f, primary.object.partName);
  const origin = primaryPose.centre;
  const primaryAxisX = turn(primaryPose.frame, [1, 0, 0]);
  const emitterArea = { down: 0, up: 0 };
  const fromRest = (part: string): Affine => restToPosed(rest, f, part);
  for (const s of surfaces) {
    const a = surfaceAreaBySide(s.positions, fromRest(s.part));
    emitterArea.down += a.down;
    emitterArea.up += a.up;
  }
  const primarySurfaces = surfaces.filter((s) => s.objects.includes(primary.object.partName));
  const primarySurfacePoints = primarySurfaces.length ? Float32Array.from(primarySurfaces.flatMap((s) => movedPoints(s.positions, fromRest(s.part), origin))) : null;
  for (const { object } of leos) {
    if (surfaces.some((s) => s.objects.includes(object.partName))) continue;
    const area = object.shape.kind === 'rectangle' ? object.shape.sizeX * object.shape.sizeY : (Math.PI * object.shape.diameter ** 2) / 4;
    if (leoPose(f, object.partName).normal[1] > 0) emitterArea.up += area;
    else emitterArea.down += area;
  }
  const body: L3dBody = { luminaire, parts, dofs, primary: primary.object.partName, primaryObject: primary.object, primaryAxisX, reference, origin, surfaces, primarySurfacePoints, emitterArea, top: 0 };
  let top = 0;
  for (const p of poseL3dBody(body, reference).parts) for (let i = 1; i < p.positions.length; i += 3) top = Math.max(top, p.positions[i]);
  return { ...body, top };
}

/** A part's rest mesh (luxbox frame) → L3D at rest → the part's own frame → posed by `posed` → back to luxbox. */
function restToPosed(rest: Map<string, Affine>, posed: Map<string, Affine>, part: string): Affine {
  return multiply(Z_UP_TO_Y_UP, multiply(posed.get(part)!, multiply(invertRigid(rest.get(part)!), invertRigid(Z_UP_TO_Y_UP))));
}

/** Points (x y z each) moved by `m`, less `origin`. */
function movedPoints(positions: Float32Array, m: Affine, origin: Vec3): number[] {
  const out: number[] = [];
  for (let i = 0; i + 2 < positions.length; i += 3) out.push(...apply(m, [positions[i], positions[i + 1], positions[i + 2]]).map((c, k) => c - origin[k]));
  return out;
}

/** The body's parts for given joint angles: housings and emitters in the model's frame (origin at the photometric centre). */
function posedParts(body: L3dBody, angles: JointAngles): LuminairePart[] {
  const restFrames = frames(body.luminaire, new Map());
  const posed = frames(body.luminaire, angles);
  const [ox, oy, oz] = body.origin;
  const parts: LuminairePart[] = [];
  for (const p of body.parts) parts.push(flatPart(p.mesh.positions, p.mesh.indices, restToPosed(restFrames, posed, p.partName), [ox, oy, oz]));
  const reference = frames(body.luminaire, body.reference);
  for (const { object } of lightEmittingObjects(body.luminaire)) {
    // An object with LightEmittingSurfaces glows as those faces (below), not as its Rectangle or Circle.
    if (body.surfaces.some((s) => s.objects.includes(object.partName))) continue;
    const side: -1 | 1 = leoPose(reference, object.partName).normal[1] > 0 ? 1 : -1;
    parts.push(emitterFace(object, leoPose(posed, object.partName).frame, [ox, oy, oz], side));
  }
  for (const s of body.surfaces) parts.push(...surfaceEmitterParts(s.positions, restToPosed(restFrames, posed, s.part), restToPosed(restFrames, reference, s.part), [ox, oy, oz]));
  return parts;
}

/** A part with one normal per triangle (the OBJ's facets), its vertices moved by `m` less `origin`. */
function flatPart(positions: Float32Array, indices: Uint32Array, m: Affine, origin: Vec3): LuminairePart {
  const n = indices.length;
  const out = new Float32Array(n * 3);
  const normals = new Float32Array(n * 3);
  for (let t = 0; t < n; t += 3) {
    const v = [0, 1, 2].map((k) => {
      const i = indices[t + k] * 3;
      const p = apply(m, [positions[i], positions[i + 1], positions[i + 2]]);
      return [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]];
    });
    const u = [v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]];
    const w = [v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]];
    const c = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const len = Math.hypot(c[0], c[1], c[2]) || 1;
    for (let k = 0; k < 3; k++) {
      out.set(v[k], (t + k) * 3);
      normals.set([c[0] / len, c[1] / len, c[2] / len], (t + k) * 3);
    }
  }
  return { role: 'housing', frame: 'mount', positions: out, normals, indices: Uint32Array.from({ length: n }, (_, i) => i) };
}

/** A light-emitting object's Rectangle or Circle (a 48-gon of equal area), 0.5 mm proud along its normal (local −z), counterclockwise seen from that side. */
function emitterFace(object: L3dLightEmittingObject, frame: Affine, origin: Vec3, side: -1 | 1): LuminairePart {
  const ring: [number, number][] =
    object.shape.kind === 'rectangle'
      ? [
          [-object.shape.sizeX / 2, -object.shape.sizeY / 2],
          [object.shape.sizeX / 2, -object.shape.sizeY / 2],
          [object.shape.sizeX / 2, object.shape.sizeY / 2],
          [-object.shape.sizeX / 2, object.shape.sizeY / 2],
        ]
      : Array.from({ length: CIRCLE_SEGMENTS }, (_, i) => {
          const r = emitterRadius(object.shape.kind === 'circle' ? object.shape.diameter : 0, CIRCLE_SEGMENTS);
          const a = (2 * Math.PI * i) / CIRCLE_SEGMENTS;
          return [r * Math.cos(a), r * Math.sin(a)];
        });
  const local = [[0, 0], ...ring].map(([x, y]) => apply(frame, [x, y, -PROUD]).map((c, k) => c - origin[k]));
  const normal = turn(frame, [0, 0, -1]);
  const indices: number[] = [];
  // The ring runs counterclockwise seen from +z; seen from −z (the emitting side) the reverse order is counterclockwise.
  for (let i = 1; i <= ring.length; i++) indices.push(0, i === ring.length ? 1 : i + 1, i);
  return {
    role: 'emitter',
    frame: 'mount',
    side,
    positions: Float32Array.from(local.flat()),
    normals: Float32Array.from(local.flatMap(() => normal)),
    indices: Uint32Array.from(indices),
  };
}

/** What a placed module tells the pose: its aim (the lighting scene's orientation) and heading, degrees, and the rail above it. */
export interface BodyPlacement {
  heading: number;
  orientation: { yaw: number; pitch: number; roll: number };
  /** Height of the rail's underside above the photometric centre (m); 0: no rail. */
  mount: number;
}

/** The beam's axis in the module's mount frame (x along the rail): Ry(−heading)·Ry(yaw)·Rx(pitch)·(0, −1, 0). */
export function mountFrameAxis(p: Pick<BodyPlacement, 'heading' | 'orientation'>): Vec3 {
  const yaw = (p.orientation.yaw - p.heading) * DEG;
  const t = p.orientation.pitch * DEG;
  return [-Math.sin(yaw) * Math.sin(t), -Math.cos(t), -Math.cos(yaw) * Math.sin(t)];
}

/** The body's housings and emitters for given joint angles (no rail hardware). */
export function poseL3dBody(body: L3dBody, angles: JointAngles): { parts: LuminairePart[] } {
  return { parts: posedParts(body, angles) };
}
