/**
 * The L3D's light-emitting object as the near field's luminous opening (docs/gldf.md "The L3D's
 * opening in the near field"). The hand-made panel (buildL3dPanel.ts: a 0.6 × 0.3 m Rectangle) and
 * track spot (buildL3dSpot.ts: a Ø 50 mm Circle) give the opening's size and orientation; a
 * Lambertian photometry (I = I₀·cos γ) with that opening, split by the baker's pointSources, gives
 * the illuminance under the panel that the analytic form factor of a Lambertian rectangle gives
 * (Howell, *A Catalog of Radiation Heat Transfer Configuration Factors*, B-3: a differential area
 * parallel to a rectangle, its normal through a corner), where the header's point opening is 76 %
 * too high at 0.3 m; far away both tend to the point-source limit I₀/h².
 */
import { readFileSync } from 'node:fs';
import { validateXML } from 'xmllint-wasm';
import { describe, expect, it } from 'vitest';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { parseGldfMapping } from '../../../src/core/gldf/gldfMapping';
import { readL3dStructure } from '../../../src/core/gldf/readL3dStructure';
import { parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import { intensity } from '../../../src/core/photometry/intensity';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../../src/core/photometry/types';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { pointSources } from '../../../src/engines/bake/pointSources';
import { readL3dMeshes } from '../../../src/engines/meshImport/readL3dMeshes';
import { l3dBody } from '../../../src/engines/view/luminaires/l3dBody';
import { l3dOpening } from '../../../src/engines/view/luminaires/l3dOpening';
import { modelBodyKey } from '../../../src/engines/view/luminaires/modelBodyKey';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { withModelOpenings } from '../../../src/engines/view/modelOpenings';
import { gldfBytes, MAPPING_TEXT, trackSpotSpec } from '../../core/gldf/buildGldf';
import { panelL3d, panelStructure, type PanelOptions } from '../../core/gldf/buildL3dPanel';
import { spotL3d } from '../../core/gldf/buildL3dSpot';
import { only, run, withPreset } from '../../core/model/helpers';

const bodyOf = (bytes: Uint8Array) => {
  const { luminaire, zip } = readL3dStructure(bytes, 'test.l3d');
  return l3dBody(luminaire, readL3dMeshes(luminaire, zip).parts);
};
const panel = (o: PanelOptions = {}) => bodyOf(panelL3d(o));

/** A Lambertian emitter's intensity, I₀·cos γ below the horizon (1° rows), with the given opening. */
function lambertian(i0: number, opening: Photometry['luminousOpening']): Photometry {
  const verticalAngles = Array.from({ length: 181 }, (_, g) => g);
  return {
    format: 'IES',
    version: 'LM-63-2002',
    manufacturer: 'luxbox tests',
    luminaire: 'Lambertian panel',
    catalogNumber: '',
    keywords: {},
    photometricType: 'C',
    symmetry: 'rotational',
    verticalAngles,
    horizontalAngles: [0],
    candela: [verticalAngles.map((g) => (g < 90 ? i0 * Math.cos((g * Math.PI) / 180) : 0))],
    statedLumens: Math.PI * i0,
    absolute: false,
    inputWatts: null,
    luminousOpening: opening,
    warnings: [],
  };
}

/** Horizontal illuminance at (px, −h, pz) in the luminaire frame from the baker's point sources of the opening (5 cm cells, ≤ 8 a side). */
function splitIlluminance(ph: Photometry, px: number, h: number, pz: number): number {
  const points = pointSources(ph, 0.05, 8);
  let e = 0;
  for (const [x, , z] of points) {
    const d = [px - x, -h, pz - z];
    const r = Math.hypot(d[0], d[1], d[2]);
    const gamma = (Math.acos(h / r) * 180) / Math.PI;
    const c = (Math.atan2(-d[2], d[0]) * 180) / Math.PI;
    e += ((intensity(ph, gamma, c) / points.length) * (h / r)) / (r * r);
  }
  return e;
}

/** Howell B-3 times π·L: illuminance under the corner of an a × b Lambertian rectangle of luminance L at distance h (odd in a and b). */
function corner(L: number, a: number, b: number, h: number): number {
  const ah = Math.hypot(a, h);
  const bh = Math.hypot(b, h);
  return (L / 2) * ((a / ah) * Math.atan(b / ah) + (b / bh) * Math.atan(a / bh));
}

/** Illuminance at (px, −h, pz) under the Lambertian rectangle [x0, x1] × [z0, z1] at y = 0: four corner terms. */
function rectangleIlluminance(L: number, x0: number, x1: number, z0: number, z1: number, px: number, h: number, pz: number): number {
  return corner(L, x1 - px, z1 - pz, h) - corner(L, x0 - px, z1 - pz, h) - corner(L, x1 - px, z0 - pz, h) + corner(L, x0 - px, z0 - pz, h);
}

describe("the L3D's light-emitting object as the luminous opening", () => {
  it('the panel structure.xml validates against the official L3D schema (with and without LightEmittingSurfaces)', async () => {
    const schema = { fileName: 'l3d.xsd', contents: readFileSync('vendor/l3d/l3d.xsd', 'utf8') };
    for (const xml of [panelStructure(), panelStructure({ surfaces: true, turn: 90 })]) {
      const result = await validateXML({ xml: [{ fileName: 'structure.xml', contents: xml }], schema: [schema] });
      expect(result.errors).toEqual([]);
    }
  });

  it('size, shape and orientation: sizeX along the C0 axis (local x) unless the object or the beam is turned by 90°', () => {
    expect(l3dOpening(panel(), 0)).toEqual({ width: 0.6, length: 0.3, height: 0, shape: 'rectangular' });
    expect(l3dOpening(panel(), 90)).toEqual({ width: 0.3, length: 0.6, height: 0, shape: 'rectangular' });
    expect(l3dOpening(panel(), -90)).toEqual({ width: 0.3, length: 0.6, height: 0, shape: 'rectangular' });
    expect(l3dOpening(panel({ turn: 90 }), 0)).toEqual({ width: 0.3, length: 0.6, height: 0, shape: 'rectangular' });
    expect(l3dOpening(panel({ turn: 90 }), 90)).toEqual({ width: 0.6, length: 0.3, height: 0, shape: 'rectangular' });
    // 30° from the C0 axis is nearer 0° than 90°: not swapped; 60° is.
    expect(l3dOpening(panel({ turn: 30 }), 0).width).toBe(0.6);
    expect(l3dOpening(panel({ turn: 60 }), 0).width).toBe(0.3);
    expect(l3dOpening(bodyOf(spotL3d()), 0)).toEqual({ width: 0.05, length: 0.05, height: 0, shape: 'circular' });
  });

  it('the split opening gives the analytic illuminance of a Lambertian rectangle near it; far away both tend to the point source', () => {
    const i0 = 1000;
    const L = i0 / (0.6 * 0.3); // a flat Lambertian emitter's luminance: I₀ = L·A
    const fromL3d = lambertian(i0, l3dOpening(panel(), 0));
    const header = lambertian(i0, { width: 0, length: 0, height: 0, shape: 'point' });
    const analytic = (px: number, h: number, pz: number) => rectangleIlluminance(L, -0.3, 0.3, -0.15, 0.15, px, h, pz);
    // 0.3 m under the centre: 1.1334·L analytic; the point source says L·A/h² = 2·L.
    expect(analytic(0, 0.3, 0) / L).toBeCloseTo(1.1334, 3);
    expect(Math.abs(splitIlluminance(fromL3d, 0, 0.3, 0) / analytic(0, 0.3, 0) - 1)).toBeLessThan(0.01);
    expect(splitIlluminance(header, 0, 0.3, 0) / analytic(0, 0.3, 0)).toBeGreaterThan(1.7);
    // Off the axis, under the panel's corner region: along x (sizeX) and along z (sizeY).
    for (const [px, pz] of [
      [0.25, 0],
      [0, 0.12],
      [0.4, -0.2],
    ]) {
      expect(Math.abs(splitIlluminance(fromL3d, px, 0.3, pz) / analytic(px, 0.3, pz) - 1)).toBeLessThan(0.02);
    }
    // The same panel turned 90° in its L3D: the opening turns with it (sizeX along z).
    const turned = lambertian(i0, l3dOpening(panel({ turn: 90 }), 0));
    const turnedAnalytic = rectangleIlluminance(L, -0.15, 0.15, -0.3, 0.3, 0.25, 0.3, 0);
    expect(Math.abs(splitIlluminance(turned, 0.25, 0.3, 0) / turnedAnalytic - 1)).toBeLessThan(0.02);
    // 5 m away: the split within 0.05 % of the analytic value, and all three within 0.5 % of the point-source limit I₀/h²
    // (the panel's own cos⁴ fall-off over its half-size is 2·⟨r²⟩/h² ≈ 0.3 %).
    expect(Math.abs(splitIlluminance(fromL3d, 0, 5, 0) / analytic(0, 5, 0) - 1)).toBeLessThan(0.0005);
    for (const e of [splitIlluminance(fromL3d, 0, 5, 0), splitIlluminance(header, 0, 5, 0), analytic(0, 5, 0)]) expect(Math.abs(e / (i0 / 25) - 1)).toBeLessThan(0.005);
  });
});

describe('withModelOpenings: the bake scene of a configuration with an imported L3D spot', () => {
  const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');
  const imported = importGldfCatalog(base, [{ name: 'track-spot.gldf', bytes: gldfBytes(trackSpotSpec()) }], parseGldfMapping(MAPPING_TEXT, 'mapping.json'));
  const catalog = imported.catalog;
  const type = catalog.moduleTypes.find((t) => t.id === 'track-spot')!;
  const modelFile = imported.files.find((f) => f.path === type.model)!;
  const body = readL3dBody(modelFile.bytes, type.model!, type.modelEmitter);
  const medium = imported.files.find((f) => f.path === type.beams.find((b) => b.id === 'medium')!.photometry)!;
  const spotPhotometry = parsePhotometry(medium.bytes, medium.path);

  it("the spots' openings become the lens (Ø 50 mm), one photometry object for both; the demo's modules keep their header's", () => {
    let c = withPreset('single', 3, 3);
    const railId = only(c).rails[0].id;
    c = run(c, 'addModule', { railId, type: 'track-spot' }, catalog);
    c = run(c, 'addModule', { railId, type: 'track-spot' }, catalog);
    const scene = toLightingScene(c, catalog);
    const demo = parsePhotometry(readFileSync('public/ies/bega_50975_downlight_lm1995_crlf.ies'), 'demo.ies');
    const types = new Map(
      only(c)
        .rails.flatMap((r) => r.modules)
        .map((m) => [m.id, m.type]),
    );
    const ids = scene.luminaires.map((l) => l.id ?? '');
    const bake = {
      room: { width: 8, height: 3, depth: 6, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, east: 0.5, west: 0.5 } },
      luminaires: scene.luminaires.map((l) => ({ ...l, photometry: types.get(l.id ?? '') === 'track-spot' ? spotPhotometry : demo })),
    } as unknown as BakeScene;
    const out = withModelOpenings(bake, ids, c, catalog, new Map([[modelBodyKey(type)!, body]]));
    const spots = out.luminaires.filter((_, i) => types.get(ids[i]) === 'track-spot');
    expect(spots).toHaveLength(2);
    expect(spotPhotometry.luminousOpening).not.toEqual({ width: 0.05, length: 0.05, height: 0, shape: 'circular' });
    for (const s of spots) expect(s.photometry.luminousOpening).toEqual({ width: 0.05, length: 0.05, height: 0, shape: 'circular' });
    expect(spots[0].photometry).toBe(spots[1].photometry);
    // Everything else of the photometry is the file's.
    expect(spots[0].photometry.candela).toBe(spotPhotometry.candela);
    out.luminaires.forEach((l, i) => {
      if (types.get(ids[i]) !== 'track-spot') expect(l).toBe(bake.luminaires[i]);
    });
    // Without bodies (the file failed to load): the scene as it was.
    expect(withModelOpenings(bake, ids, c, catalog, new Map())).toBe(bake);
  });
});
