/**
 * Objects in the GPU baker (issue #10, docs/baker.md "Objects: passes"): shadows of direct light,
 * the atlas as a seventh receiver, flux conservation with obstruction (CIE 171:2006 §5.4), the
 * closed-box interreflection law with an object inside (CIE 171:2006 §5.8 generalised: every
 * reflected lumen lands on some surface), and finite maps in contact cases. Analytic references
 * only; the independent CPU reference for furnished rooms is src/reference.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { probeScene } from '../../../src/engines/bake/probeMaps';
import { texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { boxMesh } from './objects/objectFixtures';
import { atlasArea, atlasFlux, isotropic, spot, totalFlux, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);

function box(id: string, w: number, h: number, d: number, base: Vec3, reflectance: number): BakeObject {
  return { id, mesh: boxMesh(w, h, d, reflectance), position: base, yaw: 0, scale: 1, reflectance };
}

function allFinite(maps: BakedMaps): boolean {
  const arrays = [...SURFACE_NAMES.flatMap((n) => [maps[n].direct, maps[n].indirect, maps[n].total])];
  if (maps.objects) arrays.push(maps.objects.direct, maps.objects.indirect, maps.objects.total);
  return arrays.every((a) => a.every((x) => Number.isFinite(x) && x >= 0));
}

describe('direct light with objects', () => {
  // 3 m cube, black; 100 cd isotropic point source 1 m above a 1 × 1 m plate 2 cm thick (top at y = 1.01).
  const I = 100;
  const source: Vec3 = [1.5, 2, 1.5];
  const scene: BakeScene = {
    room: uniformRoom(3, 3, 3, 0),
    luminaires: [{ photometry: isotropic(I), position: source, yaw: 0, pitch: 0, roll: 0 }],
    nearField: 'point',
  };
  const plate = box('plate', 1, 0.02, 1, [1.5, 0.99, 1.5], 0.5);
  const settings = { texelSize: 0.1, samples: 16, bounces: 0 };
  const furnished = baker.bake({ ...scene, objects: [plate] }, settings);
  const empty = baker.bake(scene, settings);

  it('floor texels in the umbra get exactly 0; outside the shadow they are unchanged', () => {
    const floor = furnished.maps.floor;
    const lux = luxOf(floor.direct);
    const emptyLux = luxOf(empty.maps.floor.direct);
    // The plate's top edge (half width 0.5 m, 0.99 m under the source) throws the umbra to |x − 1.5| < 0.5·2/0.99 = 1.01 m on the floor.
    const shadowHalf = (0.5 * 2) / 0.99;
    let inside = 0;
    let outside = 0;
    for (let j = 0; j < floor.layout.height; j++) {
      for (let i = 0; i < floor.layout.width; i++) {
        const [x, , z] = texelCentre(floor.layout, i, j);
        const reach = Math.max(Math.abs(x - 1.5), Math.abs(z - 1.5));
        const k = j * floor.layout.width + i;
        // A texel mean: the texel lies wholly inside (outside) the umbra when its centre is 0.1 m inside (outside) the edge.
        if (reach < shadowHalf - 0.1) {
          expect(lux[k]).toBe(0);
          inside++;
        } else if (reach > shadowHalf + 0.1) {
          expect(Math.abs(lux[k] - emptyLux[k])).toBeLessThanOrEqual(1e-6 * emptyLux[k]);
          outside++;
        }
      }
    }
    expect(inside).toBeGreaterThan(200);
    expect(outside).toBeGreaterThan(200);
  });

  it('the plate top gets I·cosθ/d² within 0.5 %; its sides and bottom get 0', () => {
    const o = furnished.maps.objects!;
    const lux = luxOf(o.direct);
    let top = 0;
    let worst = 0;
    for (let i = 0; i < o.atlas.width * o.atlas.height; i++) {
      if (o.atlas.position[4 * i + 3] <= 0) continue;
      const p = [0, 1, 2].map((a) => o.atlas.position[4 * i + a]);
      const n = [0, 1, 2].map((a) => o.atlas.normal[4 * i + a]);
      const d = [0, 1, 2].map((a) => source[a] - p[a]);
      const dist = Math.hypot(...d);
      const cos = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / dist;
      const expected = cos > 0 ? (I * cos) / (dist * dist) : 0;
      if (n[1] > 0.99) {
        top++;
        worst = Math.max(worst, Math.abs(lux[i] / expected - 1));
      } else expect(lux[i]).toBe(0);
    }
    console.info(`plate top: ${top} texels, worst |E/(I·cosθ/d²) − 1| = ${worst.toExponential(2)}`);
    expect(top).toBeGreaterThanOrEqual(100);
    expect(worst).toBeLessThan(0.005);
  });

  it('probe: direct light at a point is shadow-tested on the CPU as in the direct pass', () => {
    const withPlate = { ...scene, objects: [plate] };
    const [under, beside] = probeScene(withPlate, furnished.maps, settings, [
      [1.7, 0, 1.4],
      [2.8, 0, 0.3],
    ]);
    expect(under.direct).toBe(0);
    // Beside the shadow: I·cosθ/d² of the point source.
    const d = [2.8 - source[0], -source[1], 0.3 - source[2]];
    const dist = Math.hypot(...d);
    expect(Math.abs(beside.direct / ((I * source[1]) / dist ** 3) - 1)).toBeLessThan(1e-9);
  });

  it('the report lists the plate with its area, texels and flux', () => {
    const entry = furnished.report.objects!;
    expect(entry).toHaveLength(1);
    expect(entry[0].id).toBe('plate');
    expect(entry[0].area).toBeCloseTo(2 + 4 * 0.02, 6);
    expect(entry[0].flux).toBeCloseTo(atlasFlux(furnished.maps, 'total'), 3);
    expect(entry[0].maxLux).toBeGreaterThan(entry[0].meanLux);
  });
});

describe('CIE 171:2006 §5.4 flux conservation with obstruction: black room, black objects', () => {
  it('Σ E·A over the six walls and the atlas = Φ within 1 %', () => {
    const I = 1000 / (4 * Math.PI);
    const scene: BakeScene = {
      room: uniformRoom(3, 2.5, 3.5, 0),
      luminaires: [{ photometry: isotropic(I), position: [1.4, 1.6, 1.7], yaw: 0, pitch: 0, roll: 0 }],
      objects: [box('cabinet', 0.6, 1.2, 0.5, [0.6, 0, 0.6], 0), box('table', 1.2, 0.7, 0.8, [1.8, 0, 2.4], 0), box('shelf', 1.0, 0.03, 0.3, [1.5, 2.0, 0.2], 0)],
    };
    const { maps, report } = baker.bake(scene, { texelSize: 0.1, samples: 16, bounces: 2 });
    const walls = totalFlux(maps, 'direct');
    const objects = atlasFlux(maps, 'direct');
    console.info(`black room with 3 objects: walls ${walls.toFixed(1)} lm + objects ${objects.toFixed(1)} lm = ${(walls + objects).toFixed(1)} lm of 1000`);
    expect(objects).toBeGreaterThan(50);
    expect(Math.abs(walls + objects - 1000) / 1000).toBeLessThan(0.01);
    expect(report.indirectEnabled).toBe(false);
    expect(allFinite(maps)).toBe(true);
  });
});

describe('closed box with uniform ρ and an object of the same ρ: mean E = Φ/(S(1−ρ))', () => {
  for (const rho of [0.5, 0.8]) {
    it(`ρ = ${rho}`, () => {
      const phi = 1000;
      const scene: BakeScene = {
        room: uniformRoom(3, 2.5, 3, rho),
        luminaires: [{ photometry: isotropic(phi / (4 * Math.PI)), position: [1.5, 1.9, 1.5], yaw: 0, pitch: 0, roll: 0 }],
        objects: [box('block', 0.8, 0.9, 0.7, [1.2, 0, 1.4], rho)],
      };
      const { maps, report } = baker.bake(scene, { texelSize: 0.1, samples: 64, bounces: 4 });
      let wallArea = 0;
      for (const n of SURFACE_NAMES) wallArea += maps[n].layout.lengthU * maps[n].layout.lengthV;
      const objectArea = atlasArea(maps);
      const S = wallArea + objectArea;
      const mean = (totalFlux(maps, 'total') + atlasFlux(maps, 'total')) / S;
      const expected = phi / (S * (1 - rho));
      console.info(
        `ρ = ${rho}: mean E ${mean.toFixed(2)} lx vs Φ/(S(1−ρ)) = ${expected.toFixed(2)} lx (${((mean / expected - 1) * 100).toFixed(2)} %), S = ${wallArea.toFixed(2)} + ${objectArea.toFixed(3)} m², tail r ${report.tailRatio[0].toFixed(4)}`,
      );
      expect(Math.abs(mean / expected - 1)).toBeLessThan(0.03);
      expect(allFinite(maps)).toBe(true);
    });
  }
});

describe('stiff light with objects: bright patches shaded by an object, and gathered by the atlas', () => {
  it('narrow spot 15 cm from a ρ = 0.8 wall, a panel in front of the wall: closed-box law within 3 %, patches taken', () => {
    const phi = 1000;
    const beam = spot(1, 6, 2, 0.5);
    // Scale the spot to 1000 lm: Φ = 2π ∫ I(γ) sin γ dγ (trapezoid over the 0.5° grid).
    let unit = 0;
    const g = beam.verticalAngles;
    const cd = beam.candela[0];
    for (let k = 1; k < g.length; k++) {
      const a = (g[k - 1] * Math.PI) / 180;
      const b = (g[k] * Math.PI) / 180;
      unit += 0.5 * (cd[k - 1] * Math.sin(a) + cd[k] * Math.sin(b)) * (b - a) * 2 * Math.PI;
    }
    const scaled = { ...beam, candela: [cd.map((c) => (c * phi) / unit)] };
    const rho = 0.8;
    const scene: BakeScene = {
      room: uniformRoom(2.5, 2.4, 2, rho),
      // Aimed at the north wall (z = 0) from 15 cm.
      luminaires: [{ photometry: scaled, position: [1.2, 1.3, 0.15], yaw: 0, pitch: 90, roll: 0 }],
      objects: [box('panel', 1.0, 1.2, 0.05, [1.0, 0.3, 0.6], rho)],
    };
    const { maps, report } = baker.bake(scene, { texelSize: 0.1, samples: 64, bounces: 4 });
    let wallArea = 0;
    for (const n of SURFACE_NAMES) wallArea += maps[n].layout.lengthU * maps[n].layout.lengthV;
    const S = wallArea + atlasArea(maps);
    const direct = totalFlux(maps, 'direct') + atlasFlux(maps, 'direct');
    // The beam (6° half angle) makes a spot of 1.6 cm radius on the wall, finer than 8×8 sub-samples of a 0.1 m texel resolve:
    // the direct flux the maps hold is what the bounces start from, so it is the Φ of the law. The panel is behind the lamp:
    // it takes none of the beam (same direct flux as without it).
    const emptyDirect = totalFlux(baker.bake({ ...scene, objects: [] }, { texelSize: 0.1, samples: 16, bounces: 0 }).maps, 'direct');
    const mean = (totalFlux(maps, 'total') + atlasFlux(maps, 'total')) / S;
    const expected = direct / (S * (1 - rho));
    console.info(
      `stiff spot, panel: direct ${direct.toFixed(1)} lm (${phi} lm emitted), mean E ${mean.toFixed(2)} vs ${expected.toFixed(2)} lx (${((mean / expected - 1) * 100).toFixed(2)} %), ${report.brightPatches?.count} bright patches`,
    );
    expect(report.brightPatches!.count).toBeGreaterThan(0);
    expect(Math.abs(direct / emptyDirect - 1)).toBeLessThan(1e-4);
    expect(Math.abs(mean / expected - 1)).toBeLessThan(0.03);
    // The panel's side toward the lit wall catches the patch's light; its far side only later bounces.
    expect(report.objects![0].maxLux).toBeGreaterThan(report.objects![0].meanLux);
    expect(allFinite(maps)).toBe(true);
  });
});

describe('contact cases', () => {
  it('a lamp touching an object, an object touching two walls, one sunk 5 mm into the floor (within OBJECT_ROOM_TOLERANCE): every map finite and ≥ 0', () => {
    const scene: BakeScene = {
      room: uniformRoom(2, 2, 2, 0.6),
      luminaires: [
        // On the top face of the corner box (y = 0.4) and just inside the shelf.
        { photometry: isotropic(50), position: [1.8, 0.4, 0.2], yaw: 0, pitch: 0, roll: 0 },
        { photometry: isotropic(50), position: [0.3, 1.5, 0.1], yaw: 0, pitch: 0, roll: 0 },
      ],
      objects: [box('block', 0.6, 0.8, 0.6, [1.2, -0.005, 1.2], 0.7), box('shelf', 0.6, 0.04, 0.2, [0.3, 1.48, 0.1], 0.5), box('corner', 0.4, 0.4, 0.4, [1.8, 0, 0.2], 0.4)],
    };
    const { maps, report } = baker.bake(scene, { texelSize: 0.1, samples: 16, bounces: 2 });
    expect(allFinite(maps)).toBe(true);
    expect(report.objects!.every((o) => Number.isFinite(o.meanLux) && Number.isFinite(o.flux))).toBe(true);
    // The corner box's top texels around the lamp are lit (a source on the surface lights it from the front side).
    expect(report.objects!.find((o) => o.id === 'corner')!.maxLux).toBeGreaterThan(0);
    // The floor under the block gets no direct light, and its indirect light is only what the blur (radius 0.2 m) carries in from
    // the block's edges: every gather ray from under the block meets the block from inside.
    const floor = maps.floor;
    const direct = luxOf(floor.direct);
    const total = luxOf(floor.total);
    const meanTotal = total.reduce((a, b) => a + b, 0) / total.length;
    for (let j = 0; j < floor.layout.height; j++) {
      for (let i = 0; i < floor.layout.width; i++) {
        const [x, , z] = texelCentre(floor.layout, i, j);
        const under = Math.max(Math.abs(x - 1.2), Math.abs(z - 1.2));
        if (under < 0.2) expect(direct[j * floor.layout.width + i]).toBe(0);
        if (under < 0.1) expect(total[j * floor.layout.width + i]).toBeLessThan(0.1 * meanTotal);
      }
    }
  });
});
