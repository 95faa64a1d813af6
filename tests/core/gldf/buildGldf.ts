/**
 * GLDF containers built by the tests from the repository's own photometry (public/ies): a track
 * spot with three optics in three CCTs, a pendant and a linear module. product.xml follows the
 * element order of vendor/gldf/gldf.xsd (checked by gldfSchema.test.ts); the zip is written by
 * fflate. `hostile` variants of these are made by editing the spec or the bytes.
 */
import { readFileSync } from 'node:fs';
import { zipSync, type Zippable } from 'fflate';
import { spotL3d } from './buildL3dSpot';

export type Lang = 'en' | 'de' | 'fr' | 'it';
export type Texts = Partial<Record<Lang, string>>;

export interface SpecFile {
  id: string;
  contentType: 'ldc/ies' | 'ldc/eulumdat' | 'image/png' | 'geo/l3d';
  name: string;
  bytes: Uint8Array;
}
export interface SpecLightSource {
  id: string;
  name: string;
  watts: number;
  cct?: number;
  cri?: number;
}
export interface SpecEmitter {
  id: string;
  photometryId: string;
  lightSourceId: string;
  flux: number;
  name?: Texts;
}
export interface SpecVariant {
  id: string;
  name: Texts;
  productNumber: string;
  gtin?: string;
  /** Inner XML of <Mountings>; null: no Mountings element. */
  mountings: string | null;
  emitterId: string;
  sortOrder?: number;
  productSize?: [number, number, number];
  adjustabilities?: string[];
  listPrice?: { currency: string; price: number };
  /** A ModelGeometry (L3D) the variant is drawn with, and the light-emitting object its emitter is. */
  model?: { geometryId: string; emitterObject: string };
}
export interface GldfSpec {
  uniqueProductId: string;
  productNumber: string;
  name: Texts;
  files: SpecFile[];
  photometries: { id: string; fileId: string }[];
  lightSources: SpecLightSource[];
  emitters: SpecEmitter[];
  variants: SpecVariant[];
  pictureFileId?: string;
  /** ModelGeometry elements: id and the L3D File they reference. */
  modelGeometries?: { id: string; fileId: string }[];
}

const esc = (s: string): string => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
const locales = (t: Texts): string =>
  Object.entries(t)
    .map(([lang, text]) => `<Locale language="${lang}">${esc(text)}</Locale>`)
    .join('');

/** GTIN-13 with its GS1 check digit (mod 10, weights 1,3 from the left). */
export function gtin13(first12: string): string {
  const sum = [...first12].reduce((s, d, i) => s + Number(d) * (i % 2 ? 3 : 1), 0);
  return first12 + String((10 - (sum % 10)) % 10);
}

export function productXml(s: GldfSpec): string {
  const files = s.files.map((f) => `<File id="${f.id}" contentType="${f.contentType}" type="localFileName">${esc(f.name)}</File>`).join('');
  const photometries = s.photometries.map((p) => `<Photometry id="${p.id}"><PhotometryFileReference fileId="${p.fileId}"/></Photometry>`).join('');
  const lightSources = s.lightSources
    .map(
      (l) =>
        `<FixedLightSource id="${l.id}"><Name><Locale language="en">${esc(l.name)}</Locale></Name><RatedInputPower>${l.watts}</RatedInputPower>` +
        (l.cct !== undefined || l.cri !== undefined
          ? `<ColorInformation>${l.cri !== undefined ? `<ColorRenderingIndex>${l.cri}</ColorRenderingIndex>` : ''}${l.cct !== undefined ? `<CorrelatedColorTemperature>${l.cct}</CorrelatedColorTemperature>` : ''}</ColorInformation>`
          : '') +
        `</FixedLightSource>`,
    )
    .join('');
  const emitters = s.emitters
    .map(
      (e) =>
        `<Emitter id="${e.id}"><FixedLightEmitter>${e.name ? `<Name>${locales(e.name)}</Name>` : ''}<PhotometryReference photometryId="${e.photometryId}"/>` +
        `<LightSourceReference fixedLightSourceId="${e.lightSourceId}"/><RatedLuminousFlux>${e.flux}</RatedLuminousFlux></FixedLightEmitter></Emitter>`,
    )
    .join('');
  const geometries = s.modelGeometries?.length ? `<Geometries>${s.modelGeometries.map((g) => `<ModelGeometry id="${g.id}"><GeometryFileReference fileId="${g.fileId}"/></ModelGeometry>`).join('')}</Geometries>` : '';
  const variants = s.variants
    .map((v) => {
      const mech =
        v.productSize || v.adjustabilities
          ? `<Mechanical>${v.productSize ? `<ProductSize><Length>${v.productSize[0]}</Length><Width>${v.productSize[1]}</Width><Height>${v.productSize[2]}</Height></ProductSize>` : ''}${
              v.adjustabilities ? `<Adjustabilities>${v.adjustabilities.map((a) => `<Adjustability>${a}</Adjustability>`).join('')}</Adjustabilities>` : ''
            }</Mechanical>`
          : '';
      const marketing = v.listPrice ? `<Marketing><ListPrices><ListPrice currency="${v.listPrice.currency}">${v.listPrice.price}</ListPrice></ListPrices></Marketing>` : '';
      return (
        `<Variant id="${v.id}"${v.sortOrder !== undefined ? ` sortOrder="${v.sortOrder}"` : ''}>` +
        `<ProductNumber><Locale language="en">${esc(v.productNumber)}</Locale></ProductNumber><Name>${locales(v.name)}</Name>` +
        (v.gtin ? `<GTIN>${v.gtin}</GTIN>` : '') +
        (v.mountings !== null ? `<Mountings>${v.mountings}</Mountings>` : '') +
        (v.model
          ? `<Geometry><ModelGeometryReference geometryId="${v.model.geometryId}"><EmitterReference emitterId="${v.emitterId}"><EmitterObjectExternalName>${esc(v.model.emitterObject)}</EmitterObjectExternalName></EmitterReference></ModelGeometryReference></Geometry>`
          : `<Geometry><EmitterReference emitterId="${v.emitterId}"/></Geometry>`) +
        (mech || marketing ? `<DescriptiveAttributes>${mech}${marketing}</DescriptiveAttributes>` : '') +
        `</Variant>`
      );
    })
    .join('');
  return (
    `<?xml version="1.0" encoding="UTF-8"?>\n` +
    `<Root><Header><Manufacturer>Luxbox Test Lighting</Manufacturer><FormatVersion major="1" minor="0" pre-release="3"/>` +
    `<CreatedWithApplication>luxbox tests</CreatedWithApplication><GldfCreationTimeCode>2026-11-27T08:00:00Z</GldfCreationTimeCode>` +
    `<UniqueGldfId>${esc(s.uniqueProductId)}-gldf</UniqueGldfId><DefaultLanguage>en</DefaultLanguage></Header>` +
    `<GeneralDefinitions><Files>${files}</Files><Photometries>${photometries}</Photometries><LightSources>${lightSources}</LightSources><Emitters>${emitters}</Emitters>${geometries}</GeneralDefinitions>` +
    `<ProductDefinitions><ProductMetaData><UniqueProductId>${esc(s.uniqueProductId)}</UniqueProductId><ProductNumber><Locale language="en">${esc(s.productNumber)}</Locale></ProductNumber>` +
    `<Name>${locales(s.name)}</Name>${s.pictureFileId ? `<Pictures><Image fileId="${s.pictureFileId}" imageType="Product Picture"/></Pictures>` : ''}</ProductMetaData>` +
    `<Variants>${variants}</Variants></ProductDefinitions></Root>\n`
  );
}

const FOLDER: Record<SpecFile['contentType'], string> = { 'ldc/ies': 'ldc', 'ldc/eulumdat': 'ldc', 'image/png': 'image', 'geo/l3d': 'geo' };

/** The .gldf bytes: product.xml plus every file in its folder; `extra` entries are added as given (or replace). */
export function gldfBytes(s: GldfSpec, extra: Zippable = {}, xml: string = productXml(s)): Uint8Array {
  const entries: Zippable = { 'product.xml': new TextEncoder().encode(xml) };
  for (const f of s.files) entries[`${FOLDER[f.contentType]}/${f.name}`] = f.bytes;
  return zipSync({ ...entries, ...extra }, { level: 6, mtime: new Date('2026-11-27T08:00:00Z') });
}

export const ies = (name: string): Uint8Array => new Uint8Array(readFileSync(`public/ies/${name}`));

/** A 1×1 PNG (a product picture need not be more for the tests). */
export const PNG_1X1 = new Uint8Array(Buffer.from('iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==', 'base64'));

const CEILING_SURFACE = '<Ceiling><SurfaceMounted/></Ceiling>';
const CEILING_PENDANT = '<Ceiling><Pendant pendantLength="1500"/></Ceiling>';

/** The track spot: narrow (BEGA 84693, IES), medium (Zumtobel Arcos 3, LDT), wide (BEGA 50975, IES), each in 2700, 3000 and 4000 K, drawn with the hand-made L3D of buildL3dSpot.ts. */
export function trackSpotSpec(): GldfSpec {
  const optics = [
    { key: 'narrow', file: 'bega_84693_narrow_spot.ies', type: 'ldc/ies' as const, flux3000: 2044, watts: 43, texts: { en: 'Narrow spot', de: 'Enger Spot', fr: 'Spot étroit', it: 'Spot stretto' } },
    { key: 'medium', file: 'zumtobel_arcos3_spot_isym1.ldt', type: 'ldc/eulumdat' as const, flux3000: 758, watts: 28, texts: { en: 'Medium spot', de: 'Mittlerer Spot', fr: 'Spot moyen', it: 'Spot medio' } },
    { key: 'wide', file: 'bega_50975_downlight_lm1995_crlf.ies', type: 'ldc/ies' as const, flux3000: 321, watts: 9, texts: { en: 'Wide flood', de: 'Breiter Fluter', fr: 'Flood large', it: 'Flood largo' } },
  ];
  // Warmer LEDs give less light at the same power: 2700 K 7 % less, 4000 K 4 % more than 3000 K (typical of one LED family's bins).
  const ccts = [
    { k: 3000, factor: 1 },
    { k: 2700, factor: 0.93 },
    { k: 4000, factor: 1.04 },
  ];
  const spec: GldfSpec = {
    uniqueProductId: 'LTL-TRACK-SPOT',
    productNumber: 'LTL-TS',
    name: { en: 'Track spot', de: 'Schienenstrahler', fr: 'Spot sur rail', it: 'Faretto a binario' },
    files: [
      ...optics.map((o) => ({ id: `f-${o.key}`, contentType: o.type, name: o.file, bytes: ies(o.file) })),
      { id: 'f-picture', contentType: 'image/png', name: 'track-spot.png', bytes: PNG_1X1 },
      { id: 'f-geometry', contentType: 'geo/l3d', name: 'track-spot.l3d', bytes: spotL3d() },
    ],
    modelGeometries: [{ id: 'geo-spot', fileId: 'f-geometry' }],
    photometries: optics.map((o) => ({ id: `ph-${o.key}`, fileId: `f-${o.key}` })),
    lightSources: [],
    emitters: [],
    variants: [],
    pictureFileId: 'f-picture',
  };
  let sort = 0;
  let serial = 100;
  for (const o of optics) {
    for (const c of ccts) {
      const suffix = `${o.key}-${c.k}`;
      spec.lightSources.push({ id: `ls-${suffix}`, name: `LED ${c.k} K`, watts: o.watts, cct: c.k, cri: c.k === 4000 ? 80 : 90 });
      spec.emitters.push({ id: `em-${suffix}`, photometryId: `ph-${o.key}`, lightSourceId: `ls-${suffix}`, flux: Math.round(o.flux3000 * c.factor), name: o.texts });
      spec.variants.push({
        id: `v-${suffix}`,
        name: { en: `Track spot ${o.texts.en} ${c.k} K`, de: `Schienenstrahler ${o.texts.de} ${c.k} K` },
        productNumber: `LTL-TS-${o.key.toUpperCase()}-${c.k / 100}`,
        gtin: gtin13(`400000000${serial++}`),
        mountings: CEILING_SURFACE,
        emitterId: `em-${suffix}`,
        sortOrder: sort++,
        adjustabilities: ['Cardanic'],
        model: { geometryId: 'geo-spot', emitterObject: 'lens' },
      });
    }
  }
  return spec;
}

/** The pendant (Ledalite direct/indirect, IES, relative photometry): 3000 and 4000 K on a pendant; a wall version that does not fit the rail. */
export function pendantSpec(): GldfSpec {
  const variant = (id: string, k: number, mountings: string | null, n: string): SpecVariant => ({
    id,
    name: { en: `Pendant ${k} K`, fr: `Suspension ${k} K` },
    productNumber: n,
    mountings,
    emitterId: `em-${k}`,
    listPrice: { currency: 'EUR', price: 349 },
  });
  return {
    uniqueProductId: 'LTL-PENDANT',
    productNumber: 'LTL-PD',
    name: { en: 'Pendant direct/indirect', fr: 'Suspension directe/indirecte' },
    files: [{ id: 'f-pendant', contentType: 'ldc/ies', name: 'ledalite_pendant_direct_indirect_iesna95.ies', bytes: ies('ledalite_pendant_direct_indirect_iesna95.ies') }],
    photometries: [{ id: 'ph-pendant', fileId: 'f-pendant' }],
    lightSources: [
      { id: 'ls-3000', name: 'LED 3000 K', watts: 63.7, cct: 3000, cri: 90 },
      { id: 'ls-4000', name: 'LED 4000 K', watts: 63.7, cct: 4000, cri: 80 },
    ],
    emitters: [
      { id: 'em-3000', photometryId: 'ph-pendant', lightSourceId: 'ls-3000', flux: 5300 },
      { id: 'em-4000', photometryId: 'ph-pendant', lightSourceId: 'ls-4000', flux: 5500 },
    ],
    variants: [variant('pd-3000', 3000, CEILING_PENDANT, 'LTL-PD-30'), variant('pd-4000', 4000, CEILING_PENDANT, 'LTL-PD-40'), variant('pd-wall-3000', 3000, '<Wall mountingHeight="2200"><SurfaceMounted/></Wall>', 'LTL-PD-W30')],
  };
}

/** The linear module (Zumtobel SLOIN, LDT): 600 mm, surface-mounted in 3000 and 4000 K; a recessed version that does not fit. */
export function linearSpec(): GldfSpec {
  return {
    uniqueProductId: 'LTL-LINEAR-600',
    productNumber: 'LTL-LN600',
    name: { en: 'Linear module 600', de: 'Linearmodul 600', it: 'Modulo lineare 600' },
    files: [{ id: 'f-linear', contentType: 'ldc/eulumdat', name: 'zumtobel_sloin_linear_isym4.ldt', bytes: ies('zumtobel_sloin_linear_isym4.ldt') }],
    photometries: [{ id: 'ph-linear', fileId: 'f-linear' }],
    lightSources: [
      { id: 'ls-3000', name: 'LED 3000 K', watts: 32.7, cct: 3000, cri: 90 },
      { id: 'ls-4000', name: 'LED 4000 K', watts: 32.7, cct: 4000, cri: 90 },
    ],
    emitters: [
      // The 4000 K rating is the data sheet's round 3000 lm; the photometry integrates to 2842 lm (−5.3 %): reported.
      { id: 'em-3000', photometryId: 'ph-linear', lightSourceId: 'ls-3000', flux: 2840, name: { en: 'Opal diffuser', de: 'Opal-Diffusor' } },
      { id: 'em-4000', photometryId: 'ph-linear', lightSourceId: 'ls-4000', flux: 3000, name: { en: 'Opal diffuser', de: 'Opal-Diffusor' } },
    ],
    variants: [
      { id: 'ln-4000', name: { en: 'Linear 600 4000 K' }, productNumber: 'LTL-LN600-40', mountings: CEILING_SURFACE, emitterId: 'em-4000', productSize: [600, 35, 50] },
      { id: 'ln-3000', name: { en: 'Linear 600 3000 K' }, productNumber: 'LTL-LN600-30', mountings: CEILING_SURFACE, emitterId: 'em-3000', productSize: [600, 35, 50] },
      {
        id: 'ln-rec-3000',
        name: { en: 'Linear 600 recessed' },
        productNumber: 'LTL-LN600-R30',
        mountings: '<Ceiling><Recessed recessedDepth="60"><RectangularCutout><Width>40</Width><Length>605</Length><Depth>60</Depth></RectangularCutout></Recessed></Ceiling>',
        emitterId: 'em-3000',
        productSize: [600, 35, 50],
      },
    ],
  };
}

/** The manufacturer's mapping file (docs/gldf.md has the same example). */
export const MAPPING_TEXT = JSON.stringify({
  formatVersion: 1,
  products: {
    'LTL-TRACK-SPOT': {
      id: 'track-spot',
      length: 0.15,
      defaultCct: 3000,
      defaultBeam: 'medium',
      filterHolder: true,
      adjustable: { tilt: { min: 0, max: 90, stops: 5 }, rotation: { min: 0, max: 355, stops: 5 } },
      beams: {
        'ph-narrow': { id: 'narrow', article: 'LTL-TS-N', price: 199 },
        'ph-medium': { id: 'medium', article: 'LTL-TS-M', price: 189 },
        'ph-wide': { id: 'wide', article: 'LTL-TS-W', price: 179 },
      },
    },
    'LTL-LINEAR-600': { id: 'linear-600', length: 0.6, price: 229, defaultCct: 3000, beams: { 'ph-linear': { id: 'opal', roll: 90 } } },
  },
});

/**
 * The pendant with changeable lamps instead of fixed LEDs (a fluorescent version: two 2900 lm
 * T5 lamps, 63.7 W with the ballast): ChangeableLightSource, Equipment, ChangeableLightEmitter.
 * Its photometry is relative (lamp lumens 5800), so integrated/rated is the light output ratio.
 */
export function changeablePendantXml(): string {
  const lamp = (k: number): string =>
    `<ChangeableLightSource id="lamp-${k}"><Name><Locale language="en">T5 28 W/8${k / 100}</Locale></Name><RatedInputPower>28</RatedInputPower>` +
    `<ColorInformation><ColorRenderingIndex>85</ColorRenderingIndex><CorrelatedColorTemperature>${k}</CorrelatedColorTemperature></ColorInformation><RatedLuminousFlux>2900</RatedLuminousFlux></ChangeableLightSource>`;
  const equipment = (k: number): string => `<Equipment id="eq-${k}"><LightSourceReference changeableLightSourceId="lamp-${k}" lightSourceCount="2"/><RatedInputPower>63.7</RatedInputPower></Equipment>`;
  const emitter = (k: number): string => `<Emitter id="em-${k}"><ChangeableLightEmitter><PhotometryReference photometryId="ph-pendant"/><EquipmentReference equipmentId="eq-${k}"/></ChangeableLightEmitter></Emitter>`;
  return productXml(pendantSpec())
    .replace(/<LightSources>.*<\/LightSources>/, `<LightSources>${lamp(3000)}${lamp(4000)}</LightSources><Equipments>${equipment(3000)}${equipment(4000)}</Equipments>`)
    .replace(/<Emitters>.*<\/Emitters>/, `<Emitters>${emitter(3000)}${emitter(4000)}</Emitters>`);
}
