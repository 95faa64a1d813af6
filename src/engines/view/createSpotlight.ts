/**
 * The spotlight view (docs/aiming.md): the camera at a selected adjustable module looking along its
 * axis, its beam (50 %) and field (10 %) outlines drawn where the cones meet the room, and
 * dragging (mouse or one finger) that pans and tilts the head with a per-frame preview of its
 * direct light (spotPreview.ts) over the relit maps without it. On release the new aim goes to
 * the host (a setAim), whose new scene rebakes that module's group only; the preview stays
 * until that bake is done, so the light never jumps back to the old aim.
 */
import type { ModuleAim } from '../../core/model/configuration/configuration';
import { beamAndField } from '../../core/photometry/beam';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../bake/bakeScene';
import { createSpotlightDisplay } from './spotlight/createSpotlightDisplay';
import type { OrbitPose } from './spotlight/orbitPose';
import type { SpotlightDeps, SpotlightTarget } from './spotlight/spotlightTarget';
import { watchHeadDrag } from './spotlight/watchHeadDrag';

export type { SpotlightDeps, SpotlightRequest, SpotlightTarget } from './spotlight/spotlightTarget';

const angles = new WeakMap<Photometry, { beamDeg: number; fieldDeg: number }>();
/** Full beam and field angles of a photometry, the mean of its C0–C180 and C90–C270 planes (photometry/beam.ts); cached per file. */
export function beamAndFieldDeg(ph: Photometry): { beamDeg: number; fieldDeg: number } {
  let a = angles.get(ph);
  if (!a) {
    const { c0, c90 } = beamAndField(ph);
    a = { beamDeg: (c0.beam + c90.beam) / 2, fieldDeg: (c0.field + c90.field) / 2 };
    angles.set(ph, a);
  }
  return a;
}

export { BEAM_OUTLINE_COLOR, FIELD_OUTLINE_COLOR } from './spotlight/createSpotlightOutlines';

/** The scene with one module's luminaire dimmed to 0 (a relight: its basis stays). */
export function withoutModule(scene: BakeScene, ids: readonly string[], moduleId: string): BakeScene {
  return { ...scene, luminaires: scene.luminaires.map((l, i) => (ids[i] === moduleId ? { ...l, dimming: 0 } : l)) };
}

export function createSpotlight(deps: SpotlightDeps) {
  let target: SpotlightTarget | null = null;
  /** The aim shown now (the target's, or the dragged one). */
  let aim: ModuleAim | null = null;
  let saved: OrbitPose | null = null;
  /** After a release: the module whose preview stays until its new bake is done; `seen`: its new scene arrived. */
  let settling: { moduleId: string; seen: boolean } | null = null;
  const display = createSpotlightDisplay(deps);
  const pose = () => display.pose(target, aim);
  const preview = (on: boolean) => display.preview(on ? target : null, aim);
  const endPreview = () => {
    settling = null;
    preview(false);
    deps.setDimmed(null);
    deps.request();
  };
  const drag = watchHeadDrag(deps.canvas, {
    current: () => (target && aim ? { aim, limits: target.limits } : null),
    fov: () => deps.view().camera.fov,
    moved(next) {
      // First move: the module leaves the relit maps (a relight) and its light comes from the shader.
      if (settling?.moduleId !== target!.moduleId) deps.setDimmed(target!.moduleId);
      settling = { moduleId: target!.moduleId, seen: false };
      aim = next;
      pose();
      preview(true);
    },
    released(start) {
      if (aim!.rotation === start.rotation && aim!.tilt === start.tilt) {
        if (settling && !settling.seen) endPreview();
        return;
      }
      deps.onAim(target!.moduleId, aim!);
    },
  });

  return {
    /** Enter the view for a module, or follow the store's aim (null: leave, the orbit camera comes back). */
    set(next: SpotlightTarget | null) {
      if (!next) {
        if (!target) return;
        [target, aim] = [null, null];
        drag.cancel();
        endPreview();
        display.leave(saved);
        saved = null;
        return;
      }
      if (!target) saved = display.enter();
      if (target && target.moduleId !== next.moduleId) endPreview();
      target = next;
      // While a drag runs the dragged aim wins; otherwise the store's.
      if (!drag.dragging()) aim = next.aim;
      pose();
    },
    active: () => target !== null,
    dragging: () => drag.dragging(),
    /** The host's new scene arrived (after a release it carries the new aim: its group bakes now). */
    sceneChanged() {
      if (settling && !drag.dragging()) settling.seen = true;
    },
    /** A bake slice ran: once the released aim's bake is done, the baked light replaces the preview. */
    bakeProgress(done: boolean) {
      if (settling?.seen && done && !drag.dragging()) endPreview();
    },
    /** The room view was rebuilt (context restored): outlines and preview go to the new one. */
    reattach() {
      display.attach();
      if (target) pose();
      if (settling) preview(true);
    },
    dispose() {
      drag.dispose();
      display.dispose();
    },
  };
}

export type Spotlight = ReturnType<typeof createSpotlight>;
