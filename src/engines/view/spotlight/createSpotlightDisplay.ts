import type { ModuleAim } from '../../../core/model/configuration/configuration';
import { setPreviewLamp } from '../spotPreview';
import { spotlightPose } from '../spotlightPose';
import { createSpotlightOutlines } from './createSpotlightOutlines';
import { restoreOrbitPose, saveOrbitPose, setCameraPose, type OrbitPose } from './orbitPose';
import { createCandelaCache, worldToLuminaire } from './previewLampParts';
import type { SpotlightDeps, SpotlightTarget } from './spotlightTarget';

/** What the spotlight view draws: the camera at the module, the outlines, the preview lamp; and the orbit camera kept and given back. */
export function createSpotlightDisplay(deps: SpotlightDeps) {
  const outlines = createSpotlightOutlines();
  const candela = createCandelaCache(deps.linearFloat);
  /** The outlines in the room view on screen (a new one after a context restore). */
  const attach = () => {
    const scene = deps.view().scene;
    if (outlines.group.parent !== scene) scene.add(outlines.group);
  };
  return {
    attach,
    /** Camera and outlines for the module at this aim (nothing without both). */
    pose(target: SpotlightTarget | null, aim: ModuleAim | null) {
      if (!target || !aim) return;
      setCameraPose(deps.view().camera, spotlightPose(target.position, target.heading, aim, target.fieldDeg));
      outlines.update(target, aim, deps.room());
      attach();
      deps.request();
    },
    /** The preview lamp for the module at this aim (off without both, or when the scene has no luminaire for it). */
    preview(target: SpotlightTarget | null, aim: ModuleAim | null) {
      const u = deps.view().preview;
      const lamp = target && aim ? deps.lamp(target.moduleId) : null;
      if (!lamp || !target || !aim) return setPreviewLamp(u, null);
      u.uSpotCandela.value = candela.get(lamp.photometry);
      setPreviewLamp(u, { position: target.position, toLocal: worldToLuminaire(target.heading, target.roll, aim), weight: lamp.weight });
    },
    /** Entering the view: the orbit camera's pose, kept for leave; the orbit controls rest meanwhile. */
    enter(): OrbitPose {
      const saved = saveOrbitPose(deps.view().camera, deps.controls);
      deps.controls.enabled = false;
      return saved;
    },
    /** Leaving the view: no outlines, the orbit camera back where it was, its controls on again. */
    leave(saved: OrbitPose | null) {
      outlines.group.removeFromParent();
      if (saved) restoreOrbitPose(deps.view().camera, deps.controls, saved);
      deps.controls.enabled = true;
      deps.controls.update();
      deps.request();
    },
    dispose() {
      outlines.dispose();
      candela.dispose();
    },
  };
}
