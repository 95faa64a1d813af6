import * as THREE from 'three';
import { canRenderGlare, createGlarePass, type GlarePass } from './glare/createGlarePass';
import type { SharedDisplayUniforms } from './createRoomSurfaces';

/** The view's background (sRGB bytes 0x1d2126), as three shows THREE.Color(0x1d2126) on the canvas. */
const BACKGROUND = 0x1d2126;

/** How the room view draws: straight to the canvas, or through the glare pass (glare/createGlarePass.ts). */
export interface RoomViewRender {
  setGlare(on: boolean): void;
  glareShown(): boolean;
  render(renderer: THREE.WebGLRenderer): void;
  /** The materials of the next render compiled without blocking, into the target that render draws to (renderer.compileAsync). */
  compileAsync(renderer: THREE.WebGLRenderer): Promise<unknown>;
  dispose(): void;
}

export function createRoomViewRender(scene: THREE.Scene, camera: THREE.PerspectiveCamera, display: SharedDisplayUniforms): RoomViewRender {
  const background = new THREE.Color(BACKGROUND);
  scene.background = background;
  // The glare pass's HDR target is cleared to 0 (no light); its composite shows this display colour there.
  const backgroundDisplay: [number, number, number] = [((BACKGROUND >> 16) & 255) / 255, ((BACKGROUND >> 8) & 255) / 255, (BACKGROUND & 255) / 255];
  const black = new THREE.Color(0, 0, 0);
  const bufferSize = new THREE.Vector2();
  const clearColor = new THREE.Color();
  let glareOn = false;
  let glare: GlarePass | null = null;
  let glareShown = false;
  const throughGlare = (renderer: THREE.WebGLRenderer) => glareOn && display.uMode.value === 0 && canRenderGlare(renderer);
  const glarePass = (renderer: THREE.WebGLRenderer): GlarePass => {
    renderer.getDrawingBufferSize(bufferSize);
    // Multisampled like the canvas (antialias) when it is.
    glare ??= createGlarePass({ samples: renderer.getContext().getContextAttributes()?.antialias ? 4 : 0, background: backgroundDisplay });
    glare.setSize(bufferSize.x, bufferSize.y);
    return glare;
  };
  return {
    setGlare(on) {
      glareOn = on;
    },
    glareShown: () => glareShown,
    render(renderer) {
      glareShown = throughGlare(renderer);
      if (!glareShown) {
        renderer.render(scene, camera);
        return;
      }
      const pass = glarePass(renderer);
      const mode = display.uMode;
      renderer.getClearColor(clearColor);
      const clearAlpha = renderer.getClearAlpha();
      mode.value = 2;
      scene.background = null;
      renderer.setClearColor(black, 0);
      renderer.setRenderTarget(pass.target);
      renderer.clear();
      renderer.render(scene, camera);
      renderer.setRenderTarget(null);
      mode.value = 0;
      scene.background = background;
      renderer.setClearColor(clearColor, clearAlpha);
      pass.finish(renderer, camera.fov / bufferSize.y, null);
    },
    compileAsync(renderer) {
      // Three's program variant depends on the target (tone mapping and colour space apply only to the canvas).
      if (!throughGlare(renderer)) return renderer.compileAsync(scene, camera);
      renderer.setRenderTarget(glarePass(renderer).target);
      const done = renderer.compileAsync(scene, camera);
      renderer.setRenderTarget(null);
      return done;
    },
    dispose() {
      glare?.dispose();
    },
  };
}

/**
 * A key of the programs the scene's next render needs: each material three would compile
 * (WebGLRenderer.compile walks every object with a material, shown or not) by its uuid and
 * version (three bumps the version at `needsUpdate`, the one way a material asks for a new
 * program). Equal keys: nothing to compile.
 */
export function materialsKey(scene: THREE.Object3D): string {
  const parts: string[] = [];
  scene.traverse((object) => {
    const material = (object as THREE.Object3D & { material?: THREE.Material | THREE.Material[] }).material;
    if (!material) return;
    for (const m of Array.isArray(material) ? material : [material]) parts.push(`${m.uuid}:${m.version}`);
  });
  return parts.join(',');
}
