import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Mat3 } from './luminaireRotation';

/** A GLSL float literal with float32-sufficient precision (9 significant digits). */
export function glslFloat(x: number): string {
  if (!Number.isFinite(x)) throw new Error(`non-finite shader constant ${x}`);
  if (Number.isInteger(x) && Math.abs(x) < 1e9) return x.toFixed(1);
  const s = x.toPrecision(9);
  return s.includes('.') || s.includes('e') ? s : `${s}.0`;
}

export function glslVec3(v: Vec3 | readonly number[]): string {
  return `vec3(${glslFloat(v[0])}, ${glslFloat(v[1])}, ${glslFloat(v[2])})`;
}

/**
 * A row-major matrix M given to GLSL's column-major mat3 constructor yields
 * Mᵀ: used on purpose to get the world → local rotation (the inverse of a
 * rotation is its transpose).
 */
export function glslMat3Transposed(m: Mat3): string {
  return `mat3(${m.map(glslFloat).join(', ')})`;
}
