import { InputError } from '../../core/inputError';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { unknownFieldMessage } from '../../core/zodIssues';
import type { BakeScene } from '../bake/bakeScene';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { eyeAcrossTheRoom, frameTheLight } from './frameTheLight';

export interface CameraPose {
  position: Vec3;
  target: Vec3;
  /** Vertical field of view, degrees. */
  fov: number;
}

export const CAMERA_PRESETS = ['eye', 'top', 'corner'] as const;
export type CameraPresetName = (typeof CAMERA_PRESETS)[number];

export class CameraSpecError extends InputError {
  override name = 'CameraSpecError';
}

/** What a light-framing preset looks at: the scene's room and luminaires, and the view's aspect (width / height). */
export interface FramingLight {
  scene: BakeScene;
  aspect: number;
}

/**
 * Camera presets for a W×H×D room:
 * - eye: a person at eye height inside the room looking at where the light is (frameTheLight.ts:
 *   the main pool and the luminaires in view), given the scene; without one, from the middle of
 *   the south wall across the room;
 * - top: straight down from above (the ceiling faces away and is culled: a plan view with light);
 * - corner: the "doll's house" view from above the south-east corner, outside the room; the
 *   walls facing away from the camera are culled, so the inside shows.
 */
export function cameraPreset(name: CameraPresetName, room: { width: number; height: number; depth: number; shape?: ShapedRoom }, light?: FramingLight): CameraPose {
  const { width: W, height: H, depth: D } = room;
  // A shaped room's outline may start anywhere: the views from outside frame its bounding box.
  const [x0, z0] = room.shape ? [Math.min(...room.shape.corners.map((c) => c[0])), Math.min(...room.shape.corners.map((c) => c[1]))] : [0, 0];
  const moved = (pose: CameraPose): CameraPose => (x0 === 0 && z0 === 0 ? pose : { ...pose, position: [pose.position[0] + x0, pose.position[1], pose.position[2] + z0], target: [pose.target[0] + x0, pose.target[1], pose.target[2] + z0] });
  switch (name) {
    case 'eye':
      return light ? frameTheLight(light.scene, light.aspect).pose : eyeAcrossTheRoom(room);
    case 'top': {
      // Narrow field: little parallax between the hardware and the floor, close to a plan.
      const fov = 30;
      const extent = Math.max(W, D) * 0.6;
      const distance = extent / Math.tan(((fov / 2) * Math.PI) / 180);
      // A hair off the vertical so the view's "up" (−z, north) is well defined.
      return moved({ position: [W / 2, H + distance, D / 2 + 1e-3], target: [W / 2, 0, D / 2], fov });
    }
    case 'corner': {
      const r = Math.max(W, D, H);
      return moved({ position: [W + 0.55 * r, H + 0.9 * r, D + 0.75 * r], target: [W / 2, H * 0.3, D / 2], fov: 45 });
    }
  }
}

const CAMERA_FIELDS = ['position', 'target', 'fov'] as const;

const isVec3 = (v: unknown): v is Vec3 => Array.isArray(v) && v.length === 3 && v.every((x) => typeof x === 'number' && Number.isFinite(x));

/** `--camera eye|top|corner` or a JSON object `{"position":[x,y,z],"target":[x,y,z],"fov":deg}`. */
export function parseCameraSpec(spec: string, room: { width: number; height: number; depth: number; shape?: ShapedRoom }, light?: FramingLight): CameraPose {
  if ((CAMERA_PRESETS as readonly string[]).includes(spec)) return cameraPreset(spec as CameraPresetName, room, light);
  let data: unknown;
  try {
    data = JSON.parse(spec);
  } catch {
    throw new CameraSpecError(`--camera: "${spec}" is neither a preset (${CAMERA_PRESETS.join(', ')}) nor JSON like {"position":[x,y,z],"target":[x,y,z],"fov":60}`);
  }
  if (typeof data !== 'object' || data === null) throw new CameraSpecError('--camera: JSON must be an object with position, target and fov');
  const o = data as Record<string, unknown>;
  // Strict, as every other JSON input (issue 18): a misspelt "fov" must not silently become 60°.
  const unknown = Array.isArray(o) ? undefined : Object.keys(o).find((k) => !(CAMERA_FIELDS as readonly string[]).includes(k));
  if (unknown !== undefined) throw new CameraSpecError(`--camera: ${unknownFieldMessage(unknown, CAMERA_FIELDS)}; expected position, target and fov`);
  if (!isVec3(o.position)) throw new CameraSpecError('--camera: position must be three finite numbers [x, y, z] in metres');
  if (!isVec3(o.target)) throw new CameraSpecError('--camera: target must be three finite numbers [x, y, z] in metres');
  const fov = o.fov ?? 60;
  if (typeof fov !== 'number' || !(fov > 1 && fov < 170)) throw new CameraSpecError(`--camera: fov must be a number of degrees in 1..170, got ${JSON.stringify(fov)}`);
  if (o.position.every((v, i) => v === (o.target as Vec3)[i])) throw new CameraSpecError('--camera: position and target must differ');
  return { position: o.position, target: o.target, fov };
}
