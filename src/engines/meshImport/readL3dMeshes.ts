/**
 * The OBJ parts of an L3D luminaire (readL3dStructure) as triangle meshes in luxbox's frame
 * (docs/gldf.md, "L3D geometry"). Each GeometryFileDefinition's OBJ goes through the project's OBJ
 * importer (importObjMesh: line checks, the triangle budget, orientation, the stored size), in the
 * L3D's declared units; each Geometry part that references it is then placed by the positions and
 * rotations of the parts and joints above it (joints at rest: every joint angle 0), and turned from
 * L3D's Z-up frame into luxbox's y-up one.
 *
 * Frames: the L3D examples (globallightingdata/l3d, example_000: a 0.1 m high cube standing on
 * z = 0 with its light-emitting object on the bottom face) are Z up; luxbox's object frame is y up
 * (core/mesh/triangleMesh.ts). Both right-handed, so L3D (x, y, z) → luxbox (x, z, −y), a proper
 * rotation (determinant +1): triangles keep their winding.
 *
 * Rotations: "Rotation of the current part around the local axes. The rotation order is fixed to
 * ZXY" (L3D XML reference, Rotation). Read literally (about the part's own axes, Z first, then the
 * turned X, then the twice-turned Y), the part's rotation matrix is Rz·Rx·Ry.
 */
import { InputError } from '../../core/inputError';
import { GldfError, quoteName } from '../../core/gldf/GldfError';
import { type L3dGeometryNode, type L3dLuminaire, type Vec3 } from '../../core/gldf/readL3dStructure';
import type { UploadZip } from '../../core/gldf/readUploadZip';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { importObjMesh } from './importObjMesh';
import type { ImportedMesh } from './importedMesh';
import { METRES_PER_UNIT, type MeshUnit } from './meshUnits';
import { formatCount, MAX_IMPORT_TRIANGLES } from './triangleBudget';

export interface L3dPartMesh {
  partName: string;
  /** The container entry of its OBJ (`<geometry id>/<file>`). */
  entry: string;
  /** Metres, y up, in the luminaire's frame (the L3D insert point at the origin), joints at rest. */
  mesh: TriangleMesh;
  /** Triangles of the OBJ (what the budget counts). */
  triangleCount: number;
  /** The joints above the part, outermost first: what moves it when the head is aimed. */
  joints: string[];
}

export interface L3dMeshes {
  parts: L3dPartMesh[];
  /** The OBJ importer's warnings, each naming the container and entry. */
  warnings: string[];
}

/** A 3×4 affine transform, row-major: [r00 r01 r02 tx; r10 r11 r12 ty; r20 r21 r22 tz]. */
export type Affine = number[];

export const IDENTITY: Affine = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0];

export function multiply(a: Affine, b: Affine): Affine {
  const out = new Array<number>(12);
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 4; c++) {
      let s = c === 3 ? a[r * 4 + 3] : 0;
      for (let k = 0; k < 3; k++) s += a[r * 4 + k] * b[k * 4 + c];
      out[r * 4 + c] = s;
    }
  }
  return out;
}

function rotation(axis: 0 | 1 | 2, degrees: number): Affine {
  const t = (degrees * Math.PI) / 180;
  // Exact quarter turns keep exact zeros (sin 90° is 1, cos 90° is 6e-17 in floating point).
  const c = Number.isInteger(degrees / 90) ? Math.round(Math.cos(t)) : Math.cos(t);
  const s = Number.isInteger(degrees / 90) ? Math.round(Math.sin(t)) : Math.sin(t);
  if (axis === 0) return [1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0];
  if (axis === 1) return [c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0];
  return [c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0];
}

/** A part's transform relative to its parent: translate by its Position, then rotate by Rz·Rx·Ry (see above). */
export function l3dLocalTransform(position: Vec3, rotationDegrees: Vec3): Affine {
  const [x, y, z] = rotationDegrees;
  const r = multiply(multiply(rotation(2, z), rotation(0, x)), rotation(1, y));
  return [r[0], r[1], r[2], position[0], r[4], r[5], r[6], position[1], r[8], r[9], r[10], position[2]];
}

/** L3D's Z-up frame into luxbox's y-up one: (x, y, z) → (x, z, −y). */
export const Z_UP_TO_Y_UP: Affine = [1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0];

/** The project's mesh unit for an L3D unit, when it has one; otherwise metres, scaled afterwards. */
function meshUnitFor(metresPerUnit: number): MeshUnit | null {
  return (Object.keys(METRES_PER_UNIT) as MeshUnit[]).find((u) => METRES_PER_UNIT[u] === metresPerUnit) ?? null;
}

export function readL3dMeshes(luminaire: L3dLuminaire, zip: UploadZip): L3dMeshes {
  const warnings: string[] = [];
  const imported = new Map<string, { mesh: ImportedMesh; rescale: number }>();
  const load = (geometryId: string): { mesh: ImportedMesh; rescale: number; entry: string } => {
    const file = luminaire.geometryFiles.get(geometryId);
    // readL3dStructure resolved every geometryId; this is the guard for a tree built otherwise.
    if (!file) throw new GldfError(`${luminaire.source}: geometryId ${quoteName(geometryId)} names no GeometryFileDefinition`);
    const done = imported.get(file.id);
    if (done) return { ...done, entry: file.path };
    const where = `${luminaire.source}: entry ${quoteName(file.path)}`;
    const unit = meshUnitFor(file.scale);
    const folder = file.path.slice(0, file.path.lastIndexOf('/') + 1);
    let mesh: ImportedMesh;
    try {
      mesh = importObjMesh([{ name: file.path.slice(folder.length), bytes: zip.read(file.path) }], {
        // dm, foot and yard have no mesh unit: read as metres, then scaled (the 0.5 mm back-side offset shrinks with them).
        units: unit ?? 'm',
        readFile: (name) => zip.read(`${folder}${name}`),
      });
    } catch (error) {
      if (error instanceof GldfError) throw error;
      if (error instanceof InputError) throw new GldfError(`${where}: ${error.message}`);
      throw error;
    }
    // The L3D declares the unit, and a luminaire's part may well be smaller than the 5 cm the furniture check expects: its size warning is not kept.
    for (const w of mesh.warnings) if (!/ m across in \w+ — check the units$/.test(w)) warnings.push(`${where}: ${w}`);
    const entry = { mesh, rescale: unit ? 1 : file.scale };
    imported.set(file.id, entry);
    return { ...entry, entry: file.path };
  };

  const parts: L3dPartMesh[] = [];
  const visit = (nodes: readonly L3dGeometryNode[], parent: Affine, joints: string[]): void => {
    for (const node of nodes) {
      const frame = multiply(parent, l3dLocalTransform(node.position, node.rotation));
      const { mesh, rescale, entry } = load(node.geometryId);
      const toLuxbox = multiply(Z_UP_TO_Y_UP, multiply(frame, [rescale, 0, 0, 0, 0, rescale, 0, 0, 0, 0, rescale, 0]));
      parts.push({ partName: node.partName, entry, mesh: transformMesh(mesh.mesh, toLuxbox), triangleCount: mesh.triangleCount, joints });
      for (const joint of node.joints) {
        visit(joint.geometries, multiply(frame, l3dLocalTransform(joint.position, joint.rotation)), [...joints, joint.partName]);
      }
    }
  };
  visit(luminaire.structure, IDENTITY, []);
  // One luminaire is one model: its parts together stay within the budget too.
  const total = parts.reduce((s, p) => s + p.triangleCount, 0);
  if (total > MAX_IMPORT_TRIANGLES) {
    throw new GldfError(`${luminaire.source}: its ${parts.length} parts have ${formatCount(total)} triangles together; the limit is ${formatCount(MAX_IMPORT_TRIANGLES)} — simplify the model and import again`);
  }
  return { parts, warnings };
}

function transformMesh(mesh: TriangleMesh, m: Affine): TriangleMesh {
  const p = mesh.positions;
  const out = new Float32Array(p.length);
  for (let i = 0; i < p.length; i += 3) {
    const x = p[i];
    const y = p[i + 1];
    const z = p[i + 2];
    out[i] = m[0] * x + m[1] * y + m[2] * z + m[3];
    out[i + 1] = m[4] * x + m[5] * y + m[6] * z + m[7];
    out[i + 2] = m[8] * x + m[9] * y + m[10] * z + m[11];
  }
  return { ...mesh, positions: out };
}
