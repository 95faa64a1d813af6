/**
 * `luxbox catalog export`'s core (docs/gldf.md, "Export"): the three GLDF-imported test products
 * go back to GLDF, each product.xml validates against the official schema (xmllint-wasm), and
 * importing the exported files with the exported mapping gives the same module types again —
 * every field but the beams' `source` (provenance: it names the GLDF file and variant the import
 * read). Without the mapping only the fields GLDF has no element for differ, and exactly those.
 */
import { readFileSync } from 'node:fs';
import { unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { validateXML } from 'xmllint-wasm';
import { exportGldfProduct } from '../../../src/core/gldf/exportGldfProduct';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { parseGldfMapping, type GldfMapping } from '../../../src/core/gldf/gldfMapping';
import { parseCatalogText, type Catalog } from '../../../src/core/model/catalogSchema/catalogSchema';
import type { ModuleTypeSpec } from '../../../src/core/model/catalogSchema/moduleTypeSchema';
import { gldfBytes, linearSpec, MAPPING_TEXT, pendantSpec, PNG_1X1, trackSpotSpec } from './buildGldf';
import { spotL3d } from './buildL3dSpot';

const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');
const schema = { fileName: 'gldf.xsd', contents: readFileSync('vendor/gldf/gldf.xsd', 'utf8') };
const IMPORTED = ['track-spot', 'ltl-pendant', 'linear-600'];

const first = importGldfCatalog(
  base,
  [
    { name: 'track-spot.gldf', bytes: gldfBytes(trackSpotSpec()) },
    { name: 'pendant.gldf', bytes: gldfBytes(pendantSpec()) },
    { name: 'linear.gldf', bytes: gldfBytes(linearSpec()) },
  ],
  parseGldfMapping(MAPPING_TEXT, 'mapping.json'),
);
const folder = new Map(first.files.map((f) => [f.path, f.bytes]));
const readFile = (path: string): Uint8Array => {
  const bytes = folder.get(path);
  if (!bytes) throw new Error(`${path}: not in the folder`);
  return bytes;
};
const createdAt = new Date('2026-11-27T09:00:00Z');
const exported = IMPORTED.map((id) => exportGldfProduct(first.catalog, id, { createdAt, readFile, ...(folder.has(`images/${id}.png`) ? { picture: { name: `${id}.png`, bytes: readFile(`images/${id}.png`) } } : {}) }));
const exportedMapping: GldfMapping = { formatVersion: 1, products: Object.fromEntries(IMPORTED.map((id, i) => [id, exported[i].mapping])) };

const typeOf = (c: Catalog, id: string): ModuleTypeSpec => c.moduleTypes.find((t) => t.id === id) as ModuleTypeSpec;
const withoutSource = (t: ModuleTypeSpec): ModuleTypeSpec => ({ ...t, beams: t.beams.map(({ source: _source, ...b }) => b) });
const reimport = (mapping: GldfMapping | null): ReturnType<typeof importGldfCatalog> =>
  importGldfCatalog(
    base,
    IMPORTED.map((id, i) => ({ name: `${id}.gldf`, bytes: exported[i].bytes })),
    mapping,
  );

describe('module types back to GLDF', () => {
  for (const [i, id] of IMPORTED.entries()) {
    it(`${id}: product.xml validates against the official XSD`, async () => {
      const r = await validateXML({ xml: [{ fileName: 'product.xml', contents: exported[i].productXml }], schema: [schema] });
      expect(r.errors.map((e) => e.rawMessage)).toEqual([]);
      expect(r.valid).toBe(true);
    });
  }

  it('the container holds product.xml, each beam’s photometry byte for byte, and the picture', () => {
    const entries = unzipSync(exported[0].bytes);
    expect(Object.keys(entries).sort()).toEqual(['geo/track-spot.l3d', 'image/track-spot.png', 'ldc/track-spot-medium.ldt', 'ldc/track-spot-narrow.ies', 'ldc/track-spot-wide.ies', 'product.xml']);
    // The L3D body byte for byte (the import wrote it as geo/track-spot.l3d).
    expect(entries['geo/track-spot.l3d']).toEqual(spotL3d());
    expect(entries['ldc/track-spot-medium.ldt']).toEqual(readFile('ies/track-spot-medium.ldt'));
    expect(entries['image/track-spot.png']).toEqual(PNG_1X1);
    expect(new TextDecoder().decode(entries['product.xml'])).toBe(exported[0].productXml);
  });

  it('writes every beam × CCT as a variant with its article number, CCT, power, flux, list price and the localized names', () => {
    const xml = exported[0].productXml;
    expect(xml.match(/<Variant /g)).toHaveLength(9);
    // The default CCT first, so the import takes it as the default again.
    expect(/<Variant id="v-narrow-3000" sortOrder="0"><ProductNumber><Locale language="en">LTL-TS-N-3000<\/Locale>/.test(xml)).toBe(true);
    expect(xml).toContain(
      '<FixedLightSource id="ls-narrow-2700"><Name><Locale language="en">Narrow spot 2700 K</Locale></Name><RatedInputPower>43</RatedInputPower><ColorInformation><CorrelatedColorTemperature>2700</CorrelatedColorTemperature></ColorInformation></FixedLightSource>',
    );
    expect(xml).toContain('<RatedLuminousFlux>2044</RatedLuminousFlux>');
    expect(xml).toContain('<Name><Locale language="en">Track spot</Locale><Locale language="de">Schienenstrahler</Locale><Locale language="fr">Spot sur rail</Locale><Locale language="it">Faretto a binario</Locale></Name>');
    expect(xml).toContain('<ListPrice currency="EUR">199</ListPrice>');
    expect(xml).toContain('<Adjustability>Cardanic</Adjustability>');
  });

  it('the mapping holds only what GLDF cannot say', () => {
    expect(exportedMapping.products).toEqual({
      'track-spot': { length: 0.15, defaultBeam: 'medium', adjustable: { tilt: { min: 0, max: 90, stops: 5 }, rotation: { min: 0, max: 355, stops: 5 } }, filterHolder: true },
      // One CCT per optic would lose the article; two CCTs give it back as the common prefix. The linear optic lies along the rail.
      'ltl-pendant': { length: 0.15 },
      'linear-600': { length: 0.6, beams: { opal: { roll: 90 } } },
    });
    // The mapping file validates as one.
    expect(parseGldfMapping(JSON.stringify(exportedMapping), 'exported-mapping.json')).toEqual(exportedMapping);
  });

  it('round trip: importing the exported files with the exported mapping gives the module types back (all but the beams’ source)', () => {
    const again = reimport(exportedMapping);
    for (const id of IMPORTED) expect(withoutSource(typeOf(again.catalog, id))).toEqual(withoutSource(typeOf(first.catalog, id)));
    // The photometry comes back byte for byte, under the same path.
    for (const f of again.files) expect(f.bytes).toEqual(folder.get(f.path));
    expect(again.files.map((f) => f.path).sort()).toEqual([...folder.keys()].sort());
    // The new source names the exported file and variant.
    expect(typeOf(again.catalog, 'track-spot').beams[0].source).toBe('GLDF track-spot.gldf, variant v-narrow-3000 (LTL-TS-N-3000): rated 2044 lm, 43 W');
  });

  it('without the mapping exactly the fields GLDF has no element for differ: length on the rail, default beam, aiming stops, filter holder, roll', () => {
    const again = reimport(null);
    const diff = (id: string): string[] => {
      const a = withoutSource(typeOf(first.catalog, id)) as unknown as Record<string, unknown>;
      const b = withoutSource(typeOf(again.catalog, id)) as unknown as Record<string, unknown>;
      return [...new Set([...Object.keys(a), ...Object.keys(b)])].filter((k) => JSON.stringify(a[k]) !== JSON.stringify(b[k])).sort();
    };
    expect(diff('track-spot')).toEqual(['adjustable', 'defaultBeam', 'filterHolder']);
    expect(diff('ltl-pendant')).toEqual([]);
    expect(diff('linear-600')).toEqual(['beams', 'length']);
    expect(typeOf(again.catalog, 'linear-600').beams[0].roll).toBe(0);
    // Without the mapping the ranges come from the exported L3D's joints (tilt 0–90° in 5° stops, a 340° swivel in 1° stops).
    expect(typeOf(again.catalog, 'track-spot').adjustable).toEqual({ tilt: { min: 0, max: 90, stops: 5 }, rotation: { min: 0, max: 340, stops: 1 } });
    expect(typeOf(again.catalog, 'track-spot').model).toBe('geo/track-spot.l3d');
  });

  it('ids that are not XML names or file names: safe ids in the file; the mapping gives back what it may hold, the rest is noted', async () => {
    const spot = typeOf(first.catalog, 'track-spot');
    const odd: ModuleTypeSpec = { ...spot, id: 'Track Spot/2', beams: spot.beams.map((b) => ({ ...b, id: `2 ${b.id}` })), defaultBeam: '2 medium' };
    const catalog = { ...first.catalog, moduleTypes: [odd] };
    const out = exportGldfProduct(catalog, 'Track Spot/2', { createdAt, readFile });
    const r = await validateXML({ xml: [{ fileName: 'product.xml', contents: out.productXml }], schema: [schema] });
    expect(r.errors.map((e) => e.rawMessage)).toEqual([]);
    expect(Object.keys(unzipSync(out.bytes)).sort()).toEqual(['geo/track-spot-2.l3d', 'ldc/track-spot-2-ph-2-medium.ldt', 'ldc/track-spot-2-ph-2-narrow.ies', 'ldc/track-spot-2-ph-2-wide.ies', 'product.xml']);
    expect(out.mapping).toEqual({ length: 0.15, adjustable: spot.adjustable, filterHolder: true });
    expect(out.notes).toContain("its id comes back as 'track-spot-2' (imported ids are lower-case letters, digits and -)");
    expect(out.notes).toContain("beam '2 narrow' comes back as 'ph-2-narrow' (imported ids are lower-case letters, digits and -)");
    // A beam id that is a catalog id but not an XML name ('2-narrow': starts with a digit) comes back through the mapping.
    const digits: ModuleTypeSpec = { ...spot, beams: spot.beams.map((b) => ({ ...b, id: `2-${b.id}` })), defaultBeam: '2-medium' };
    const out2 = exportGldfProduct({ ...first.catalog, moduleTypes: [digits] }, 'track-spot', { createdAt, readFile });
    expect(out2.mapping.beams).toEqual({ 'ph-2-narrow': { id: '2-narrow' }, 'ph-2-medium': { id: '2-medium' }, 'ph-2-wide': { id: '2-wide' } });
    const back = importGldfCatalog(base, [{ name: 'digits.gldf', bytes: out2.bytes }], { formatVersion: 1, products: { 'track-spot': out2.mapping } });
    expect(withoutSource(typeOf(back.catalog, 'track-spot'))).toEqual(withoutSource({ ...digits, beams: digits.beams.map((b) => ({ ...b, photometry: `ies/track-spot-${b.id}.${b.photometry.split('.').pop()}` })) }));
  });

  it('notes what neither carries, and refuses an unknown type or a missing photometry naming it', () => {
    expect(exported[0].notes).toEqual(['each beam’s source text is provenance: the import writes its own, naming the GLDF file and variant']);
    expect(() => exportGldfProduct(first.catalog, 'nope', { createdAt, readFile })).toThrow(/has no module type 'nope' \(its types: spot, /);
    expect(() => exportGldfProduct(first.catalog, 'spot', { createdAt, readFile })).toThrow(/module type 'spot', beam '[a-z0-9-]+': photometry ies\/\S+ cannot be read \(ies\/\S+: not in the folder\)/);
  });
});
