/**
 * L3D bodies in the Radiance export (docs/radiance.md, docs/gldf.md "L3D in the 3D view"): the
 * imported GLDF track spot (buildGldf.ts with buildL3dSpot.ts) on the demo's single rail, as
 * polygons of one grey plastic, one a triangle, placed as the 3D view places it; the face the lens
 * is set in (the head's bottom cap, 24 triangles) left out so the source spheres are not buried.
 * Checked against the spot's parts worked out by hand: 12 + 36 + 96 + 12 housing triangles, heights
 * from the barn door's lowest corner (28.3 mm below the lens) to the adapter's top (128 mm above).
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { parseGldfMapping } from '../../../src/core/gldf/gldfMapping';
import { parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { BODY_REFLECTANCE, bodiesRad } from '../../../src/engines/radiance/bodiesRad';
import { fixturesFromConfiguration } from '../../../src/engines/view/fixtures';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { gldfBytes, MAPPING_TEXT, trackSpotSpec } from '../../core/gldf/buildGldf';
import { HEAD_SEGMENTS, SPOT } from '../../core/gldf/buildL3dSpot';
import { only, run, withPreset } from '../../core/model/helpers';

const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');
const imported = importGldfCatalog(base, [{ name: 'track-spot.gldf', bytes: gldfBytes(trackSpotSpec()) }], parseGldfMapping(MAPPING_TEXT, 'mapping.json'));
// Keyed as the bake feed keys them: the model with its emitter object (modelBodyKey).
const bodies = new Map([['geo/track-spot.l3d#lens', readL3dBody(imported.files.find((f) => f.path === 'geo/track-spot.l3d')!.bytes, 'geo/track-spot.l3d', 'lens')]]);

function spotOnRail() {
  let c = withPreset('single', 3, 3);
  c = run(c, 'addModule', { railId: only(c).rails[0].id, type: 'track-spot' }, imported.catalog);
  return fixturesFromConfiguration(c, imported.catalog, new Map(), bodies).modules;
}

/** The polygons of a .rad text: name and its vertices (Radiance X, Y, Z). */
function polygons(rad: string): { name: string; vertices: number[][] }[] {
  const lines = rad.split('\n');
  const out: { name: string; vertices: number[][] }[] = [];
  lines.forEach((l, i) => {
    const m = /^luminaire_body polygon (\S+)$/.exec(l);
    if (!m) return;
    expect(lines.slice(i + 1, i + 4)).toEqual(['0', '0', '9']);
    out.push({ name: m[1], vertices: lines.slice(i + 4, i + 7).map((v) => v.trim().split(' ').map(Number)) });
  });
  return out;
}

describe('L3D bodies as Radiance polygons', () => {
  it('writes every housing triangle of the spot but the face its lens is set in, in one grey plastic, at the module', () => {
    const modules = spotOnRail();
    const spot = modules.find((m) => m.body)!;
    const rad = bodiesRad(modules);
    expect(rad).toContain(`void plastic luminaire_body\n0\n0\n5 ${BODY_REFLECTANCE} ${BODY_REFLECTANCE} ${BODY_REFLECTANCE} 0 0`);
    const polys = polygons(rad);
    // adapter 12, yoke 3 boxes × 12, head 24-gon 4 × 24, barn door 12; less the head's bottom cap (24).
    expect(polys).toHaveLength(12 + 36 + 4 * HEAD_SEGMENTS + 12 - HEAD_SEGMENTS);
    expect(new Set(polys.map((p) => p.name)).size).toBe(polys.length);
    // Radiance (X, Y, Z) = luxbox (x, −z, y): heights from the barn door's lowest corner to the adapter's top.
    const zs = polys.flatMap((p) => p.vertices.map((v) => v[2] - spot.centre[1]));
    expect(Math.min(...zs)).toBeCloseTo(-SPOT.flapLength * Math.SQRT1_2, 5);
    expect(Math.max(...zs)).toBeCloseTo(SPOT.insert, 5);
    // In plan every vertex is within the hull's reach of the module's centre: ±42 mm along, −64…35 mm across.
    for (const p of polys) for (const v of p.vertices) expect(Math.hypot(v[0] - spot.centre[0], -v[1] - spot.centre[2])).toBeLessThanOrEqual(Math.hypot(0.042, 0.035 + 0.041 * Math.SQRT1_2) + 1e-5);
    // Nothing of the body lies in the lens's plane facing down any more (the sources' spheres sit there).
    const flatAtLens = polys.filter((p) => p.vertices.every((v) => Math.abs(v[2] - spot.centre[1]) < 1e-6));
    expect(flatAtLens).toEqual([]);
  });

  it('aimed, the body turns with the joints: tilted 60°, the head reaches below the lens plane', () => {
    let c = withPreset('single', 3, 3);
    c = run(c, 'addModule', { railId: only(c).rails[0].id, type: 'track-spot' }, imported.catalog);
    const id = only(c).rails[0].modules.find((m) => m.type === 'track-spot')!.id;
    c = run(c, 'setAim', { moduleId: id, aim: { rotation: 0, tilt: 60 } }, imported.catalog);
    const modules = fixturesFromConfiguration(c, imported.catalog, new Map(), bodies).modules;
    const spot = modules.find((m) => m.id === id)!;
    const zs = polygons(bodiesRad(modules)).flatMap((p) => p.vertices.map((v) => v[2] - spot.centre[1]));
    // The head (radius 35 mm, 80 mm long about a pivot 40 mm above the lens) tilted 60°: its lowest rim corner at
    // pivot − (40 cos 60° + 35 sin 60°) mm = 40 − 50.31 = −10.31 mm, below the barn door's corner there.
    expect(Math.min(...zs)).toBeLessThan(-0.0103);
  });

  it('modules without a body write nothing', () => {
    expect(bodiesRad(spotOnRail().filter((m) => !m.body))).toBe('');
  });
});
