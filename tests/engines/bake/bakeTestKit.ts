/** Shared fixtures for the baker tests: a headless-gl context, synthetic and real photometry, reference maths. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { SURFACE_NAMES, type SurfaceName, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../../src/core/photometry/types';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { texelArea } from '../../../src/engines/bake/surfaceLayout';

export function basePhotometry(over: Partial<Photometry>): Photometry {
  return {
    format: 'IES',
    version: 'test',
    manufacturer: '',
    luminaire: '',
    catalogNumber: '',
    keywords: {},
    photometricType: 'C',
    symmetry: 'rotational',
    verticalAngles: [0, 180],
    horizontalAngles: [0],
    candela: [[1, 1]],
    statedLumens: null,
    absolute: true,
    inputWatts: null,
    luminousOpening: { width: 0, length: 0, height: 0, shape: 'point' },
    warnings: [],
    ...over,
  };
}

/** Constant intensity I over the whole sphere: Φ = 4πI. */
export function isotropic(candela: number): Photometry {
  return basePhotometry({ candela: [[candela, candela]] });
}

/** A rotationally symmetric spot: `peak` cd inside `halfAngle`°, falling linearly to 0 over the next `edge`°, sampled every `step`°. */
export function spot(peak: number, halfAngle: number, edge: number, step: number): Photometry {
  const angles: number[] = [];
  for (let g = 0; g <= 180 + 1e-9; g += step) angles.push(Number(g.toFixed(6)));
  const cd = angles.map((g) => (g <= halfAngle ? peak : g >= halfAngle + edge ? 0 : peak * (1 - (g - halfAngle) / edge)));
  return basePhotometry({ verticalAngles: angles, candela: [cd] });
}

export function loadIes(name: string): Photometry {
  return parsePhotometry(readFileSync(join(__dirname, '../../../public/ies', name)), name);
}

export function uniformRoom(width: number, height: number, depth: number, rho: number | [number, number, number]): BakeScene['room'] {
  return { width, height, depth, reflectance: Object.fromEntries(SURFACE_NAMES.map((s) => [s, rho])) as Record<SurfaceName, number> };
}

/** Σ E·A over all six surfaces (lm), from the maps' Y channel. */
export function totalFlux(maps: BakedMaps, kind: 'direct' | 'indirect' | 'total'): number {
  let flux = 0;
  for (const name of SURFACE_NAMES) {
    const m = maps[name];
    const a = texelArea(m.layout);
    for (const e of luxOf(m[kind])) flux += e * a;
  }
  return flux;
}

/** Area-weighted mean lux over all surfaces. */
export function averageLux(maps: BakedMaps, kind: 'direct' | 'indirect' | 'total'): number {
  let area = 0;
  for (const name of SURFACE_NAMES) area += maps[name].layout.lengthU * maps[name].layout.lengthV;
  return totalFlux(maps, kind) / area;
}

/** Every value finite and ≥ 0. */
export function allFiniteNonNegative(maps: BakedMaps): boolean {
  return SURFACE_NAMES.every((n) => (['direct', 'indirect', 'total'] as const).every((k) => maps[n][k].every((x) => Number.isFinite(x) && x >= 0)));
}

// Rotations written out independently of src/engines/bake (docs/scene-format.md: world = Ry(yaw)·Rx(pitch)·Ry(roll)·local),
// here as successive rotations of a vector with Rodrigues' formula.
function rotate(v: Vec3, axis: Vec3, deg: number): Vec3 {
  const t = (deg * Math.PI) / 180;
  const c = Math.cos(t);
  const s = Math.sin(t);
  const dot = axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2];
  const cross: Vec3 = [axis[1] * v[2] - axis[2] * v[1], axis[2] * v[0] - axis[0] * v[2], axis[0] * v[1] - axis[1] * v[0]];
  return [0, 1, 2].map((i) => v[i] * c + cross[i] * s + axis[i] * dot * (1 - c)) as Vec3;
}

/** World → local for a luminaire: undo yaw, then pitch, then roll. */
export function worldToLocal(v: Vec3, yaw: number, pitch: number, roll: number): Vec3 {
  return rotate(rotate(rotate(v, [0, 1, 0], -yaw), [1, 0, 0], -pitch), [0, 1, 0], -roll);
}

/** (γ, C) in degrees of a local direction (γ from −y, C from +x toward −z). */
export function anglesOf(l: Vec3): [number, number] {
  const n = Math.hypot(...l);
  const g = (Math.acos(Math.max(-1, Math.min(1, -l[1] / n))) * 180) / Math.PI;
  let c = (Math.atan2(-l[2], l[0]) * 180) / Math.PI;
  if (c < 0) c += 360;
  return [g, c];
}

/** Σ E·coverage·texel² over the objects' atlas (lm), from the Y channel. */
export function atlasFlux(maps: BakedMaps, kind: 'direct' | 'indirect' | 'total'): number {
  const o = maps.objects!;
  const lux = luxOf(o[kind]);
  let flux = 0;
  for (let i = 0; i < lux.length; i++) flux += lux[i] * o.atlas.position[4 * i + 3];
  return flux * o.atlas.texelSize * o.atlas.texelSize;
}

/** The objects' surface area the atlas covers (m²): Σ coverage·texel². */
export function atlasArea(maps: BakedMaps): number {
  const o = maps.objects!;
  let c = 0;
  for (let i = 0; i < o.atlas.width * o.atlas.height; i++) c += o.atlas.position[4 * i + 3];
  return c * o.atlas.texelSize * o.atlas.texelSize;
}
