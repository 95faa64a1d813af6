/**
 * The spotlight view (docs/aiming.md): the camera at a selected adjustable module looking along its
 * axis, its beam (50 %) and field (10 %) outlines drawn where the cones meet the room, and
 * dragging (mouse or one finger) that pans and tilts the head with a per-frame preview of its
 * direct light (spotPreview.ts) over the relit maps without it. On release the new aim goes to
 * the host (a setAim), whose new scene rebakes that module's group only; the preview stays
 * until that bake is done, so the light never jumps back to the old aim.
 */
import * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { aimAxis, aimedOrientation, type AimLimits } from '../../core/model/modules/aim';
import { coneRoomOutline, type RoomBox } from '../../core/model/modules/coneOutline';
import type { ModuleAim } from '../../core/model/configuration/configuration';
import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { beamAndField } from '../../core/photometry/beam';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../bake/bakeScene';
import { luminaireRotation } from '../bake/luminaireRotation';
import type { RoomView } from './roomView';
import { candelaTexture, setPreviewLamp } from './spotPreview';
import { draggedAim, spotlightPose } from './spotlightPose';

/** What the spotlight view needs of the selected module (the host derives it from the configuration). */
export interface SpotlightTarget {
  moduleId: string;
  /** Photometric centre, world metres. */
  position: Vec3;
  /** Rail heading, degrees. */
  heading: number;
  /** The optic's catalog roll, degrees. */
  roll: number;
  aim: ModuleAim;
  limits: AimLimits;
  /** Full beam (50 %) and field (10 %) angles of the optic, degrees (photometry/beam.ts). */
  beamDeg: number;
  fieldDeg: number;
}

/** What the host knows of the module (the controller adds beam and field from the scene's photometry). */
export type SpotlightRequest = Omit<SpotlightTarget, 'beamDeg' | 'fieldDeg'>;

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

/** Outline colours: beam (50 %) warm yellow, field (10 %) orange, both readable on light and dark surfaces. */
export const BEAM_OUTLINE_COLOR = 0xffd23f;
export const FIELD_OUTLINE_COLOR = 0xff7a1a;
/** Rays per outline: a smooth curve where it crosses from the floor onto a wall. */
const OUTLINE_RAYS = 180;

/** The scene with one module's luminaire dimmed to 0 (a relight: its basis stays). */
export function withoutModule(scene: BakeScene, ids: readonly string[], moduleId: string): BakeScene {
  return { ...scene, luminaires: scene.luminaires.map((l, i) => (ids[i] === moduleId ? { ...l, dimming: 0 } : l)) };
}

export interface SpotlightDeps {
  canvas: HTMLCanvasElement;
  view: () => RoomView;
  controls: OrbitControls;
  request: () => void;
  room: () => RoomBox | null;
  /** The module's luminaire in the scene: photometry and RGB weight (dimming × colour), or null. */
  lamp: (moduleId: string) => { photometry: Photometry; weight: Rgb } | null;
  /** Dim one module out of the relit maps (null: none). */
  setDimmed: (moduleId: string | null) => void;
  /** A drag ended on a new aim. */
  onAim: (moduleId: string, aim: ModuleAim) => void;
  /** Whether the device filters float textures (else the candela texture is sampled nearest). */
  linearFloat: boolean;
}

export function createSpotlight(deps: SpotlightDeps) {
  let target: SpotlightTarget | null = null;
  /** The aim shown now (the target's, or the dragged one). */
  let aim: ModuleAim | null = null;
  let saved: { position: THREE.Vector3; target: THREE.Vector3; fov: number; up: THREE.Vector3 } | null = null;
  let drag: { id: number; x: number; y: number; start: ModuleAim } | null = null;
  /** After a release: the module whose preview stays until its new bake is done; `seen`: its new scene arrived. */
  let settling: { moduleId: string; seen: boolean } | null = null;
  let texture: { photometry: Photometry; texture: THREE.DataTexture } | null = null;
  const group = new THREE.Group();
  group.name = 'spotlight-outlines';
  group.renderOrder = 10;
  const lines = [BEAM_OUTLINE_COLOR, FIELD_OUTLINE_COLOR].map((color) => {
    const line = new THREE.LineLoop(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color, depthTest: false, transparent: true }));
    line.renderOrder = 10;
    line.frustumCulled = false;
    group.add(line);
    return line;
  });

  const attach = () => {
    const scene = deps.view().scene;
    if (group.parent !== scene) scene.add(group);
  };

  /** Camera and outlines for the aim shown now. */
  const pose = () => {
    if (!target || !aim) return;
    const cam = deps.view().camera;
    const p = spotlightPose(target.position, target.heading, aim, target.fieldDeg);
    cam.fov = p.fov;
    cam.position.set(...p.position);
    cam.up.set(...p.up);
    cam.lookAt(new THREE.Vector3(...p.target));
    cam.updateProjectionMatrix();
    const room = deps.room();
    const axis = aimAxis(target.heading, aim);
    [target.beamDeg, target.fieldDeg].forEach((full, k) => {
      const hits = room && full > 0 && full < 180 ? coneRoomOutline(target!.position, axis, full / 2, room, OUTLINE_RAYS) : [];
      const g = new THREE.BufferGeometry();
      g.setAttribute(
        'position',
        new THREE.Float32BufferAttribute(
          hits.flatMap((h) => h.point),
          3,
        ),
      );
      lines[k].geometry.dispose();
      lines[k].geometry = g;
    });
    attach();
    deps.request();
  };

  /** The preview lamp at the aim shown now (null: off). */
  const preview = (on: boolean) => {
    const u = deps.view().preview;
    const lamp = on && target && aim ? deps.lamp(target.moduleId) : null;
    if (!lamp || !target || !aim) {
      setPreviewLamp(u, null);
      return;
    }
    if (texture?.photometry !== lamp.photometry) {
      texture?.texture.dispose();
      texture = { photometry: lamp.photometry, texture: candelaTexture(lamp.photometry, deps.linearFloat) };
    }
    u.uSpotCandela.value = texture.texture;
    const o = aimedOrientation(target.heading, target.roll, aim);
    const m = luminaireRotation(o.yaw, o.pitch, o.roll);
    // world → local is the transpose of the (orthonormal) local → world rotation.
    const toLocal = [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]];
    setPreviewLamp(u, { position: target.position, toLocal, weight: lamp.weight });
  };

  const endPreview = () => {
    settling = null;
    preview(false);
    deps.setDimmed(null);
    deps.request();
  };

  const ndcHeight = () => Math.max(1, deps.canvas.getBoundingClientRect().height);
  const onDown = (e: PointerEvent) => {
    if (!target || !aim || drag || (e.pointerType === 'mouse' && e.button !== 0)) return;
    drag = { id: e.pointerId, x: e.clientX, y: e.clientY, start: aim };
    deps.canvas.setPointerCapture?.(e.pointerId);
  };
  const onMove = (e: PointerEvent) => {
    if (!drag || e.pointerId !== drag.id || !target) return;
    const next = draggedAim(drag.start, e.clientX - drag.x, e.clientY - drag.y, deps.view().camera.fov, ndcHeight(), target.limits);
    if (aim && next.rotation === aim.rotation && next.tilt === aim.tilt) return;
    // First move: the module leaves the relit maps (a relight) and its light comes from the shader.
    if (settling?.moduleId !== target.moduleId) deps.setDimmed(target.moduleId);
    settling = { moduleId: target.moduleId, seen: false };
    aim = next;
    pose();
    preview(true);
  };
  const onUp = (e: PointerEvent) => {
    if (!drag || e.pointerId !== drag.id || !target || !aim) return;
    // The release's own position counts: the last move before it may have been coalesced away.
    if (e.type !== 'pointercancel') onMove(e);
    const start = drag.start;
    drag = null;
    if (aim.rotation === start.rotation && aim.tilt === start.tilt) {
      if (settling && !settling.seen) endPreview();
      return;
    }
    deps.onAim(target.moduleId, aim);
  };
  deps.canvas.addEventListener('pointerdown', onDown);
  deps.canvas.addEventListener('pointermove', onMove);
  deps.canvas.addEventListener('pointerup', onUp);
  deps.canvas.addEventListener('pointercancel', onUp);

  return {
    /** Enter the view for a module, or follow the store's aim (null: leave, the orbit camera comes back). */
    set(next: SpotlightTarget | null) {
      const cam = deps.view().camera;
      if (!next) {
        if (!target) return;
        target = null;
        aim = null;
        drag = null;
        endPreview();
        group.removeFromParent();
        if (saved) {
          cam.position.copy(saved.position);
          cam.up.copy(saved.up);
          cam.fov = saved.fov;
          cam.lookAt(saved.target);
          cam.updateProjectionMatrix();
          deps.controls.target.copy(saved.target);
        }
        saved = null;
        deps.controls.enabled = true;
        deps.controls.update();
        deps.request();
        return;
      }
      if (!target) {
        saved = { position: cam.position.clone(), target: deps.controls.target.clone(), fov: cam.fov, up: cam.up.clone() };
        deps.controls.enabled = false;
      }
      if (target && target.moduleId !== next.moduleId) endPreview();
      target = next;
      // While a drag runs the dragged aim wins; otherwise the store's.
      if (!drag) aim = next.aim;
      pose();
    },
    active: () => target !== null,
    dragging: () => drag !== null,
    /** The host's new scene arrived (after a release it carries the new aim: its group bakes now). */
    sceneChanged() {
      if (settling && !drag) settling.seen = true;
    },
    /** A bake slice ran: once the released aim's bake is done, the baked light replaces the preview. */
    bakeProgress(done: boolean) {
      if (settling?.seen && done && !drag) endPreview();
    },
    /** The room view was rebuilt (context restored): outlines and preview go to the new one. */
    reattach() {
      attach();
      if (target) pose();
      if (settling) preview(true);
    },
    dispose() {
      deps.canvas.removeEventListener('pointerdown', onDown);
      deps.canvas.removeEventListener('pointermove', onMove);
      deps.canvas.removeEventListener('pointerup', onUp);
      deps.canvas.removeEventListener('pointercancel', onUp);
      group.removeFromParent();
      for (const l of lines) {
        l.geometry.dispose();
        (l.material as THREE.Material).dispose();
      }
      texture?.texture.dispose();
    },
  };
}

export type Spotlight = ReturnType<typeof createSpotlight>;
