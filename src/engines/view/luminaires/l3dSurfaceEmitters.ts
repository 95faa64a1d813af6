/**
 * An L3D's LightEmittingSurfaces (readL3dEmittingFaces) as glowing faces of the body (docs/gldf.md
 * "Light-emitting surfaces"): each triangle is drawn 0.5 mm proud of its face along its normal (as
 * the objects' Rectangles and Circles are), on the side its normal faces in the reference pose
 * (aimed straight down: up-facing triangles emit the upper hemisphere).
 */
import type { Affine } from '../../meshImport/readL3dMeshes';
import type { Vec3 } from '../../../core/gldf/readL3dStructure';
import { PROUD } from './luminaireDimensions';
import type { LuminairePart } from './luminaireModel';

const apply = (m: Affine, p: readonly number[]): number[] => [0, 1, 2].map((r) => m[r * 4] * p[0] + m[r * 4 + 1] * p[1] + m[r * 4 + 2] * p[2] + m[r * 4 + 3]);

function normalOf(a: number[], b: number[], c: number[]): number[] {
  const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
  const len = Math.hypot(n[0], n[1], n[2]);
  return len > 0 ? n.map((v) => v / len) : [0, -1, 0];
}

function triangles(positions: Float32Array, m: Affine): number[][][] {
  const out: number[][][] = [];
  for (let i = 0; i + 8 < positions.length; i += 9) out.push([0, 3, 6].map((k) => apply(m, [positions[i + k], positions[i + k + 1], positions[i + k + 2]])));
  return out;
}

/** Which hemisphere each triangle emits (by its normal in the reference pose, `reference` moving the rest positions there). */
export function triangleSides(positions: Float32Array, reference: Affine): (-1 | 1)[] {
  return triangles(positions, reference).map(([a, b, c]) => (normalOf(a, b, c)[1] > 0 ? 1 : -1));
}

/** Area (m²) of the triangles facing down and up in the reference pose. */
export function surfaceAreaBySide(positions: Float32Array, reference: Affine): { down: number; up: number } {
  const out = { down: 0, up: 0 };
  for (const [a, b, c] of triangles(positions, reference)) {
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const area = Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 2;
    if (normalOf(a, b, c)[1] > 0) out.up += area;
    else out.down += area;
  }
  return out;
}

/** The emitter parts of a surface: its triangles moved by `posed` less `origin`, 0.5 mm proud, one part per side that has any. */
export function surfaceEmitterParts(positions: Float32Array, posed: Affine, reference: Affine, origin: Vec3): LuminairePart[] {
  const sides = triangleSides(positions, reference);
  const parts: LuminairePart[] = [];
  for (const side of [-1, 1] as const) {
    const verts: number[] = [];
    const normals: number[] = [];
    triangles(positions, posed).forEach((tri, t) => {
      if (sides[t] !== side) return;
      const n = normalOf(tri[0], tri[1], tri[2]);
      for (const v of tri) {
        verts.push(v[0] + PROUD * n[0] - origin[0], v[1] + PROUD * n[1] - origin[1], v[2] + PROUD * n[2] - origin[2]);
        normals.push(...n);
      }
    });
    if (verts.length === 0) continue;
    parts.push({ role: 'emitter', frame: 'mount', side, positions: Float32Array.from(verts), normals: Float32Array.from(normals), indices: Uint32Array.from({ length: verts.length / 3 }, (_, i) => i) });
  }
  return parts;
}
