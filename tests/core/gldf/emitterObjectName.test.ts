/**
 * GLDF EmitterObjectExternalName (docs/gldf.md "Which object emits"): a variant's
 * ModelGeometryReference names the L3D light-emitting object its emitter is. The import checks the
 * name against the L3D (a missing one refuses the file in one line naming the product, the variant
 * and the name), writes it as the type's `modelEmitter`, the export writes it back, and the 3D
 * view's body takes that object as the photometric centre (l3dBody), even one facing up.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { exportGldfProduct } from '../../../src/core/gldf/exportGldfProduct';
import { GldfError } from '../../../src/core/gldf/GldfError';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { parseGldfMapping } from '../../../src/core/gldf/gldfMapping';
import { readL3dStructure } from '../../../src/core/gldf/readL3dStructure';
import { parseCatalog, parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { readL3dMeshes } from '../../../src/engines/meshImport/readL3dMeshes';
import { l3dBody } from '../../../src/engines/view/luminaires/l3dBody';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { gldfBytes, MAPPING_TEXT, trackSpotSpec, type GldfSpec } from './buildGldf';
import { SPOT, SPOT_STRUCTURE, spotL3d } from './buildL3dSpot';

const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');
const mapping = parseGldfMapping(MAPPING_TEXT, 'mapping.json');
/** The track spot with a second light-emitting object on the adapter, facing up (an uplight). */
const UPLIGHT = '<LightEmittingObjects><LightEmittingObject partName="uplight"><Position x="0" y="0" z="0"/><Rotation x="180" y="0" z="0"/><Rectangle sizeX="0.03" sizeY="0.02"/></LightEmittingObject></LightEmittingObjects>';
const WITH_UPLIGHT = SPOT_STRUCTURE.replace('      </Joints>\n    </Geometry>\n  </Structure>', `      </Joints>\n      ${UPLIGHT}\n    </Geometry>\n  </Structure>`);

function spotNaming(name: string, xml = SPOT_STRUCTURE, only?: string): GldfSpec {
  const spec = trackSpotSpec();
  spec.files = spec.files.map((f) => (f.contentType === 'geo/l3d' ? { ...f, bytes: spotL3d(xml) } : f));
  spec.variants.forEach((v) => {
    if (v.model && (only === undefined || only === v.id)) v.model = { ...v.model, emitterObject: name };
  });
  return spec;
}

function refusal(spec: GldfSpec): string {
  try {
    importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes(spec) }], mapping);
  } catch (error) {
    expect(error).toBeInstanceOf(GldfError);
    return (error as Error).message;
  }
  throw new Error('accepted');
}

describe('EmitterObjectExternalName', () => {
  it("is read, checked against the L3D and becomes the type's modelEmitter", () => {
    expect(WITH_UPLIGHT).not.toBe(SPOT_STRUCTURE);
    const lens = importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes(spotNaming('lens', WITH_UPLIGHT)) }], mapping).catalog.moduleTypes.find((t) => t.id === 'track-spot')!;
    expect(lens.modelEmitter).toBe('lens');
    const up = importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes(spotNaming('uplight', WITH_UPLIGHT)) }], mapping).catalog.moduleTypes.find((t) => t.id === 'track-spot')!;
    expect(up.modelEmitter).toBe('uplight');
  });

  it('a name the L3D does not have refuses the file in one line naming the product, the variant and the name', () => {
    const message = refusal(spotNaming('lense'));
    expect(message).toBe("spot.gldf: product 'LTL-TRACK-SPOT': Variant 'v-narrow-3000': EmitterObjectExternalName 'lense' is no LightEmittingObject of 'geo/track-spot.l3d' (it has 'lens')");
    expect(message.length).toBeLessThanOrEqual(200);
    // Any variant drawn with the model is checked, not only the lead.
    expect(refusal(spotNaming('head', SPOT_STRUCTURE, 'v-medium-3000'))).toContain("Variant 'v-medium-3000': EmitterObjectExternalName 'head' is no LightEmittingObject");
  });

  it('the export writes it back, and the import of the export gives it again', () => {
    const imported = importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes(spotNaming('uplight', WITH_UPLIGHT)) }], mapping);
    const files = new Map(imported.files.map((f) => [f.path, f.bytes]));
    const out = exportGldfProduct(imported.catalog, 'track-spot', { readFile: (p) => files.get(p)!, createdAt: new Date('2026-11-27T08:00:00Z') });
    const xml = out.productXml;
    expect(xml).toContain('<EmitterObjectExternalName>uplight</EmitterObjectExternalName>');
    expect(xml).not.toContain('<EmitterObjectExternalName>lens</EmitterObjectExternalName>');
    const again = importGldfCatalog(base, [{ name: 'track-spot.gldf', bytes: out.bytes }], { formatVersion: 1, products: { 'track-spot': out.mapping } });
    expect(again.catalog.moduleTypes.find((t) => t.id === 'track-spot')!.modelEmitter).toBe('uplight');
    // A catalog naming an object its model lacks is not exported.
    const wrong = { ...imported.catalog, moduleTypes: imported.catalog.moduleTypes.map((t) => (t.id === 'track-spot' ? { ...t, modelEmitter: 'lense' } : t)) };
    expect(() => exportGldfProduct(wrong, 'track-spot', { readFile: (p) => files.get(p)!, createdAt: new Date() })).toThrow("modelEmitter 'lense' is no LightEmittingObject of geo/track-spot.l3d");
  });

  it('the catalog refuses a modelEmitter without a model', () => {
    const json = JSON.parse(readFileSync('src/core/catalog/default-catalog.json', 'utf8')) as { moduleTypes: Record<string, unknown>[] };
    json.moduleTypes[0].modelEmitter = 'lens';
    expect(() => parseCatalog(json)).toThrow(/modelEmitter/);
  });

  it('picks the photometric centre of the 3D body: the named object, even facing up; an unknown name is refused', () => {
    const { luminaire, zip } = readL3dStructure(spotL3d(WITH_UPLIGHT), 'spot.l3d');
    const parts = readL3dMeshes(luminaire, zip).parts;
    const byDefault = l3dBody(luminaire, parts);
    expect(byDefault.primary).toBe('lens');
    expect(byDefault.origin[1]).toBeCloseTo(-SPOT.insert, 9);
    const up = l3dBody(luminaire, parts, 'uplight');
    expect(up.primary).toBe('uplight');
    expect(up.primaryObject.shape).toEqual({ kind: 'rectangle', sizeX: 0.03, sizeY: 0.02 });
    // The uplight lies on the adapter's top, the insert point: the origin, 128 mm above the lens.
    expect(up.origin[1]).toBeCloseTo(0, 9);
    expect(() => readL3dBody(spotL3d(WITH_UPLIGHT), 'spot.l3d', 'lense')).toThrow("spot.l3d: no LightEmittingObject 'lense' (it has 'uplight', 'lens')");
  });
});

describe("the import report names a header opening that differs from the L3D's", () => {
  it('one note per beam whose photometric header disagrees with the lens', () => {
    const report = importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes(trackSpotSpec()) }], mapping).report.products[0];
    expect(report.notes.filter((n) => n.includes('luminous opening'))).toEqual([
      "beam narrow: the photometry's luminous opening is Ø 150 mm, the L3D's light-emitting object 'lens' Ø 50 mm; the near field uses the L3D's",
      "beam medium: the photometry's luminous opening is Ø 110 mm, the L3D's light-emitting object 'lens' Ø 50 mm; the near field uses the L3D's",
      "beam wide: the photometry's luminous opening is Ø 80 mm, the L3D's light-emitting object 'lens' Ø 50 mm; the near field uses the L3D's",
    ]);
    // A lens as wide as the narrow beam's header (within 1 mm): no note for that beam.
    const wide = importGldfCatalog(base, [{ name: 'spot.gldf', bytes: gldfBytes(spotNaming('lens', SPOT_STRUCTURE.replace('diameter="0.05"', 'diameter="0.1505"'))) }], mapping).report.products[0];
    expect(wide.notes.filter((n) => n.includes('luminous opening')).map((n) => n.split(':')[0])).toEqual(['beam medium', 'beam wide']);
  });
});
