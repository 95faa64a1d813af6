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
import { intensity } from '../../../src/core/photometry/intensity';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../../src/core/photometry/types';
import { frameMatrix } from '../../../src/engines/view/createRoomHardware';
import { buildLuminaireModel } from '../../../src/engines/view/luminaires/buildLuminaireModel';
import { modelHeight } from '../../../src/engines/view/luminaires/luminaireDimensions';
import { hemisphereFlux } from '../../../src/engines/view/luminaires/hemisphereFlux';
import { emitterPhotometry, GRAZING_LIMIT_DEG, luminanceToward } from '../../../src/engines/view/luminaires/viewLuminance';
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

const NO_TURN = { yaw: 0, pitch: 0, roll: 0 };

/** A Lambertian emitter of the lower hemisphere, I(γ) = I₀·cos γ (γ ≤ 90°), on a 2.5° grid. */
function lambertian(i0: number): Photometry {
  const verticalAngles = Array.from({ length: 73 }, (_, j) => j * 2.5);
  return {
    ...load('ies/bega_50975_downlight_lm1995_crlf.ies'),
    tilt: null,
    verticalAngles,
    horizontalAngles: [0],
    candela: [verticalAngles.map((g) => (g <= 90 ? i0 * Math.max(0, Math.cos((g * Math.PI) / 180)) : 0))],
  };
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
        const l = luminanceToward(emitterPhotometry(lambertian(500), NO_TURN), -1, model.emitterArea, [0, -1, 0]);
        expect(Number.isFinite(l) && l > 0).toBe(true);
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

describe('glow luminance toward the eye L = I(γ, C) / (A · cos θ)', () => {
  it('the halves of the flux add up to the whole (what tells a lighting scene luminaire its kind)', () => {
    for (const { ph, type } of catalogModels) {
      const flux = hemisphereFlux(ph);
      expect(flux.down + flux.up).toBeCloseTo(integrateFlux(ph), 6);
      if (type !== 'updown') expect(flux.up / (flux.down + flux.up)).toBeLessThan(0.01);
    }
  });

  it('a Lambertian face (I = I₀·cos γ) has L = I₀/A from every angle up to the grazing limit, then falls with I; its back is dark', () => {
    const e = emitterPhotometry(lambertian(500), NO_TURN);
    const A = 0.01;
    for (const g of [0, 20, 45, 70, 84]) {
      const r = (g * Math.PI) / 180;
      expect(luminanceToward(e, -1, A, [Math.sin(r), -Math.cos(r), 0]) / (500 / A)).toBeCloseTo(1, 2);
    }
    // Past 85° the projected area is floored at A·cos 85°: L = I₀·cos γ / (A·cos 85°), below I₀/A and → 0 at 90°.
    const r88 = (88 * Math.PI) / 180;
    const at88 = luminanceToward(e, -1, A, [Math.sin(r88), -Math.cos(r88), 0]);
    expect(at88 / ((500 * Math.cos(r88)) / (A * Math.cos((GRAZING_LIMIT_DEG * Math.PI) / 180)))).toBeCloseTo(1, 2);
    expect(at88).toBeLessThan(500 / A);
    expect(luminanceToward(e, -1, A, [1, 0, 0])).toBeLessThan(1e-9 * (500 / A));
    // Seen from above, the lower face shows nothing; the upper face of the same (downward) photometry shows I(γ > 90°) = 0.
    expect(luminanceToward(e, -1, A, [0, 1, 0])).toBe(0);
    expect(luminanceToward(e, 1, A, [0, 1, 0])).toBe(0);
    expect(luminanceToward(e, -1, 0, [0, -1, 0])).toBe(0);
    expect(luminanceToward(e, -1, A, [0, 0, 0])).toBe(0);
  });

  it('the narrow spot from below on its axis: I(0°)/A = 2.2 × 10⁶ cd/m², 60 × its mean Φ/(π·A); at 70° from the side 1.3 cd / (A·cos 70°)', () => {
    const narrow = catalogModels.find((m) => m.beam === 'narrow')!;
    const e = emitterPhotometry(narrow.ph, NO_TURN);
    const A = narrow.model.emitterArea;
    // The file's own rows (1° steps): 39 295.9 cd at 0°, 1.3 cd at 70°.
    expect(narrow.ph.candela[0][0]).toBeCloseTo(39295.9, 1);
    expect(narrow.ph.candela[0][70]).toBeCloseTo(1.3, 1);
    const axial = luminanceToward(e, -1, A, [0, -3, 0]);
    expect(axial / (39295.9 / (Math.PI * 0.075 ** 2))).toBeCloseTo(1, 4);
    const r = (70 * Math.PI) / 180;
    expect(luminanceToward(e, -1, A, [3 * Math.sin(r), -3 * Math.cos(r), 0]) / (1.3 / (A * Math.cos(r)))).toBeCloseTo(1, 4);
    const mean = hemisphereFlux(narrow.ph).down / (Math.PI * A);
    expect(axial / mean).toBeGreaterThan(55);
  });

  it('turned as the baker turns it: a spot pitched 30° toward +z shows its axial luminance to an eye on its aim, and its luminance at γ from there', () => {
    const narrow = catalogModels.find((m) => m.beam === 'narrow')!;
    const A = narrow.model.emitterArea;
    const e = emitterPhotometry(narrow.ph, { yaw: 0, pitch: 30, roll: 0 });
    // Rx(+30°) turns the nadir −y toward −z (luminaireRotation.ts).
    const r = (30 * Math.PI) / 180;
    expect(luminanceToward(e, -1, A, [0, -Math.cos(r), -Math.sin(r)]) / (intensity(narrow.ph, 0, 0) / A)).toBeCloseTo(1, 6);
    // Straight down is 30° off its axis.
    expect(luminanceToward(e, -1, A, [0, -1, 0]) / (intensity(narrow.ph, 30, 0) / (A * Math.cos(r)))).toBeCloseTo(1, 6);
  });
});

describe('the emitter on screen (three.js on headless-gl)', () => {
  const W = 16;
  const H = 16;
  const renderer = headlessRenderer(W, H);

  // A downlight (the BEGA 50975 file: 321 lm through a Ø 80 mm opening) at 2 m, seen from 10 cm below: the face fills the view.
  const ph = load('ies/bega_50975_downlight_lm1995_crlf.ies');
  const weight: Rgb = [0.5 * 1.2, 0.5 * 1.0, 0.5 * 0.7];
  const fixtures = oneLuminaire({ id: 'd1', kind: 'downlight', light: { photometry: ph, opening: ph.luminousOpening, flux: hemisphereFlux(ph), weight } });
  const pose = { position: [0, 1.9, 0.002] as Vec3, target: [0, 2, 0] as Vec3, fov: 30 };
  // The face lies 0.5 mm below the photometric centre (PROUD); the eye sees it 1.15° off the axis:
  // L = I(γ, 0)/(A·cos γ), I from the file, A the Ø 80 mm opening.
  const toEye = [pose.position[0], pose.position[1] - (2 - 0.0005), pose.position[2]];
  const gammaEye = Math.atan2(Math.hypot(toEye[0], toEye[2]), -toEye[1]);
  const L = intensity(ph, (gammaEye * 180) / Math.PI, 90) / (openingArea(ph.luminousOpening) * Math.cos(gammaEye));

  it('before the tone curve: the pixel is L toward the eye × weight × exposure (float target, identity adaptation)', () => {
    expect(L).toBeCloseTo(331 / (Math.PI * 0.04 ** 2), -3);
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

  /** The linear value (green, float target) of the centre pixel of a face of the narrow spot, housings hidden, seen from `eye`. */
  function narrowFacePixel(eye: Vec3): number {
    const narrow = catalogModels.find((m) => m.beam === 'narrow')!;
    const spot = oneLuminaire({ id: 'd1', kind: 'spot', light: { photometry: narrow.ph, opening: narrow.ph.luminousOpening, flux: hemisphereFlux(narrow.ph), weight: [1, 1, 1] } });
    // Looking up at the face with "up" along z, so a camera straight below the spot is well defined.
    const shot = linearHardwareShot(renderer, spot(true), { position: eye, target: [0, 2 - 0.0005, 0], fov: 10 }, 0.01, W, H, 1e-6, [0, 0, 1]);
    shot.hardware.group.traverse((o) => {
      const mat = (o as THREE.Mesh).material as THREE.ShaderMaterial | undefined;
      if (mat?.uniforms && mat.uniforms.uEmitter.value !== 1) o.visible = false;
    });
    const px = shot.render();
    shot.dispose();
    return px[((H / 2) * W + W / 2) * 4 + 1] / 1e-6;
  }

  it('the narrow spot from below on its axis against from the side at 60°: the ratio is I(0°)·cos 60° / I(60°) of its IES rows within 1 %', () => {
    const narrow = catalogModels.find((m) => m.beam === 'narrow')!;
    const [i0, i60] = [narrow.ph.candela[0][0], narrow.ph.candela[0][60]];
    expect([i0, i60]).toEqual([39295.9, 13.7]);
    const face = 2 - 0.0005;
    const below = narrowFacePixel([0, face - 0.6, 0]);
    const r = (60 * Math.PI) / 180;
    const side = narrowFacePixel([0.6 * Math.sin(r), face - 0.6 * Math.cos(r), 0]);
    // Each is its own I/(A·cos θ): A = π·0.075² (the Ø 150 mm opening).
    const A = Math.PI * 0.075 ** 2;
    expect(Math.abs(below / (i0 / A) - 1)).toBeLessThan(0.01);
    expect(Math.abs(side / (i60 / (A * Math.cos(r))) - 1)).toBeLessThan(0.01);
    expect(Math.abs(below / side / ((i0 * Math.cos(r)) / i60) - 1)).toBeLessThan(0.01);
  });

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
