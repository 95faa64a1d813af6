import * as THREE from 'three';
import { windowPaneFragment, windowPaneVertex } from '../../../shaders/windowPane.glsl';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import type { BakeDaylight } from '../bake/daylight/bakeDaylight';
import { daylightWindows, type BakeWindow } from '../bake/daylight/daylightWindows';
import type { SharedDisplayUniforms } from './createRoomSurfaces';
import { NIGHT_SKY_LUMINANCE, WINDOW_FRAME_GREY, WINDOW_FRAME_WIDTH, windowGlazingUniforms, windowSkyUniforms } from './windowPaneUniforms';

/** How far outside the wall's plane a pane is drawn (m): behind the hole, never in the wall's depth. */
const PANE_OUTSIDE = 0.01;

/**
 * The windows of a shaped room in the 3D view (issue 30, docs/daylight.md "Windows in the 3D view"):
 * one pane per window opening, just outside its hole, showing the sky and the ground through the
 * glazing (windowPane.glsl.ts) with the exposure and adaptation every surface shares. Doors and plain
 * openings get none (they lead indoors).
 */
export interface WindowPanes {
  readonly group: THREE.Group;
  /** The room's windows and what they show: its daylight, or null for the night sky (no daylight, or electric light only). */
  set(shape: ShapedRoom | null, daylight: BakeDaylight | null, glazing: BakeDaylight['glazing']): void;
  dispose(): void;
}

function paneGeometry(w: BakeWindow): THREE.BufferGeometry {
  const out = w.inward.map((v) => -v * PANE_OUTSIDE);
  const at = (a: number, b: number) => w.corner.map((c, k) => c + a * w.edgeA[k] + b * w.edgeB[k] + out[k]);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute([...at(0, 0), ...at(1, 0), ...at(1, 1), ...at(0, 1)], 3));
  g.setAttribute('uv', new THREE.Float32BufferAttribute([0, 0, 1, 0, 1, 1, 0, 1], 2));
  // Front faces toward the room: edgeA × edgeB against the inward normal decides the winding.
  const [a, b] = [w.edgeA, w.edgeB];
  const cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const facesIn = cross[0] * w.inward[0] + cross[1] * w.inward[1] + cross[2] * w.inward[2] > 0;
  g.setIndex(facesIn ? [0, 1, 2, 0, 2, 3] : [0, 2, 1, 0, 3, 2]);
  return g;
}

function paneMaterial(display: SharedDisplayUniforms, w: BakeWindow, daylight: BakeDaylight | null): THREE.ShaderMaterial {
  const sky = windowSkyUniforms(daylight?.sky ?? null);
  const glass = windowGlazingUniforms(w.glazing);
  const night = !daylight;
  return new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: windowPaneVertex,
    fragmentShader: windowPaneFragment,
    uniforms: {
      uSky: { value: night ? 0 : sky.sky },
      uZenith: { value: sky.zenith },
      uGradation: { value: new THREE.Vector3(...sky.gradation) },
      uIndicatrix: { value: new THREE.Vector3(...sky.indicatrix) },
      uSun: { value: new THREE.Vector3(...sky.sun) },
      uGround: { value: daylight?.groundLuminance ?? 0 },
      uNight: { value: NIGHT_SKY_LUMINANCE },
      uTransmittance: { value: glass.transmittance },
      uPanes: { value: glass.panes },
      uOutward: { value: new THREE.Vector3(-w.inward[0], -w.inward[1], -w.inward[2]) },
      uSize: { value: new THREE.Vector2(Math.hypot(...w.edgeA), Math.hypot(...w.edgeB)) },
      uFrameWidth: { value: WINDOW_FRAME_WIDTH },
      uFrameGrey: { value: WINDOW_FRAME_GREY },
      uExposure: display.uExposure,
      uAdapt: display.uAdapt,
      uMode: display.uMode,
    },
    side: THREE.FrontSide,
  });
}

export function createWindowPanes(display: SharedDisplayUniforms): WindowPanes {
  const group = new THREE.Group();
  group.name = 'windows';
  const clear = () => {
    for (const child of [...group.children]) {
      const mesh = child as THREE.Mesh<THREE.BufferGeometry, THREE.ShaderMaterial>;
      mesh.geometry.dispose();
      mesh.material.dispose();
      group.remove(mesh);
    }
  };
  return {
    group,
    set(shape, daylight, glazing) {
      clear();
      if (!shape) return;
      // World coordinates: the view draws a shaped room where the scene has it (shapedRoomView.ts).
      for (const w of daylightWindows(shape, [0, 0, 0], glazing)) {
        const mesh = new THREE.Mesh(paneGeometry(w), paneMaterial(display, w, daylight));
        mesh.name = `window-${w.opening}`;
        // Picks (select, aim at) see the room and its objects, never the outside through a window.
        mesh.raycast = () => undefined;
        group.add(mesh);
      }
    },
    dispose: clear,
  };
}
