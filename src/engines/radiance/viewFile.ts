import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { CameraPose } from '../view/cameraPresets';
import { num, toRadiance, vecText } from './radianceFrame';

/**
 * A camera pose as a Radiance view file (`rpict -vf`): perspective, position and direction in
 * Radiance's frame, Z up (or north, +Y, for a view straight down, where Z is no use as "up").
 * luxbox's `fov` is vertical (three.js); Radiance wants both angles, the horizontal one from the
 * image's aspect: vh = 2·atan(tan(vv/2)·width/height).
 */
export function viewFile(pose: CameraPose, aspect: number): string {
  const eye = toRadiance(pose.position);
  const target = toRadiance(pose.target);
  const dir: Vec3 = [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]];
  const len = Math.hypot(dir[0], dir[1], dir[2]);
  const unit = dir.map((d) => d / len) as Vec3;
  const up: Vec3 = Math.abs(unit[2]) > 0.999 ? [0, 1, 0] : [0, 0, 1];
  const vv = pose.fov;
  const vh = (2 * Math.atan(Math.tan((vv * Math.PI) / 360) * aspect) * 180) / Math.PI;
  return `rview -vtv -vp ${vecText(eye)} -vd ${vecText(unit)} -vu ${vecText(up)} -vh ${num(vh)} -vv ${num(vv)}\n`;
}
