import { l3dPlanOutline } from '../../engines/view/luminaires/l3dPlanOutline';
import { readL3dBody } from '../../engines/view/luminaires/readL3dBody';

/** A catalog `model` file (L3D) read into its plan outline (l3dPlanOutline); loaded as its own chunk by footprintSource, off the first screen. */
export function modelOutline(bytes: Uint8Array, path: string): [number, number][] {
  return l3dPlanOutline(readL3dBody(bytes, path));
}
