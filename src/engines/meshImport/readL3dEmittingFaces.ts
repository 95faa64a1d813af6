/**
 * The faces an L3D marks as emitting (LightEmittingSurfaces, docs/gldf.md "Light-emitting
 * surfaces"): for each LightEmittingSurface of a Geometry part, the OBJ faces its FaceAssignments
 * and FaceRangeAssignments name, fan-triangulated, in metres, y up, in the luminaire's frame with the
 * joints at rest (exactly as readL3dMeshes places the part's mesh).
 *
 * Face numbering (the L3D schema gives the attributes no words): faceIndex counts the OBJ's `f`
 * statements from 0 in file order; with a groupIndex it counts within the groupIndex-th `g`
 * statement's faces (from 0). The OBJ goes through the importer's line checks first (scanObjText:
 * byte, vertex and triangle caps, indices in range), so only a face index past the file's faces is
 * new: refused in one line naming the container, the surface and the index.
 */
import { GldfError, quoteName } from '../../core/gldf/GldfError';
import type { L3dGeometryNode, L3dLightEmittingSurface, L3dLuminaire } from '../../core/gldf/readL3dStructure';
import type { UploadZip } from '../../core/gldf/readUploadZip';
import { InputError } from '../../core/inputError';
import { decodeText } from './decodeText';
import { IDENTITY, l3dLocalTransform, multiply, Z_UP_TO_Y_UP, type Affine } from './readL3dMeshes';
import { scanObjText } from './scanObjText';

export interface L3dEmittingSurfaceMesh {
  /** The LightEmittingSurface's partName. */
  surface: string;
  /** The Geometry part whose OBJ holds the faces (what moves them when the joints turn). */
  part: string;
  /** The light-emitting objects it belongs to. */
  objects: string[];
  /** Triangles, x y z per vertex (three vertices each, counterclockwise seen from the emitting side as in the OBJ), metres, luminaire frame at rest. */
  positions: Float32Array;
  /** Their total area (m²). */
  area: number;
}

interface ObjFaces {
  vertices: number[];
  /** Each `f` statement's 1-based vertex indices, in file order. */
  faces: number[][];
  /** The index of the `g` statement each face follows (−1: before any). */
  groups: number[];
}

function readFaces(bytes: Uint8Array, file: string): ObjFaces {
  const scanned = scanObjText(bytes, file);
  const vertices: number[] = [];
  const faces: number[][] = [];
  for (const line of scanned.text.split('\n')) {
    if (line.startsWith('v ')) vertices.push(...line.slice(2).split(' ').map(Number));
    else if (line.startsWith('f ')) faces.push(line.slice(2).split(' ').map(Number));
  }
  // The groups from the file itself (the scan drops `g`): its `f` and `g` statements in order.
  const groups: number[] = [];
  let group = -1;
  for (const raw of decodeText(bytes).split(/\r?\n/)) {
    const t = raw.trimStart();
    if (/^g(\s|$)/.test(t)) group++;
    else if (/^f\s/.test(t)) groups.push(group);
  }
  return { vertices, faces, groups: groups.length === faces.length ? groups : faces.map(() => -1) };
}

/** The faces a surface names, as indices into `obj.faces`. */
function assignedFaces(surface: L3dLightEmittingSurface, obj: ObjFaces, where: string): number[] {
  const out: number[] = [];
  for (const range of surface.faces) {
    const pool = range.groupIndex === undefined ? obj.faces.map((_, i) => i) : obj.groups.flatMap((g, i) => (g === range.groupIndex ? [i] : []));
    if (range.end < range.begin) throw new GldfError(`${where}: face range ${range.begin}–${range.end} runs backwards`);
    if (range.end >= pool.length) {
      const of = range.groupIndex === undefined ? '' : ` of group ${range.groupIndex}`;
      throw new GldfError(`${where}: face ${range.end}${of} does not exist (${pool.length} faces${of})`);
    }
    for (let f = range.begin; f <= range.end; f++) out.push(pool[f]);
  }
  return out;
}

function surfaceMesh(surface: L3dLightEmittingSurface, node: L3dGeometryNode, obj: ObjFaces, m: Affine, where: string): L3dEmittingSurfaceMesh {
  const positions: number[] = [];
  let area = 0;
  const vertex = (k: number): number[] => {
    const [x, y, z] = obj.vertices.slice((k - 1) * 3, k * 3);
    return [m[0] * x + m[1] * y + m[2] * z + m[3], m[4] * x + m[5] * y + m[6] * z + m[7], m[8] * x + m[9] * y + m[10] * z + m[11]];
  };
  for (const f of new Set(assignedFaces(surface, obj, where))) {
    const ring = obj.faces[f].map(vertex);
    for (let i = 1; i + 1 < ring.length; i++) {
      const [a, b, c] = [ring[0], ring[i], ring[i + 1]];
      positions.push(...a, ...b, ...c);
      const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      const w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
      area += Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 2;
    }
  }
  return { surface: surface.partName, part: node.partName, objects: surface.objects.map((o) => o.partName), positions: Float32Array.from(positions), area };
}

export function readL3dEmittingFaces(luminaire: L3dLuminaire, zip: UploadZip): L3dEmittingSurfaceMesh[] {
  const out: L3dEmittingSurfaceMesh[] = [];
  const objs = new Map<string, ObjFaces>();
  const visit = (nodes: readonly L3dGeometryNode[], parent: Affine): void => {
    for (const node of nodes) {
      const frame = multiply(parent, l3dLocalTransform(node.position, node.rotation));
      if (node.lightEmittingSurfaces.length) {
        const file = luminaire.geometryFiles.get(node.geometryId);
        if (!file) throw new GldfError(`${luminaire.source}: geometryId ${quoteName(node.geometryId)} names no GeometryFileDefinition`);
        let obj = objs.get(file.id);
        if (!obj) {
          try {
            obj = readFaces(zip.read(file.path), file.path);
          } catch (error) {
            if (error instanceof InputError) throw new GldfError(`${luminaire.source}: entry ${quoteName(file.path)}: ${error.message}`);
            throw error;
          }
          objs.set(file.id, obj);
        }
        // OBJ units → metres, the part's frame, then L3D's Z up into luxbox's y up (as readL3dMeshes).
        const m = multiply(Z_UP_TO_Y_UP, multiply(frame, [file.scale, 0, 0, 0, 0, file.scale, 0, 0, 0, 0, file.scale, 0]));
        for (const s of node.lightEmittingSurfaces) out.push(surfaceMesh(s, node, obj, m, `${luminaire.source}: LightEmittingSurface ${quoteName(s.partName)} (entry ${quoteName(file.path)})`));
      }
      for (const joint of node.joints) visit(joint.geometries, multiply(frame, l3dLocalTransform(joint.position, joint.rotation)));
    }
  };
  visit(luminaire.structure, IDENTITY);
  return out;
}
