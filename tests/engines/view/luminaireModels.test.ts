/**
 * Luminaires you can see (docs/viewer.md, "Luminaires"): the models of each kind built from the
 * default catalog's real photometry (emitter area = luminous opening, finite meshes, bounded
 * triangle counts), the spot head's axis along the module's aim, L = Φ/(π·A), and on headless-gl
 * the emitter's pixel before the tone curve = L × weight × exposure, after it = the room's display
 * transform of that; lux mode and off modules do not glow.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import * as THREE from 'three';
import { headlessRenderer } from './headlessRenderer';
import { centreViewPixel, linearHardwareShot, oneLuminaire } from './glowShots';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { aimAxis } from '../../../src/core/model/modules/aim';
import type { Rgb, Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { integrateFlux } from '../../../src/core/photometry/flux';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../../src/core/photometry/types';
import { frameMatrix } from '../../../src/engines/view/createRoomHardware';
import { buildLuminaireModel } from '../../../src/engines/view/luminaires/buildLuminaireModel';
import { modelHeight } from '../../../src/engines/view/luminaires/luminaireDimensions';
import { emitterLuminance, hemisphereFlux } from '../../../src/engines/view/luminaires/emitterLuminance';
import { kindOfModuleType, LUMINAIRE_KINDS } from '../../../src/engines/view/luminaires/luminaireKind';
import { partArea, triangleCount, type LuminaireModel } from '../../../src/engines/view/luminaires/luminaireModel';
import { displayColor } from '../../../src/engines/view/toneMap';

const photometry = new Map<string, Photometry>();
function load(path: string): Photometry {
  let ph = photometry.get(path);
  if (!ph) {
    ph = parsePhotometry(readFileSync(join(__dirname, '../../../public', path)), path);
    photometry.set(path, ph);
  }
  return ph;
}

/** Every module type × beam of the default catalog with its model. */
const catalogModels = defaultCatalog.moduleTypes.flatMap((type) =>
  type.beams.map((beam) => {
    const ph = load(beam.photometry);
    const kind = kindOfModuleType(type);
    const model = buildLuminaireModel({ kind, opening: ph.luminousOpening, length: type.length, mount: modelHeight({ kind, opening: ph.luminousOpening, length: type.length }) + 0.05 });
    return { type: type.id, beam: beam.id, ph, kind, model };
  }),
);

function openingArea(o: Photometry['luminousOpening']): number {
  const round = ['circular', 'elliptical', 'spherical', 'cylindrical'].includes(o.shape);
  return round ? (Math.PI * o.width * o.length) / 4 : o.width * o.length;
}

describe('luminaire models of the default catalog', () => {
  it('maps each module type to its kind', () => {
    expect(Object.fromEntries(defaultCatalog.moduleTypes.map((t) => [t.id, kindOfModuleType(t)]))).toEqual({
      spot: 'spot',
      'spot-warmdim': 'spot',
      flood: 'spot',
      linear: 'linear',
      washer: 'washer',
      updown: 'pendant',
    });
  });

  it("emitter area = the photometry's luminous opening (model and mesh), every vertex and normal finite, triangles bounded", () => {
    for (const { type, beam, ph, model } of catalogModels) {
      const area = openingArea(ph.luminousOpening);
      expect(area, `${type}/${beam}`).toBeGreaterThan(0);
      expect(model.emitterArea).toBeCloseTo(area, 12);
      // Each emitting face's mesh has exactly that area (the n-gon's radii are scaled to the ellipse's area).
      expect(partArea(model, 'emitter', -1) / area).toBeCloseTo(1, 5);
      if (type === 'updown') expect(partArea(model, 'emitter', 1) / area).toBeCloseTo(1, 5);
      for (const p of model.parts) {
        expect(p.positions.every(Number.isFinite)).toBe(true);
        expect(p.normals.every(Number.isFinite)).toBe(true);
        for (let i = 0; i < p.normals.length; i += 3) expect(Math.hypot(p.normals[i], p.normals[i + 1], p.normals[i + 2])).toBeCloseTo(1, 5);
        expect(Math.max(...p.indices)).toBeLessThan(p.positions.length / 3);
      }
      expect(triangleCount(model), `${type}/${beam}`).toBeLessThanOrEqual(600);
      expect(triangleCount(model)).toBeGreaterThanOrEqual(12);
    }
  });

  it('a point opening (no area in the file) and no photometry at all: a drawn face of positive area, finite, for every kind', () => {
    for (const kind of LUMINAIRE_KINDS) {
      for (const opening of [{ width: 0, length: 0, height: 0, shape: 'point' as const }, null]) {
        const model = buildLuminaireModel({ kind, opening, length: 0.15, mount: 0.3 });
        expect(model.emitterArea).toBeGreaterThan(0);
        expect(partArea(model, 'emitter', -1) / model.emitterArea).toBeCloseTo(1, 5);
        for (const p of model.parts) expect(p.positions.every(Number.isFinite)).toBe(true);
        const l = emitterLuminance({ down: 500, up: 0 }, model.emitterArea);
        expect(Number.isFinite(l.down) && l.down > 0).toBe(true);
      }
    }
  });
});

/** The centre of a part's bounding box (the head's cylinder and its face are symmetric about their axis). */
function centroid(p: LuminaireModel['parts'][number]): THREE.Vector3 {
  return new THREE.Box3().setFromArray(p.positions).getCenter(new THREE.Vector3());
}

describe('the spot head turns with the aim', () => {
  it("the head's axis (from its cylinder's centre through its emitter) points along aimAxis(heading, aim) within 0.5°; the yoke turns about the vertical only", () => {
    const ph = load('ies/bega_84693_narrow_spot.ies');
    const model = buildLuminaireModel({ kind: 'spot', opening: ph.luminousOpening, length: 0.15, mount: 0.3 });
    const head = model.parts.find((p) => p.role === 'housing' && p.frame === 'aim')!;
    const face = model.parts.find((p) => p.role === 'emitter')!;
    let worst = 0;
    for (const heading of [0, 90, 217]) {
      for (const tilt of [0, 15, 40, 90]) {
        for (const rotation of [0, 30, 180, 355]) {
          // The orientation the lighting scene (hence the baker) gives the aimed module, beam roll 0 (aim.ts).
          const a = heading + rotation;
          const orientation = tilt === 0 ? { yaw: a, pitch: 0, roll: 0 } : { yaw: a - 90, pitch: tilt, roll: 90 };
          const m = { centre: [1, 2, 3] as Vec3, heading, orientation };
          const world = frameMatrix('aim', m, model);
          const axis = centroid(face).applyMatrix4(world).sub(centroid(head).applyMatrix4(world)).normalize();
          const want = new THREE.Vector3(...aimAxis(heading, { rotation, tilt }));
          const angle = (axis.angleTo(want) * 180) / Math.PI;
          worst = Math.max(worst, angle);
          expect(angle, `heading ${heading}, rotation ${rotation}, tilt ${tilt}`).toBeLessThan(0.5);
          // The emitter's normal agrees with it too.
          const n = new THREE.Vector3(face.normals[0], face.normals[1], face.normals[2]).transformDirection(world);
          expect((n.angleTo(want) * 180) / Math.PI).toBeLessThan(0.5);
          // The yoke (frame 'swivel') keeps its arms level: its x axis stays horizontal.
          const x = new THREE.Vector3(1, 0, 0).transformDirection(frameMatrix('swivel', m, model));
          expect(Math.abs(x.y)).toBeLessThan(1e-12);
        }
      }
    }
    expect(worst).toBeLessThan(1e-3);
  });
});

describe("a standing spot (a lighting scene's luminaire in the lower half of the room)", () => {
  it('its yoke is below the head, its base plate on the floor, the head still turns about its pivot', () => {
    const ph = load('ies/erco_kubus_floor_washlight.ies');
    const model = buildLuminaireModel({ kind: 'spot', opening: ph.luminousOpening, length: 0.12, mount: 0, stand: 0.1 });
    const bottom = Math.min(...model.parts.flatMap((p) => Array.from(p.positions.filter((_, i) => i % 3 === 1))));
    expect(bottom).toBeCloseTo(-0.1, 6);
    for (const p of model.parts) expect(p.positions.every(Number.isFinite)).toBe(true);
    const top = Math.max(...model.parts.filter((p) => p.frame !== 'aim').flatMap((p) => Array.from(p.positions.filter((_, i) => i % 3 === 1))));
    // Nothing of the yoke reaches above the pivot by more than its boss.
    expect(top).toBeLessThanOrEqual(model.pivot[1] + 0.021);
  });
});

describe('glow luminance L = Φ / (π·A)', () => {
  it('per hemisphere, from the integrated flux; the halves add up to the whole; zero area or flux gives 0', () => {
    for (const { ph, model, type } of catalogModels) {
      const flux = hemisphereFlux(ph);
      expect(flux.down + flux.up).toBeCloseTo(integrateFlux(ph), 6);
      const l = emitterLuminance(flux, model.emitterArea);
      expect(l.down).toBeCloseTo(flux.down / (Math.PI * model.emitterArea), 6);
      if (type !== 'updown') expect(flux.up / (flux.down + flux.up)).toBeLessThan(0.01);
    }
    // The narrow spot: 2047 lm through a Ø 0.15 m opening → 2047.1 / (π · π · 0.075²) = 36 872 cd/m².
    const narrow = catalogModels.find((m) => m.beam === 'narrow')!;
    expect(emitterLuminance(hemisphereFlux(narrow.ph), narrow.model.emitterArea).down).toBeCloseTo(2047.112 / (Math.PI * Math.PI * 0.075 ** 2), 0);
    expect(emitterLuminance({ down: 100, up: 0 }, 0)).toEqual({ down: 0, up: 0 });
    expect(emitterLuminance({ down: 0, up: 0 }, 0.01)).toEqual({ down: 0, up: 0 });
    expect(emitterLuminance({ down: NaN, up: Infinity }, 0.01)).toEqual({ down: 0, up: 0 });
  });
});

describe('the emitter on screen (three.js on headless-gl)', () => {
  const W = 16;
  const H = 16;
  const renderer = headlessRenderer(W, H);

  // A downlight (the BEGA 50975 file: 321 lm through a Ø 80 mm opening) at 2 m, seen from 10 cm below: the face fills the view.
  const ph = load('ies/bega_50975_downlight_lm1995_crlf.ies');
  const weight: Rgb = [0.5 * 1.2, 0.5 * 1.0, 0.5 * 0.7];
  const fixtures = oneLuminaire({ id: 'd1', kind: 'downlight', light: { opening: ph.luminousOpening, flux: hemisphereFlux(ph), weight } });
  const L = hemisphereFlux(ph).down / (Math.PI * openingArea(ph.luminousOpening));
  const pose = { position: [0, 1.9, 0.002] as Vec3, target: [0, 2, 0] as Vec3, fov: 30 };

  it('before the tone curve: the pixel is L × weight × exposure (float target, identity adaptation)', () => {
    expect(L).toBeCloseTo(321.25 / (Math.PI * Math.PI * 0.04 ** 2), -1);
    const shot = linearHardwareShot(renderer, fixtures(true), pose, 0.01, W, H, 2.5e-5);
    const px = shot.render();
    const centre = ((H / 2) * W + W / 2) * 4;
    for (let k = 0; k < 3; k++) expect(px[centre + k] / (L * weight[k] * 2.5e-5)).toBeCloseTo(1, 5);
    // Dimmed to 0 by a relight: black, not NaN.
    shot.hardware.setModuleWeights(new Map([['d1', [0, 0, 0]]]));
    const dimmed = shot.render();
    expect([dimmed[centre], dimmed[centre + 1], dimmed[centre + 2]]).toEqual([0, 0, 0]);
    shot.dispose();
  });

  const centrePixel = (setup: Parameters<typeof centreViewPixel>[4]) => centreViewPixel(renderer, pose, W, H, setup);

  it("on screen: the room's display transform of that (exposure from the shared uniforms); off and in lux mode it does not glow", () => {
    // An exposure that puts the face at linear 0.3 in green: on the curve's shoulder-free part.
    const exposure = 0.3 / (L * weight[1]);
    const on = centrePixel((v) => {
      v.setFixtures(fixtures(true));
      v.setExposure(exposure);
    });
    const want = displayColor([L * weight[0], L * weight[1], L * weight[2]], exposure).map((c) => c * 255);
    for (let k = 0; k < 3; k++) expect(Math.abs(on[k] - want[k])).toBeLessThanOrEqual(1.01);
    // Twice the exposure: brighter (the glow shares the room's exposure).
    const brighter = centrePixel((v) => {
      v.setFixtures(fixtures(true));
      v.setExposure(2 * exposure);
    });
    expect(brighter[1]).toBeGreaterThan(on[1] + 20);
    // Switched off: the face is dark (no room light yet: the housing's ambient is 0).
    expect(
      centrePixel((v) => {
        v.setFixtures(fixtures(false));
        v.setExposure(exposure);
      }),
    ).toEqual([0, 0, 0]);
    // Lux mode: the face shows the housing's flat colour, no glow.
    const lux = centrePixel((v) => {
      v.setFixtures(fixtures(true));
      v.setExposure(exposure);
      v.setMode('lux', [10, 100]);
    });
    expect(Math.max(...lux)).toBeLessThan(60);
    expect(Math.abs(lux[0] - lux[1])).toBeLessThanOrEqual(2);
  });
});
