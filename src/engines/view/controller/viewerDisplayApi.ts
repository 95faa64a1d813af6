import type { AdaptationSetting } from '../adaptationSetting';
import type { CameraPresetName } from '../cameraPresets';
import type { ViewMode } from '../roomView';
import { syncGlare, type Viewer } from './viewer';

/** The viewer controller's methods for how it is shown: exposure, adaptation, mode, glare, camera, size, on or off screen. */
export function viewerDisplayApi(v: Viewer) {
  return {
    setExposureEv(ev: number) {
      v.maps.setExposureEv(ev);
      v.frames.request();
    },
    /** Absolute exposure in EV100 (photographicExposure.ts), or null: automatic exposure again. */
    setEv100(ev100: number | null) {
      v.maps.setEv100(ev100);
      v.frames.request();
    },
    /** EV100 of the exposure on screen now: "lock exposure" passes it to setEv100. */
    currentEv100(): number {
      return v.maps.currentEv100();
    },
    /** Chromatic adaptation: eye (default), camera white balance at a CCT, none (chromaticAdaptation.ts). */
    setAdaptation(setting: AdaptationSetting) {
      v.maps.setAdaptation(setting);
      v.frames.request();
    },
    /** Adapt the automatic exposure and white to the light on screen now (they hold while the light is only dimmed or recoloured). */
    reAdapt() {
      v.maps.reAdapt();
      v.frames.request();
    },
    /** Whether the automatic exposure is held (relights keep it; a new room, a camera preset or reAdapt adapt again). */
    exposureHeld(): boolean {
      return v.maps.held();
    },
    setMode(m: ViewMode) {
      v.maps.setMode(m);
      v.frames.request();
    },
    /** Veiling glare on or off (light mode only). */
    setGlare(on: boolean) {
      v.glare = on;
      syncGlare(v);
      v.frames.request();
    },
    /** Whether the last frame went through the glare pass (light mode on a renderer with half-float targets). */
    glareShown(): boolean {
      return v.view.glareShown();
    },
    setPreset(name: CameraPresetName) {
      v.camera.setPreset(name);
      // A camera cut: the eye adapts to the room again.
      v.maps.reAdapt();
      v.frames.request();
    },
    resize(width: number, height: number) {
      v.camera.resize(width, height);
      v.renderer.setSize(v.camera.size.width, v.camera.size.height, false);
      v.frames.request();
    },
    /**
     * Shown or hidden without being disposed (the planner keeps the view while the 2D plan is on
     * screen, so the next 2D → 3D toggle costs one frame): hidden, nothing is drawn; shown again,
     * one frame with the maps it holds.
     */
    setActive(next: boolean) {
      v.active = next;
      if (v.active) v.frames.request();
    },
  };
}
