/**
 * What the 3D view draws of a luminaire: meshes by material role, each in one of the luminaire's
 * frames, and the area of its light-emitting surface (docs/viewer.md, "Luminaires"). The view's own
 * models are generated in code (buildLuminaireModel.ts); an import of real luminaire geometry
 * (GLDF's L3D: geometry parts, joint axes, light-emitting objects) fills the same interface: its
 * parts under the joint that turns with the aim go to frame 'aim', those under the vertical
 * swivel to 'swivel', the rest to 'mount', and its light-emitting objects become 'emitter' parts.
 */

/** How a part is shaded: the matte dark housing, a steel wire, or the light-emitting surface. */
export type PartRole = 'housing' | 'cable' | 'emitter';

/**
 * The frame a part's vertices are given in. All three have their origin at the photometric centre
 * (metres; y up):
 * - 'mount': fixed to the rail: world = T(centre) · Ry(heading);
 * - 'swivel': turns about the vertical with the aim: world = T(centre) · Ry(yaw);
 * - 'aim': the optic, local −y its axis: world = T(centre) · Ry(yaw) · T(pivot) · Rx(pitch) · Ry(roll) · T(−pivot),
 *   with yaw, pitch, roll the lighting scene's (docs/scene-format.md) and `pivot` the model's.
 */
export type PartFrame = 'mount' | 'swivel' | 'aim';

export interface LuminairePart {
  role: PartRole;
  frame: PartFrame;
  /** For an emitter: which hemisphere of the photometry it emits (−1 the lower, local −y; +1 the upper). */
  side?: -1 | 1;
  /** xyz per vertex, metres. */
  positions: Float32Array;
  /** Unit normal per vertex. */
  normals: Float32Array;
  /** Triangles, counterclockwise seen from outside. */
  indices: Uint32Array;
}

export interface LuminaireModel {
  parts: LuminairePart[];
  /** Point the 'aim' frame turns about, in the 'swivel' frame (metres); [0, 0, 0]: the photometric centre. */
  pivot: [number, number, number];
  /**
   * Area of the light-emitting surface facing each hemisphere it emits (m²): the luminous opening of
   * the photometry (LM-63 / EULUMDAT luminous area), or the drawn face when the file gives a point.
   */
  emitterArea: number;
  /** Area of the surface emitting the upper hemisphere where it differs (an L3D body's objects facing up); absent: `emitterArea`. */
  emitterAreaUp?: number;
}

/** Number of triangles of a model. */
export function triangleCount(model: LuminaireModel): number {
  return model.parts.reduce((n, p) => n + p.indices.length / 3, 0);
}

/** Sum of the triangle areas of the parts with a role (m²). */
export function partArea(model: LuminaireModel, role: PartRole, side?: -1 | 1): number {
  let area = 0;
  for (const p of model.parts) {
    if (p.role !== role || (side !== undefined && p.side !== side)) continue;
    const v = p.positions;
    for (let t = 0; t < p.indices.length; t += 3) {
      const [a, b, c] = [p.indices[t] * 3, p.indices[t + 1] * 3, p.indices[t + 2] * 3];
      const u = [v[b] - v[a], v[b + 1] - v[a + 1], v[b + 2] - v[a + 2]];
      const w = [v[c] - v[a], v[c + 1] - v[a + 1], v[c + 2] - v[a + 2]];
      area += Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 2;
    }
  }
  return area;
}
