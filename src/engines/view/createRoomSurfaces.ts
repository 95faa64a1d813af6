import * as THREE from 'three';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { roomSurfaceFragment, roomSurfaceVertex } from '../../../shaders/roomSurface.glsl';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { LitMaps } from '../relight/relightMaps';
import { MAX_LEVELS, shaderLevels, TURBO_B, TURBO_G, TURBO_R } from './falseColorScale';
import { surfaceQuad } from './surfaceQuad';
import { createFinishTextures } from './createFinishTextures';
import type { Mat3 } from './colourMatrices';
import { CANDELA_C_SAMPLES, CANDELA_GAMMA_SAMPLES, createSpotPreviewUniforms, type SpotPreviewUniforms } from './spotPreview';

export type ViewMode = 'light' | 'lux';

/** The display uniforms the room's surfaces own; the objects' material shares the very objects, so one assignment updates both. */
export interface SharedDisplayUniforms {
  uExposure: { value: number };
  /** Chromatic adaptation on linear sRGB (cat16.ts), before the tone curve. */
  uAdapt: { value: THREE.Matrix3 };
  uMode: { value: number };
  uLevels: { value: number[] };
  uLevelCount: { value: number };
}

const fragmentShader = roomSurfaceFragment({ maxLevels: MAX_LEVELS, turbo: [TURBO_R, TURBO_G, TURBO_B] }, { cSamples: CANDELA_C_SAMPLES, gammaSamples: CANDELA_GAMMA_SAMPLES });

/** The six room surfaces showing the relit light maps, and the display settings all six share (exposure, mode, lux levels). */
export interface RoomSurfaces {
  /** Upload relit maps (RGB lux) and the room's reflectances; a surface whose layout changed is rebuilt. */
  setMaps(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>): void;
  /**
   * Show light the GPU relight wrote in the view's context (createViewRelight.ts) on the surfaces the
   * last `setMaps` laid out (same layouts: a relight); the next `setMaps` shows its own textures again.
   */
  setLightTextures(textures: Record<SurfaceName, THREE.Texture>): void;
  setExposure(exposure: number): void;
  /** The chromatic adaptation (row-major 3×3 on linear sRGB, chromaticAdaptation.ts); a non-finite matrix counts as the identity. */
  setAdaptation(matrix: Mat3): void;
  setMode(mode: ViewMode, levels?: readonly number[]): void;
  /** Draw the finishes' patterns (default on; light mode only: lux mode always shows the pure map). */
  setFinishTextures(on: boolean): void;
  /** The exposure, mode and level uniforms every surface shares (the objects' material shares them too). */
  readonly display: SharedDisplayUniforms;
  /** The aiming preview's lamp (spotPreview.ts), shared by all six surfaces; off unless a head is being dragged. */
  readonly preview: SpotPreviewUniforms;
  dispose(): void;
}

interface Surface {
  mesh: THREE.Mesh;
  material: THREE.ShaderMaterial;
  texture: THREE.DataTexture | null;
  key: string;
  layout: SurfaceLayout;
}

function quadGeometry(layout: SurfaceLayout): THREE.BufferGeometry {
  const q = surfaceQuad(layout);
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(q.positions, 3));
  g.setAttribute('uv', new THREE.Float32BufferAttribute(q.uvs, 2));
  g.setIndex(q.index);
  return g;
}

/** Surfaces are added to `scene` when the first maps arrive (their size comes from the maps' layouts). */
export function createRoomSurfaces(scene: THREE.Scene, renderer: THREE.WebGLRenderer): RoomSurfaces {
  // Without float texture filtering the maps are sampled nearest (blocky, but correct values).
  const linear = renderer.extensions.has('OES_texture_float_linear');
  const surfaces = new Map<SurfaceName, Surface>();
  // Shared uniform objects: one assignment updates every surface's material.
  const levelUniform = { value: new Array<number>(MAX_LEVELS).fill(1) };
  const levelCount = { value: 0 };
  const exposure = { value: 1 };
  const adapt = { value: new THREE.Matrix3() };
  const mode = { value: 0 };
  const preview = createSpotPreviewUniforms();
  const finishTextures = createFinishTextures(renderer);
  let texturesOn = true;
  let lastReflectance: Record<SurfaceName, Rgb> | null = null;
  /** Each surface's pattern for its reflectance, tiled in metres (uv spans lengthU × lengthV). */
  const applyFinish = (s: Surface, layout: SurfaceLayout, rho: Rgb) => {
    const t = texturesOn ? finishTextures.forReflectance(rho) : null;
    const u = s.material.uniforms;
    u.uFinishOn.value = t ? 1 : 0;
    u.uFinish.value = t?.texture ?? null;
    (u.uFinishGain.value as THREE.Vector3).set(...(t?.gain ?? [1, 1, 1]));
    (u.uFinishRepeat.value as THREE.Vector2).set(t ? layout.lengthU / t.period : 1, t ? layout.lengthV / t.period : 1);
  };

  const release = (s: Surface) => {
    s.mesh.geometry.dispose();
    s.texture?.dispose();
    s.material.dispose();
  };

  const surfaceFor = (layout: SurfaceLayout): Surface => {
    const key = `${layout.width}x${layout.height}@${layout.lengthU}x${layout.lengthV}`;
    let s = surfaces.get(layout.name);
    if (s && s.key === key) {
      s.layout = layout;
      return s;
    }
    if (s) {
      scene.remove(s.mesh);
      release(s);
    }
    const material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      vertexShader: roomSurfaceVertex,
      fragmentShader,
      uniforms: {
        uIlluminance: { value: null },
        uNormal: { value: new THREE.Vector3(...layout.normal) },
        uReflectance: { value: new THREE.Vector3(0.5, 0.5, 0.5) },
        uExposure: exposure,
        uAdapt: adapt,
        uMode: mode,
        uLevels: levelUniform,
        uLevelCount: levelCount,
        uFinish: { value: null },
        uFinishGain: { value: new THREE.Vector3(1, 1, 1) },
        uFinishRepeat: { value: new THREE.Vector2(1, 1) },
        uFinishOn: { value: 0 },
        ...preview,
      },
      side: THREE.FrontSide,
    });
    const mesh = new THREE.Mesh(quadGeometry(layout), material);
    mesh.name = layout.name;
    // A shaped room's enclosure: the box surface is a black sink, never drawn (the room's own surfaces are objects, shapedRoomView.ts).
    mesh.visible = layout.sink !== true;
    scene.add(mesh);
    s = { mesh, material, texture: null, key, layout };
    surfaces.set(layout.name, s);
    return s;
  };

  return {
    display: { uExposure: exposure, uAdapt: adapt, uMode: mode, uLevels: levelUniform, uLevelCount: levelCount },
    preview,
    setMaps(lit, reflectance) {
      for (const name of SURFACE_NAMES) {
        const layout = lit.layouts[name];
        const s = surfaceFor(layout);
        const n = layout.width * layout.height;
        if (!s.texture) {
          // RGBA float: three has no RGB float format; alpha unused.
          s.texture = new THREE.DataTexture(new Float32Array(n * 4), layout.width, layout.height, THREE.RGBAFormat, THREE.FloatType);
          s.texture.minFilter = s.texture.magFilter = linear ? THREE.LinearFilter : THREE.NearestFilter;
          s.texture.wrapS = s.texture.wrapT = THREE.ClampToEdgeWrapping;
          s.texture.generateMipmaps = false;
        }
        s.material.uniforms.uIlluminance.value = s.texture;
        const dst = s.texture.image.data as Float32Array;
        const src = lit.maps[name].total;
        for (let i = 0; i < n; i++) {
          dst[i * 4] = src[i * 3];
          dst[i * 4 + 1] = src[i * 3 + 1];
          dst[i * 4 + 2] = src[i * 3 + 2];
          dst[i * 4 + 3] = 1;
        }
        s.texture.needsUpdate = true;
        (s.material.uniforms.uReflectance.value as THREE.Vector3).set(...reflectance[name]);
        applyFinish(s, layout, reflectance[name]);
      }
      lastReflectance = reflectance;
    },
    setLightTextures(textures) {
      for (const [name, s] of surfaces) s.material.uniforms.uIlluminance.value = textures[name];
    },
    setFinishTextures(on) {
      texturesOn = on;
      if (!lastReflectance) return;
      for (const [name, s] of surfaces) {
        applyFinish(s, s.layout, lastReflectance[name]);
      }
    },
    setExposure(value) {
      exposure.value = Number.isFinite(value) && value > 0 ? value : 1;
    },
    setAdaptation(m) {
      // three's Matrix3.set takes rows; it stores (and uploads) columns, as GLSL's mat3 expects.
      if (m.every((v) => Number.isFinite(v))) adapt.value.set(...m);
      else adapt.value.identity();
    },
    setMode(m, levels = []) {
      mode.value = m === 'lux' ? 1 : 0;
      const { count, values } = shaderLevels(levels);
      levelCount.value = count;
      values.forEach((v, i) => (levelUniform.value[i] = v));
    },
    dispose() {
      for (const s of surfaces.values()) release(s);
      surfaces.clear();
      finishTextures.dispose();
    },
  };
}
