import { useCallback, useRef, useState, type RefObject } from 'react';
import type { CameraPresetName } from '../../engines/view/cameraPresets';
import type { ViewerController } from '../../engines/view/createViewerController';
import type { ViewMode } from '../../engines/view/roomView';
import { INITIAL_CAMERA_MODE, nextCameraMode, type CameraMode, type CameraModeEvent } from './cameraMode';

/** The 3D view's switches, each kept in the view and handed to the controller: light or lux, glare, the camera's mode. */
export function useViewerToggles(controllerRef: RefObject<ViewerController | null>) {
  const [mode, setMode] = useState<ViewMode>('light');
  // Veiling glare (docs/viewer.md, "Glare"): on by default. Not kept across visits: remembering needs the
  // host's `remember` on the first screen, which is at its download budget.
  const [glare, setGlare] = useState(true);
  /** The glare switch for a controller made later (useViewerController). */
  const glareRef = useRef(glare);
  // The camera's mode (a preset's orbit or a module's spotlight view): one state for both sets of buttons.
  const [camera, setCamera] = useState<CameraMode>(INITIAL_CAMERA_MODE);
  const cameraEvent = useCallback((e: CameraModeEvent) => setCamera((m) => nextCameraMode(m, e)), []);
  const chooseMode = (m: ViewMode) => {
    setMode(m);
    controllerRef.current?.setMode(m);
  };
  const switchGlare = (on: boolean) => {
    setGlare(on);
    glareRef.current = on;
    controllerRef.current?.setGlare(on);
  };
  const choosePreset = (p: CameraPresetName) => {
    setCamera((m) => nextCameraMode(m, { kind: 'preset', name: p }));
    // A preset leaves the spotlight view first (its orbit pose comes back), then moves the orbit camera.
    controllerRef.current?.setSpotlight(null);
    controllerRef.current?.setPreset(p);
  };
  return { mode, chooseMode, glare, glareRef, switchGlare, camera, cameraEvent, choosePreset };
}
