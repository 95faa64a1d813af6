import * as THREE from 'three';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import type { CameraPose } from './cameraPresets';
import { falseColorGlsl } from '../../../shaders/falseColor.glsl';
import { MAX_LEVELS, TURBO_B, TURBO_G, TURBO_R } from './falseColorScale';
import { MODULE_HEIGHT, RAIL_HEIGHT, type Fixtures } from './fixtures';
import { toneMapGlsl } from '../../../shaders/toneMap.glsl';

export type ViewMode = 'light' | 'lux';

const surfaceVertex = /* glsl */ `
out vec2 vUv;
out vec3 vWorld;
void main() {
  vUv = uv;
  vWorld = (modelMatrix * vec4(position, 1.0)).xyz;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

/**
 * Surface: stored illuminance E (RGB lux) → luminance ρE/π → display, or
 * false-colour lux. In lux mode the isolines follow E averaged over the 4×4
 * texels around the point (four bilinear taps one texel off diagonally): the
 * fill keeps every texel's value, the lines do not wiggle with the noise of
 * the indirect light (falseColor.glsl.ts).
 */
const surfaceFragment = /* glsl */ `
precision highp float;
in vec2 vUv;
in vec3 vWorld;
uniform sampler2D uIlluminance;
uniform vec3 uNormal;
uniform vec3 uReflectance;
uniform float uExposure;
uniform int uMode;
out vec4 fragColor;
${toneMapGlsl}
${falseColorGlsl({ maxLevels: MAX_LEVELS, turbo: [TURBO_R, TURBO_G, TURBO_B] })}
void main() {
  vec3 E = max(texture(uIlluminance, vUv).rgb, 0.0);
  if (uMode == 1) {
    const vec3 Y = vec3(0.2126, 0.7152, 0.0722);
    vec2 t = 1.0 / vec2(textureSize(uIlluminance, 0));
    vec3 Es = texture(uIlluminance, vUv + vec2(t.x, t.y)).rgb + texture(uIlluminance, vUv + vec2(-t.x, t.y)).rgb
            + texture(uIlluminance, vUv + vec2(t.x, -t.y)).rgb + texture(uIlluminance, vUv - t).rgb;
    float facing = abs(dot(uNormal, normalize(cameraPosition - vWorld)));
    fragColor = vec4(luxFalseColor(dot(E, Y), max(dot(Es, Y), 0.0) * 0.25, facing), 1.0);
  } else {
    vec3 L = uReflectance * E / 3.14159265358979;
    fragColor = vec4(luxDisplay(L, uExposure), 1.0);
  }
}
`;

/** Hardware: a flat sRGB colour with a fixed fake light so boxes read as boxes (they are not part of the light solution). */
const flatVertex = /* glsl */ `
out float vShade;
void main() {
  vec3 n = normalize(mat3(modelMatrix) * normal);
  vShade = 0.55 + 0.45 * clamp(0.5 * n.y + 0.5, 0.0, 1.0) - 0.1 * abs(n.x);
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;
const flatFragment = /* glsl */ `
precision highp float;
in float vShade;
uniform vec3 uColor;
out vec4 fragColor;
void main() { fragColor = vec4(uColor * vShade, 1.0); }
`;

/** A quad covering one surface, facing into the room, with uv = (u/lengthU, v/lengthV) so texel centres land as the baker put them. */
function surfaceGeometry(l: SurfaceLayout): THREE.BufferGeometry {
  const corner = (u: number, v: number): number[] => {
    const p = [l.origin[0], l.origin[1], l.origin[2]];
    p[l.uAxisIndex] = u * l.lengthU;
    p[l.vAxisIndex] = v * l.lengthV;
    return p;
  };
  const uvs = [
    [0, 0],
    [1, 0],
    [1, 1],
    [0, 1],
  ];
  const pts = uvs.map(([u, v]) => corner(u, v));
  // Winding: the front face must face the room (counterclockwise seen from inside), so walls facing away from an outside camera are culled.
  const e1 = pts[1].map((x, i) => x - pts[0][i]);
  const e2 = pts[2].map((x, i) => x - pts[0][i]);
  const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
  const facesIn = n[0] * l.normal[0] + n[1] * l.normal[1] + n[2] * l.normal[2] > 0;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(pts.flat(), 3));
  g.setAttribute('uv', new THREE.Float32BufferAttribute(uvs.flat(), 2));
  g.setIndex(facesIn ? [0, 1, 2, 0, 2, 3] : [0, 2, 1, 0, 3, 2]);
  return g;
}

function flatMaterial(color: Rgb): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader: flatVertex, fragmentShader: flatFragment, uniforms: { uColor: { value: new THREE.Vector3(...color) } } });
}

const RAIL_COLOR: Rgb = [0.16, 0.16, 0.17];
const MODULE_ON: Rgb = [0.98, 0.95, 0.86];
const MODULE_OFF: Rgb = [0.45, 0.45, 0.45];
const CABLE_COLOR: Rgb = [0.3, 0.3, 0.3];

/**
 * The 3D room: six surfaces showing the relit light maps, the hardware, a
 * camera. Shared by the browser viewer and `luxbox render` (three.js on
 * headless-gl), so both draw the same pixels from the same maps.
 */
export interface RoomView {
  readonly scene: THREE.Scene;
  readonly camera: THREE.PerspectiveCamera;
  /** Upload relit maps (RGB lux) and the room's reflectances. */
  setMaps(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>): void;
  setExposure(exposure: number): void;
  setMode(mode: ViewMode, levels?: readonly number[]): void;
  setFixtures(fixtures: Fixtures): void;
  setCamera(pose: CameraPose, aspect: number): void;
  render(renderer: THREE.WebGLRenderer): void;
  dispose(): void;
}

export function createRoomView(renderer: THREE.WebGLRenderer): RoomView {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x1d2126);
  const camera = new THREE.PerspectiveCamera(60, 1, 0.05, 500);
  const linear = renderer.extensions.has('OES_texture_float_linear');
  const surfaces = new Map<SurfaceName, { mesh: THREE.Mesh; material: THREE.ShaderMaterial; texture: THREE.DataTexture | null; key: string }>();
  const levelUniform = { value: new Array<number>(MAX_LEVELS).fill(1) };
  const levelCount = { value: 0 };
  const exposure = { value: 1 };
  const mode = { value: 0 };
  const hardware = new THREE.Group();
  scene.add(hardware);
  const hwMaterials = { rail: flatMaterial(RAIL_COLOR), on: flatMaterial(MODULE_ON), off: flatMaterial(MODULE_OFF), cable: flatMaterial(CABLE_COLOR) };

  const surfaceFor = (layout: SurfaceLayout) => {
    const key = `${layout.width}x${layout.height}@${layout.lengthU}x${layout.lengthV}`;
    let s = surfaces.get(layout.name);
    if (s && s.key === key) return s;
    if (s) {
      scene.remove(s.mesh);
      s.mesh.geometry.dispose();
      s.texture?.dispose();
      s.material.dispose();
    }
    const material = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      vertexShader: surfaceVertex,
      fragmentShader: surfaceFragment,
      uniforms: {
        uIlluminance: { value: null },
        uNormal: { value: new THREE.Vector3(...layout.normal) },
        uReflectance: { value: new THREE.Vector3(0.5, 0.5, 0.5) },
        uExposure: exposure,
        uMode: mode,
        uLevels: levelUniform,
        uLevelCount: levelCount,
      },
      side: THREE.FrontSide,
    });
    const mesh = new THREE.Mesh(surfaceGeometry(layout), material);
    mesh.name = layout.name;
    scene.add(mesh);
    s = { mesh, material, texture: null, key };
    surfaces.set(layout.name, s);
    return s;
  };

  const disposeHardware = () => {
    for (const child of [...hardware.children]) {
      hardware.remove(child);
      (child as THREE.Mesh).geometry?.dispose();
    }
  };

  return {
    scene,
    camera,
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
          s.material.uniforms.uIlluminance.value = s.texture;
        }
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
      }
    },
    setExposure(value) {
      exposure.value = Number.isFinite(value) && value > 0 ? value : 1;
    },
    setMode(m, levels = []) {
      mode.value = m === 'lux' ? 1 : 0;
      const ls = levels.slice(0, MAX_LEVELS).filter((v) => v > 0);
      levelCount.value = ls.length;
      for (let i = 0; i < MAX_LEVELS; i++) levelUniform.value[i] = ls[i] ?? 1;
    },
    setFixtures(f) {
      disposeHardware();
      for (const r of f.rails) {
        const dx = r.end[0] - r.start[0];
        const dz = r.end[2] - r.start[2];
        const len = Math.hypot(dx, dz);
        const mesh = new THREE.Mesh(new THREE.BoxGeometry(len, RAIL_HEIGHT, 0.05), hwMaterials.rail);
        mesh.position.set((r.start[0] + r.end[0]) / 2, r.start[1], (r.start[2] + r.end[2]) / 2);
        mesh.rotation.y = Math.atan2(-dz, dx);
        hardware.add(mesh);
      }
      for (const m of f.modules) {
        const mesh = new THREE.Mesh(new THREE.BoxGeometry(Math.max(0.03, m.length - 0.006), MODULE_HEIGHT, 0.044), m.on ? hwMaterials.on : hwMaterials.off);
        mesh.position.set(m.centre[0], m.centre[1] + MODULE_HEIGHT / 2, m.centre[2]);
        mesh.rotation.y = (m.heading * Math.PI) / 180;
        mesh.name = `module:${m.id}`;
        hardware.add(mesh);
      }
      for (const c of f.cables) {
        const h = c.top[1] - c.bottom[1];
        if (!(h > 0)) continue;
        const mesh = new THREE.Mesh(new THREE.BoxGeometry(0.006, h, 0.006), hwMaterials.cable);
        mesh.position.set(c.top[0], (c.top[1] + c.bottom[1]) / 2, c.top[2]);
        hardware.add(mesh);
      }
    },
    setCamera(pose, aspect) {
      camera.fov = pose.fov;
      camera.aspect = aspect;
      camera.position.set(...pose.position);
      camera.up.set(0, 1, 0);
      camera.lookAt(new THREE.Vector3(...pose.target));
      camera.updateProjectionMatrix();
    },
    render(renderer) {
      renderer.render(scene, camera);
    },
    dispose() {
      disposeHardware();
      for (const s of surfaces.values()) {
        s.mesh.geometry.dispose();
        s.texture?.dispose();
        s.material.dispose();
      }
      for (const m of Object.values(hwMaterials)) m.dispose();
      surfaces.clear();
    },
  };
}
