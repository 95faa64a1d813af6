/**
 * The aiming preview's light (docs/aiming.md, "Fast preview"): while a head is dragged, its direct
 * light is evaluated per fragment in the room surfaces' shader (shaders/spotPreview.glsl.ts) instead
 * of being baked: E = I(γ, C) · cos θ / d² × dimming × colour (inverse-square law with the cosine of
 * incidence, CIE 171:2006 test case 5.2), no shadows, no interreflections. The intensity comes
 * from a candela texture resampled from the module's photometry; the rest of the room shows the
 * relit maps without that module (its dimming at 0 in the service's overlay: a relight).
 */
import * as THREE from 'three';
import { intensity } from '../../core/photometry/intensity';
import type { Photometry } from '../../core/photometry/types';
import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';

/** Samples of the candela texture: C every 2.5° over 0…360 (inclusive), γ every 0.25° over 0…180. */
export const CANDELA_C_SAMPLES = 145;
export const CANDELA_GAMMA_SAMPLES = 721;

/** The photometry resampled on the preview grid, RGBA float (intensity in r), row = γ, column = C. */
export function candelaGrid(ph: Photometry): Float32Array {
  const data = new Float32Array(CANDELA_C_SAMPLES * CANDELA_GAMMA_SAMPLES * 4);
  for (let j = 0; j < CANDELA_GAMMA_SAMPLES; j++) {
    const gamma = (180 * j) / (CANDELA_GAMMA_SAMPLES - 1);
    for (let i = 0; i < CANDELA_C_SAMPLES; i++) {
      const c = (360 * i) / (CANDELA_C_SAMPLES - 1);
      data[(j * CANDELA_C_SAMPLES + i) * 4] = intensity(ph, gamma, c);
    }
  }
  return data;
}

/** The lamp the preview lights: where it is, how it is turned, its photometry and its RGB weight (dimming × colour). */
export interface PreviewLamp {
  position: Vec3;
  /** world → luminaire local, row-major 3×3 (the transpose of Ry(yaw)·Rx(pitch)·Ry(roll)). */
  toLocal: readonly number[];
  photometry: Photometry;
  weight: Rgb;
}

/** The CPU mirror of spotPreviewE (tests compare the shader and the reference against it): RGB lux at p on a surface of normal n. */
export function previewIlluminance(lamp: PreviewLamp, p: Vec3, n: Vec3): Rgb {
  const d = [lamp.position[0] - p[0], lamp.position[1] - p[1], lamp.position[2] - p[2]];
  const r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const cosI = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.sqrt(r2);
  if (!(cosI > 0)) return [0, 0, 0];
  const m = lamp.toLocal;
  const l = [0, 1, 2].map((k) => -(m[k * 3] * d[0] + m[k * 3 + 1] * d[1] + m[k * 3 + 2] * d[2]));
  const len = Math.hypot(l[0], l[1], l[2]);
  const gamma = (Math.acos(Math.max(-1, Math.min(1, -l[1] / len))) * 180) / Math.PI;
  let c = (Math.atan2(-l[2], l[0]) * 180) / Math.PI;
  if (c < 0) c += 360;
  const e = (intensity(lamp.photometry, gamma, c) * cosI) / r2;
  return [e * lamp.weight[0], e * lamp.weight[1], e * lamp.weight[2]];
}

/** The preview's uniforms, shared by every room surface's material (one assignment updates all six). */
export interface SpotPreviewUniforms {
  uSpotOn: { value: number };
  uSpotPos: { value: THREE.Vector3 };
  uSpotToLocal: { value: THREE.Matrix3 };
  uSpotWeight: { value: THREE.Vector3 };
  uSpotCandela: { value: THREE.DataTexture | null };
}

export function createSpotPreviewUniforms(): SpotPreviewUniforms {
  return {
    uSpotOn: { value: 0 },
    uSpotPos: { value: new THREE.Vector3() },
    uSpotToLocal: { value: new THREE.Matrix3() },
    uSpotWeight: { value: new THREE.Vector3() },
    uSpotCandela: { value: null },
  };
}

/** A float texture of candelaGrid (linear filtering where the device has it, else nearest). */
export function candelaTexture(ph: Photometry, linear: boolean): THREE.DataTexture {
  const t = new THREE.DataTexture(candelaGrid(ph), CANDELA_C_SAMPLES, CANDELA_GAMMA_SAMPLES, THREE.RGBAFormat, THREE.FloatType);
  t.minFilter = t.magFilter = linear ? THREE.LinearFilter : THREE.NearestFilter;
  t.wrapS = t.wrapT = THREE.ClampToEdgeWrapping;
  t.generateMipmaps = false;
  t.needsUpdate = true;
  return t;
}

/** Puts a lamp into the uniforms (null: preview off). Matrix3.set takes row-major values. */
export function setPreviewLamp(u: SpotPreviewUniforms, lamp: Omit<PreviewLamp, 'photometry'> | null): void {
  u.uSpotOn.value = lamp ? 1 : 0;
  if (!lamp) return;
  u.uSpotPos.value.set(...lamp.position);
  const m = lamp.toLocal;
  u.uSpotToLocal.value.set(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
  u.uSpotWeight.value.set(...lamp.weight);
}
