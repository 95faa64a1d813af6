import type { CameraPresetName } from '../../engines/view/cameraPresets';

/**
 * What the 3D view's camera is doing, for the panel's buttons (docs/aiming.md, "Spotlight view"):
 * the orbit camera last placed by a preset, or the spotlight view of a module. One state, so the
 * preset buttons and the spotlight button cannot disagree with each other or with the camera.
 */
export interface CameraMode {
  /** The preset the orbit camera was last put at (the user may have orbited since). */
  readonly preset: CameraPresetName;
  /** The module whose spotlight view is shown, or null: the orbit camera. */
  readonly spotlight: string | null;
}

export type CameraModeEvent =
  /** A preset button: the orbit camera goes to the preset, which leaves the spotlight view. */
  | { readonly kind: 'preset'; readonly name: CameraPresetName }
  /** The spotlight button: enter the module's view (an id) or leave it (null). */
  | { readonly kind: 'spotlight'; readonly moduleId: string | null }
  /** The adjustable module the selection offers changed (null: none): the spotlight view of another one ends. */
  | { readonly kind: 'selection'; readonly moduleId: string | null };

export const INITIAL_CAMERA_MODE: CameraMode = { preset: 'corner', spotlight: null };

export function nextCameraMode(mode: CameraMode, event: CameraModeEvent): CameraMode {
  switch (event.kind) {
    case 'preset':
      return { preset: event.name, spotlight: null };
    case 'spotlight':
      return mode.spotlight === event.moduleId ? mode : { ...mode, spotlight: event.moduleId };
    case 'selection':
      return mode.spotlight !== null && mode.spotlight !== event.moduleId ? { ...mode, spotlight: null } : mode;
  }
}

/** A preset button shows pressed only while the orbit camera is on: in the spotlight view no preset is the view. */
export const presetPressed = (mode: CameraMode, name: CameraPresetName): boolean => mode.spotlight === null && mode.preset === name;
