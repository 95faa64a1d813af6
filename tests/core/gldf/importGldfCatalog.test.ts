/**
 * GLDF → rail catalog (docs/gldf.md): three products built from the repository's own
 * photometry (buildGldf.ts) imported into the demo catalog with a mapping file. The module
 * types must equal the hand-written ones below; every variant's rated flux is compared with the
 * flux integrated from its photometry (integrateFlux) and the report states each difference.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { formatImportReport } from '../../../src/core/gldf/gldfImportReport';
import { parseGldfMapping, type GldfMapping } from '../../../src/core/gldf/gldfMapping';
import { parseCatalog, parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { type ModuleTypeSpec } from '../../../src/core/model/catalogSchema/moduleTypeSchema';
import { billOfMaterials } from '../../../src/core/model/power/billOfMaterials';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import { integrateFlux, parsePhotometry } from '../../../src/core/photometry';
import { only, run, withPreset } from '../model/helpers';
import { spotL3d } from './buildL3dSpot';
import { changeablePendantXml, gldfBytes, ies, linearSpec, MAPPING_TEXT, pendantSpec, trackSpotSpec } from './buildGldf';

const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');

const spotBeam = (id: string, file: string, ext: string, angle: number, lumens: number, watts: number, price: number, article: string, labels: Record<string, string>): ModuleTypeSpec['beams'][number] => ({
  id,
  label: labels.en,
  labels,
  beamAngle: angle,
  article,
  photometry: `ies/track-spot-${id}.${ext}`,
  lumens,
  watts,
  roll: 0,
  price,
  source: `GLDF track-spot.gldf, variant v-${file}-3000 (LTL-TS-${file.toUpperCase()}-30): rated ${lumens} lm, ${watts} W, CRI 90`,
});

/** What the three GLDF files must become, written by hand from the specs in buildGldf.ts. */
const EXPECTED: ModuleTypeSpec[] = [
  {
    id: 'track-spot',
    name: 'Track spot',
    names: { en: 'Track spot', de: 'Schienenstrahler', fr: 'Spot sur rail', it: 'Faretto a binario' },
    length: 0.15,
    ccts: [2700, 3000, 4000],
    defaultCct: 3000,
    beams: [
      // Beam angles: half-peak full angles of the files (BEGA 84693 10.1°, Arcos 3 26.8°, BEGA 50975 54.4°; docs/catalog-format.md).
      spotBeam('narrow', 'narrow', 'ies', 10, 2044, 43, 199, 'LTL-TS-N', { en: 'Narrow spot', de: 'Enger Spot', fr: 'Spot étroit', it: 'Spot stretto' }),
      spotBeam('medium', 'medium', 'ldt', 27, 758, 28, 189, 'LTL-TS-M', { en: 'Medium spot', de: 'Mittlerer Spot', fr: 'Spot moyen', it: 'Spot medio' }),
      spotBeam('wide', 'wide', 'ies', 54, 321, 9, 179, 'LTL-TS-W', { en: 'Wide flood', de: 'Breiter Fluter', fr: 'Flood large', it: 'Flood largo' }),
    ],
    defaultBeam: 'medium',
    filterHolder: true,
    adjustable: { tilt: { min: 0, max: 90, stops: 5 }, rotation: { min: 0, max: 355, stops: 5 } },
    // The hand-made L3D (buildL3dSpot.ts), byte for byte.
    model: 'geo/track-spot.l3d',
    modelEmitter: 'lens',
  },
  {
    // No mapping: every default applies (and is reported below).
    id: 'ltl-pendant',
    name: 'Pendant direct/indirect',
    names: { en: 'Pendant direct/indirect', fr: 'Suspension directe/indirecte' },
    length: 0.15,
    ccts: [3000, 4000],
    defaultCct: 3000,
    beams: [
      {
        id: 'ph-pendant',
        label: 'ph-pendant',
        article: 'LTL-PD',
        photometry: 'ies/ltl-pendant-ph-pendant.ies',
        lumens: 5300,
        watts: 63.7,
        roll: 0,
        price: 349,
        source: 'GLDF pendant.gldf, variant pd-3000 (LTL-PD-30): rated 5300 lm, 63.7 W, CRI 90',
      },
    ],
    defaultBeam: 'ph-pendant',
  },
  {
    id: 'linear-600',
    name: 'Linear module 600',
    names: { en: 'Linear module 600', de: 'Linearmodul 600', it: 'Modulo lineare 600' },
    length: 0.6,
    ccts: [3000, 4000],
    defaultCct: 3000,
    beams: [
      {
        id: 'opal',
        label: 'Opal diffuser',
        labels: { en: 'Opal diffuser', de: 'Opal-Diffusor' },
        beamAngle: 85,
        article: 'LTL-LN600',
        photometry: 'ies/linear-600-opal.ldt',
        lumens: 2840,
        watts: 32.7,
        roll: 90,
        price: 229,
        source: 'GLDF linear.gldf, variant ln-3000 (LTL-LN600-30): rated 2840 lm, 32.7 W, CRI 90',
      },
    ],
    defaultBeam: 'opal',
  },
];

function runImport(mapping: GldfMapping | null = parseGldfMapping(MAPPING_TEXT, 'mapping.json')) {
  return importGldfCatalog(
    base,
    [
      { name: 'track-spot.gldf', bytes: gldfBytes(trackSpotSpec()) },
      { name: 'pendant.gldf', bytes: gldfBytes(pendantSpec()) },
      { name: 'linear.gldf', bytes: gldfBytes(linearSpec()) },
    ],
    mapping,
    'default-catalog.json',
  );
}

describe('GLDF import into the rail catalog', () => {
  const result = runImport();

  it('makes one module type per product, equal to the hand-written catalog, after the base catalog’s types', () => {
    expect(result.catalog.moduleTypes.slice(0, base.moduleTypes.length)).toEqual(base.moduleTypes);
    expect(result.catalog.moduleTypes.slice(base.moduleTypes.length)).toEqual(EXPECTED);
    // The result is a catalog like any other: it validates, and the rest is the base's.
    expect(parseCatalog(JSON.parse(JSON.stringify(result.catalog)))).toEqual(result.catalog);
    expect({ ...result.catalog, moduleTypes: [] }).toEqual({ ...base, moduleTypes: [] });
  });

  it('writes each beam’s photometry byte for byte from the container, and the product picture', () => {
    const byPath = new Map(result.files.map((f) => [f.path, f.bytes]));
    expect([...byPath.keys()]).toEqual(['ies/track-spot-narrow.ies', 'ies/track-spot-medium.ldt', 'ies/track-spot-wide.ies', 'geo/track-spot.l3d', 'images/track-spot.png', 'ies/ltl-pendant-ph-pendant.ies', 'ies/linear-600-opal.ldt']);
    expect(byPath.get('ies/track-spot-medium.ldt')).toEqual(ies('zumtobel_arcos3_spot_isym1.ldt'));
    expect(byPath.get('ies/linear-600-opal.ldt')).toEqual(ies('zumtobel_sloin_linear_isym4.ldt'));
    expect(byPath.get('geo/track-spot.l3d')).toEqual(spotL3d());
    for (const t of EXPECTED) for (const b of t.beams) expect(byPath.has(b.photometry)).toBe(true);
  });

  it('every variant’s rated flux against its photometry’s integrated flux: within 5 % where the numbers agree, the difference reported where not', () => {
    const spot = result.report.products[0];
    expect(spot.flux).toHaveLength(9);
    for (const f of result.report.products.flatMap((p) => p.flux)) {
      // Independent of the importer: integrate the file again and compare with the GLDF's rated flux.
      const file = f.photometry.replace(/^ldc\//, '');
      const integrated = integrateFlux(parsePhotometry(ies(file), file));
      expect(f.integratedFlux).toBeCloseTo(integrated, 6);
      const diff = ((integrated - f.ratedFlux) / f.ratedFlux) * 100;
      expect(f.differencePercent).toBeCloseTo(diff, 6);
      // The photometry parser's tolerance for a luminaire's own lumens is 5 % (docs/photometry.md).
      expect(f.warning === null).toBe(Math.abs(diff) <= 5);
    }
    // The 3000 K ratings are the files' own lumens: within 0.3 %.
    for (const f of spot.flux.filter((x) => x.variant.endsWith('-3000'))) expect(Math.abs(f.differencePercent)).toBeLessThan(0.3);
    // 2700 K is rated 7 % lower than the one photometry all CCTs share: reported, with the number.
    const warm = spot.flux.find((x) => x.variant === 'v-narrow-2700');
    expect(warm?.ratedFlux).toBe(1901);
    expect(warm?.differencePercent).toBeCloseTo(((2047.1 - 1901) / 1901) * 100, 1);
    expect(warm?.warning).toMatch(/differ by 7\.\d+ %/);
    const linear = result.report.products[2].flux.find((x) => x.variant === 'ln-4000');
    expect(linear?.differencePercent).toBeCloseTo(-5.25, 1);
    expect(formatImportReport(result.report)).toMatch(/flux ln-4000 \(ldc\/zumtobel_sloin_linear_isym4\.ldt\): rated 3000 lm, integrated 2842\.5 lm \(-5\.3 %\): /);
  });

  it('reports every variant imported with its own article number and GTIN, every variant skipped and why', () => {
    const [spot, pendant, linear] = result.report.products;
    expect(spot.imported.map((v) => `${v.variant} ${v.productNumber} ${v.gtin} ${v.beam} ${v.cct} ${v.cri}`)).toContain('v-medium-4000 LTL-TS-MEDIUM-40 4000000001058 medium 4000 80');
    expect(spot.imported).toHaveLength(9);
    expect(spot.skipped).toEqual([]);
    expect(pendant.skipped).toEqual([{ variant: 'pd-wall-3000', reason: 'mounting wall-surface does not fit the rail (ceiling-surface, ceiling-pendant)' }]);
    expect(linear.skipped).toEqual([{ variant: 'ln-rec-3000', reason: 'mounting ceiling-recessed does not fit the rail (ceiling-surface, ceiling-pendant)' }]);
    expect(linear.imported.map((v) => v.variant)).toEqual(['ln-4000', 'ln-3000']);
  });

  it('lists every value it assumed: all of them for the unmapped pendant, only the unmapped ones for the spot', () => {
    const [spot, pendant, linear] = result.report.products;
    expect(pendant.assumed.map((a) => `${a.field} = ${a.value}`)).toEqual([
      'id = ltl-pendant',
      'defaultCct = 3000 K',
      'beam ph-pendant id = ph-pendant',
      'beam ph-pendant label = ph-pendant',
      'beam ph-pendant article = LTL-PD',
      'beam ph-pendant roll = 0°',
      'defaultBeam = ph-pendant',
      'length = 0.15 m',
      'adjustable = fixed, straight down',
      'filterHolder = none',
    ]);
    // The pendant's price is its GLDF ListPrice in the catalog's currency: not assumed.
    expect(pendant.assumed.some((a) => a.field.endsWith('price'))).toBe(false);
    expect(spot.assumed.map((a) => a.field)).toEqual(['beam narrow roll', 'beam medium roll', 'beam wide roll']);
    expect(linear.assumed.map((a) => `${a.field} = ${a.value}`)).toEqual(['beam opal article = LTL-LN600', 'defaultBeam = opal', 'adjustable = fixed, straight down', 'filterHolder = none']);
  });

  it('a light source without a CCT is taken as 3000 K, and the report says so', () => {
    const spec = pendantSpec();
    delete spec.lightSources[0].cct;
    spec.variants = spec.variants.slice(0, 1);
    const r = importGldfCatalog(base, [{ name: 'pendant.gldf', bytes: gldfBytes(spec) }], null);
    expect(r.catalog.moduleTypes.find((t) => t.id === 'ltl-pendant')?.ccts).toEqual([3000]);
    expect(r.report.products[0].assumed).toContainEqual({ field: 'CCT of pd-3000', value: '3000 K', why: 'its light source states no CorrelatedColorTemperature' });
  });

  it('without a mapping file the documented defaults apply and validate', () => {
    const bare = runImport(null);
    const spot = bare.catalog.moduleTypes.find((t) => t.id === 'ltl-track-spot');
    expect(spot?.beams.map((b) => [b.id, b.price, b.roll])).toEqual([
      ['ph-narrow', 0, 0],
      ['ph-medium', 0, 0],
      ['ph-wide', 0, 0],
    ]);
    // The L3D's joints give the ranges: tilt 0–90° in 5° steps, the swivel's −170…170° as a 340° span in 1° steps; noted, not assumed.
    expect(spot?.adjustable).toEqual({ tilt: { min: 0, max: 90, stops: 5 }, rotation: { min: 0, max: 340, stops: 1 } });
    expect(bare.report.products[0].assumed.find((a) => a.field === 'adjustable')).toBeUndefined();
    expect(bare.report.products[0].notes).toContain('aiming from the joints of geo/track-spot.l3d: tilt 0–90° in 5° stops, rotation 0–340° in 1° stops');
    // Without the L3D, GLDF Adjustability 'Cardanic' gives no angles: the demo spot's ranges, reported.
    const plain = trackSpotSpec();
    const noModel = importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes({ ...plain, variants: plain.variants.map(({ model: _model, ...v }) => v) }) }], null);
    expect(noModel.catalog.moduleTypes.find((t) => t.id === 'ltl-track-spot')?.adjustable).toEqual({ tilt: { min: 0, max: 90 }, rotation: { min: 0, max: 355 } });
    expect(noModel.catalog.moduleTypes.find((t) => t.id === 'ltl-track-spot')?.model).toBeUndefined();
    expect(noModel.report.products[0].assumed.find((a) => a.field === 'adjustable')?.why).toMatch(/Cardanic/);
    expect(bare.catalog.moduleTypes.find((t) => t.id === 'ltl-linear-600')?.length).toBe(0.6); // from ProductSize 600 mm
  });

  it('a product imported again replaces the base catalog’s type of the same id, and says so', () => {
    const again = importGldfCatalog(result.catalog, [{ name: 'linear.gldf', bytes: gldfBytes(linearSpec()) }], parseGldfMapping(MAPPING_TEXT, 'mapping.json'));
    expect(again.catalog.moduleTypes.map((t) => t.id)).toEqual(result.catalog.moduleTypes.map((t) => t.id));
    expect(again.report.products[0].replaced).toBe(true);
    expect(again.report.unusedMapping).toEqual(['products.LTL-TRACK-SPOT: no imported file holds that product']);
  });

  it('the imported catalog drives the configurator: a track spot on the demo’s single rail, in the bill of materials and the lighting scene', () => {
    const cat = result.catalog;
    let c = withPreset('single', 3, 3);
    const railId = only(c).rails[0].id;
    c = run(c, 'addModule', { railId, type: 'track-spot' }, cat);
    const added = only(c).rails[0].modules.find((m) => m.type === 'track-spot');
    expect(added).toMatchObject({ beam: 'medium', cct: 3000 });
    c = run(c, 'setModuleBeam', { moduleId: added?.id, beam: 'narrow' }, cat);
    c = run(c, 'setModuleCct', { moduleId: added?.id, cct: 2700 }, cat);
    const line = billOfMaterials(c, cat).lines.find((l) => l.article === 'LTL-TS-N-2700');
    expect(line).toMatchObject({ count: 1, unitPrice: 199, kind: 'module' });
    const lum = toLightingScene(c, cat).luminaires.find((l) => l.id === added?.id);
    expect(lum?.photometry).toBe('ies/track-spot-narrow.ies');
  });

  it('changeable lamps: flux is the lamps’ (2 × 2900 lm), power the equipment’s, and the flux check is the light output ratio', () => {
    const r = importGldfCatalog(base, [{ name: 'pendant-t5.gldf', bytes: gldfBytes(pendantSpec(), {}, changeablePendantXml()) }], null);
    const type = r.catalog.moduleTypes.find((t) => t.id === 'ltl-pendant');
    expect(type?.beams.map((b) => [b.lumens, b.watts])).toEqual([[5800, 63.7]]);
    expect(type?.ccts).toEqual([3000, 4000]);
    const flux = r.report.products[0].flux;
    expect(flux.map((f) => f.kind)).toEqual(['lamp', 'lamp']);
    // Ledalite's file: 5296.7 lm from 5800 lamp lumens, a light output ratio of 0.913: within the lamp rule (0.1–1.05).
    expect(flux[0].differencePercent).toBeCloseTo(((5296.7 - 5800) / 5800) * 100, 1);
    expect(flux[0].warning).toBeNull();
    expect(r.report.products[0].imported.map((v) => v.cri)).toEqual([85, 85]);
  });
});
