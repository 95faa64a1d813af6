import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import { intensity } from '../../../core/photometry/intensity';
import { tiltMultiplier } from '../../../core/photometry/tilt';
import type { Photometry } from '../../../core/photometry/types';
import { applyMat3, luminaireRotation, photometricAngles, transpose, type Mat3 } from '../../bake/luminaireRotation';

/**
 * The steepest view of a face the luminance is resolved for: beyond 85° from its normal its
 * projected area is floored at A·cos 85° (8.7 % of the face). See `luminanceToward`.
 */
export const GRAZING_LIMIT_DEG = 85;
const COS_GRAZING = Math.cos((GRAZING_LIMIT_DEG * Math.PI) / 180);

/** What a glowing face needs to know of its module to find its luminance toward an eye. */
export interface EmitterPhotometry {
  photometry: Photometry;
  /** Luminaire → world rotation (the baker's: world = Ry(yaw)·Rx(pitch)·Ry(roll)·local). */
  rotation: Mat3;
  /** The TILT factor at the module's pitch (1 without TILT data), as the baker scales the grid. */
  tilt: number;
}

/** A module's photometry in its own frame, exactly as the baker orients and scales it (scenePointSources.ts). */
export function emitterPhotometry(photometry: Photometry, orientation: { yaw: number; pitch: number; roll: number }): EmitterPhotometry {
  return { photometry, rotation: luminaireRotation(orientation.yaw, orientation.pitch, orientation.roll), tilt: tiltMultiplier(photometry, orientation.pitch) };
}

/**
 * Luminance of a luminous face toward an eye (cd/m², at full power, before dimming and colour).
 * Luminance is intensity per unit projected area, L = dI / (dA · cos θ) (CIE S 017:2020, ILV
 * 17-21-050; DiLaura et al., *The Lighting Handbook*, 10th ed., IES 2011, ch. 2), θ the angle
 * between the face's normal and the direction of view. For the whole opening seen from afar this is
 *
 *   **L(γ, C) = I(γ, C) / (A · cos θ)**
 *
 * with I the module's measured intensity toward the eye (the baker's photometry, rotation and TILT
 * factor) and A the face's area. The face's normal is the photometric axis: the lower face
 * (side −1) looks along local −y, so cos θ = cos γ; the upper face (+1) along +y, cos θ = −cos γ.
 * A face seen from behind (cos θ ≤ 0) shows no light (it emits only into its hemisphere).
 *
 * **The grazing cap.** As θ → 90° the projected area goes to 0 while a measured I(90°) need not
 * (a diffuser's side light, a grid's coarse steps near the horizon), so I/(A cos θ) would grow
 * without bound. The data cannot resolve it there: a face seen within 5° of edge-on is a sliver of
 * at most 8.7 % of its area, a pixel or two at room distances, and the photometry's γ steps
 * (≥ 2.5° in the catalog's files) are as wide as that band. So cos θ is floored at cos 85°: L is
 * I/(A·cos 85°) beyond 85°, finite, and continuous, falling to 0 with I at the horizon. For a
 * Lambertian face (I = I₀·cos θ) L is I₀/A at every angle up to 85°, as it must be.
 *
 * `toEye`: world vector from the face to the eye. Zero area or a degenerate direction gives 0.
 */
export function luminanceToward(e: EmitterPhotometry, side: -1 | 1, area: number, toEye: Vec3): number {
  if (!(area > 0) || !Number.isFinite(area)) return 0;
  const local = applyMat3(transpose(e.rotation), toEye);
  const length = Math.hypot(local[0], local[1], local[2]);
  if (!(length > 0) || !Number.isFinite(length)) return 0;
  const cosFace = (side * local[1]) / length;
  if (!(cosFace > 0)) return 0;
  const [gamma, c] = photometricAngles(local);
  const i = Math.max(0, intensity(e.photometry, gamma, c)) * e.tilt;
  return Number.isFinite(i) ? i / (area * Math.max(cosFace, COS_GRAZING)) : 0;
}
