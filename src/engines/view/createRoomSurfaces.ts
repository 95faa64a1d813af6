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

/** What the surfaces' parts share: the scene they are added to, the surfaces by name and the uniform objects every material holds. */
interface SurfacesState {
  readonly scene: THREE.Scene;
  /** Without float texture filtering the maps are sampled nearest (blocky, but correct values). */
  readonly linear: boolean;
  readonly surfaces: Map<SurfaceName, Surface>;
  readonly display: SharedDisplayUniforms;
  readonly preview: SpotPreviewUniforms;
  readonly finishTextures: ReturnType<typeof createFinishTextures>;
  texturesOn: boolean;
  lastReflectance: Record<SurfaceName, Rgb> | null;
}

/** A surface's pattern for its reflectance, tiled in metres (uv spans lengthU × lengthV). */
function applyFinish(st: SurfacesState, s: Surface, layout: SurfaceLayout, rho: Rgb) {
  const t = st.texturesOn ? st.finishTextures.forReflectance(rho) : null;
  const u = s.material.uniforms;
  u.uFinishOn.value = t ? 1 : 0;
  u.uFinish.value = t?.texture ?? null;
  (u.uFinishGain.value as THREE.Vector3).set(...(t?.gain ?? [1, 1, 1]));
  (u.uFinishRepeat.value as THREE.Vector2).set(t ? layout.lengthU / t.period : 1, t ? layout.lengthV / t.period : 1);
}

function release(s: Surface) {
  s.mesh.geometry.dispose();
  s.texture?.dispose();
  s.material.dispose();
}

/** A surface's material: its own map, normal, reflectance and finish; the display uniforms and the aiming preview shared (the very objects). */
function surfaceMaterial(st: SurfacesState, layout: SurfaceLayout): THREE.ShaderMaterial {
  const d = st.display;
  return new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: roomSurfaceVertex,
    fragmentShader,
    uniforms: {
      uIlluminance: { value: null },
      uNormal: { value: new THREE.Vector3(...layout.normal) },
      uReflectance: { value: new THREE.Vector3(0.5, 0.5, 0.5) },
      uExposure: d.uExposure,
      uAdapt: d.uAdapt,
      uMode: d.uMode,
      uLevels: d.uLevels,
      uLevelCount: d.uLevelCount,
      uFinish: { value: null },
      uFinishGain: { value: new THREE.Vector3(1, 1, 1) },
      uFinishRepeat: { value: new THREE.Vector2(1, 1) },
      uFinishOn: { value: 0 },
      ...st.preview,
    },
    side: THREE.FrontSide,
  });
}

/** The surface of a layout: kept while its size is the same, rebuilt (and added to the scene) when it changed. */
function surfaceFor(st: SurfacesState, layout: SurfaceLayout): Surface {
  const key = `${layout.width}x${layout.height}@${layout.lengthU}x${layout.lengthV}`;
  let s = st.surfaces.get(layout.name);
  if (s && s.key === key) {
    s.layout = layout;
    return s;
  }
  if (s) {
    st.scene.remove(s.mesh);
    release(s);
  }
  const material = surfaceMaterial(st, layout);
  const mesh = new THREE.Mesh(quadGeometry(layout), material);
  mesh.name = layout.name;
  // A shaped room's enclosure: the box surface is a black sink, never drawn (the room's own surfaces are objects, shapedRoomView.ts).
  mesh.visible = layout.sink !== true;
  st.scene.add(mesh);
  s = { mesh, material, texture: null, key, layout };
  st.surfaces.set(layout.name, s);
  return s;
}

/** The surface's map texture, made on first use: RGBA float (three has no RGB float format; alpha unused). */
function mapTexture(st: SurfacesState, s: Surface, layout: SurfaceLayout): THREE.DataTexture {
  if (s.texture) return s.texture;
  const t = new THREE.DataTexture(new Float32Array(layout.width * layout.height * 4), layout.width, layout.height, THREE.RGBAFormat, THREE.FloatType);
  t.minFilter = t.magFilter = st.linear ? THREE.LinearFilter : THREE.NearestFilter;
  t.wrapS = t.wrapT = THREE.ClampToEdgeWrapping;
  t.generateMipmaps = false;
  s.texture = t;
  return t;
}

/** Upload the relit maps (RGB lux) into each surface's texture, with its reflectance and finish. */
function setSurfaceMaps(st: SurfacesState, lit: LitMaps, reflectance: Record<SurfaceName, Rgb>) {
  for (const name of SURFACE_NAMES) {
    const layout = lit.layouts[name];
    const s = surfaceFor(st, layout);
    const texture = mapTexture(st, s, layout);
    s.material.uniforms.uIlluminance.value = texture;
    const dst = texture.image.data as Float32Array;
    const src = lit.maps[name].total;
    const n = layout.width * layout.height;
    for (let i = 0; i < n; i++) {
      dst[i * 4] = src[i * 3];
      dst[i * 4 + 1] = src[i * 3 + 1];
      dst[i * 4 + 2] = src[i * 3 + 2];
      dst[i * 4 + 3] = 1;
    }
    texture.needsUpdate = true;
    (s.material.uniforms.uReflectance.value as THREE.Vector3).set(...reflectance[name]);
    applyFinish(st, s, layout, reflectance[name]);
  }
  st.lastReflectance = reflectance;
}

/** The display settings every surface (and the objects' material) shares: exposure, adaptation, mode and lux levels. */
function displaySetters(d: SharedDisplayUniforms) {
  return {
    setExposure(value: number) {
      d.uExposure.value = Number.isFinite(value) && value > 0 ? value : 1;
    },
    setAdaptation(m: Mat3) {
      // three's Matrix3.set takes rows; it stores (and uploads) columns, as GLSL's mat3 expects.
      if (m.every((v) => Number.isFinite(v))) d.uAdapt.value.set(...m);
      else d.uAdapt.value.identity();
    },
    setMode(m: ViewMode, levels: readonly number[] = []) {
      d.uMode.value = m === 'lux' ? 1 : 0;
      const { count, values } = shaderLevels(levels);
      d.uLevelCount.value = count;
      values.forEach((v, i) => (d.uLevels.value[i] = v));
    },
  };
}

/** Surfaces are added to `scene` when the first maps arrive (their size comes from the maps' layouts). */
export function createRoomSurfaces(scene: THREE.Scene, renderer: THREE.WebGLRenderer): RoomSurfaces {
  // Shared uniform objects: one assignment updates every surface's material.
  const display: SharedDisplayUniforms = {
    uExposure: { value: 1 },
    uAdapt: { value: new THREE.Matrix3() },
    uMode: { value: 0 },
    uLevels: { value: new Array<number>(MAX_LEVELS).fill(1) },
    uLevelCount: { value: 0 },
  };
  const st: SurfacesState = {
    scene,
    linear: renderer.extensions.has('OES_texture_float_linear'),
    surfaces: new Map(),
    display,
    preview: createSpotPreviewUniforms(),
    finishTextures: createFinishTextures(renderer),
    texturesOn: true,
    lastReflectance: null,
  };
  return {
    display,
    preview: st.preview,
    setMaps: (lit, reflectance) => setSurfaceMaps(st, lit, reflectance),
    setLightTextures(textures) {
      for (const [name, s] of st.surfaces) s.material.uniforms.uIlluminance.value = textures[name];
    },
    setFinishTextures(on) {
      st.texturesOn = on;
      const rho = st.lastReflectance;
      if (rho) for (const [name, s] of st.surfaces) applyFinish(st, s, s.layout, rho[name]);
    },
    ...displaySetters(display),
    dispose() {
      for (const s of st.surfaces.values()) release(s);
      st.surfaces.clear();
      st.finishTextures.dispose();
    },
  };
}
