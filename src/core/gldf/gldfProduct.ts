/**
 * What luxbox reads of a GLDF product (globallightingdata/gldf, xsd/gldf.xsd, format 1.0):
 * the parts a rail catalog needs, as plain data with every id reference already checked
 * (readGldfProduct.ts). Units as the schema gives them: watts, lumens, kelvin, millimetres.
 */

/** A translatable text: its Locale elements in document order (language as written, e.g. 'de-DE'). */
export type LocaleTexts = readonly { language: string; text: string }[];

/** GLDF `File`: a file inside the container (`localFileName`) or a link (`url`). */
export interface GldfFile {
  id: string;
  contentType: string;
  type: 'localFileName' | 'url';
  /** For a local file: the entry path inside the container (`ldc/spot.ldt`); for a url: the url. */
  path: string;
}

export interface GldfPhotometry {
  id: string;
  fileId: string;
}

export interface GldfLightSource {
  id: string;
  kind: 'fixed' | 'changeable';
  name: LocaleTexts;
  gtin?: string;
  /** RatedInputPower, W. */
  ratedInputPower: number;
  /** ChangeableLightSource RatedLuminousFlux (lamp lumens), lm; fixed light sources state flux on the emitter. */
  ratedLuminousFlux?: number;
  /** ColorInformation CorrelatedColorTemperature, K. */
  cct?: number;
  /** ColorInformation ColorRenderingIndex (Ra). */
  cri?: number;
}

export interface GldfEquipment {
  id: string;
  lightSourceId: string;
  lightSourceCount: number;
  ratedInputPower: number;
}

/** One light emitter inside an `Emitter` (a luminaire may hold several). */
export interface GldfLightEmitter {
  kind: 'fixed' | 'changeable' | 'multi-channel' | 'sensor';
  name?: LocaleTexts;
  photometryId?: string;
  /** Fixed: the FixedLightSource; changeable: through the equipment. */
  lightSourceId?: string;
  equipmentId?: string;
  /** FixedLightEmitter RatedLuminousFlux, lm. */
  ratedLuminousFlux?: number;
}

export interface GldfEmitter {
  id: string;
  lightEmitters: GldfLightEmitter[];
}

export interface GldfGeometry {
  id: string;
  kind: 'simple' | 'model';
  /** ModelGeometry GeometryFileReference file ids (L3D), by level of detail. */
  fileIds: string[];
}

/** A mounting a variant declares, as `<place>-<kind>` ('ceiling-surface', 'ceiling-pendant', 'wall-recessed', …). */
export type GldfMounting = string;

export interface GldfVariant {
  id: string;
  sortOrder?: number;
  productNumber: LocaleTexts;
  name: LocaleTexts;
  gtin?: string;
  /** The declared mountings; null when the variant has no Mountings element. */
  mountings: GldfMounting[] | null;
  /** Emitters the variant's Geometry names (one for a simple luminaire). */
  emitterIds: string[];
  /** Per emitter id, the EmitterObjectExternalName of its ModelGeometryReference: the L3D light-emitting object it is. */
  emitterObjects?: ReadonlyMap<string, string>;
  geometryId?: string;
  pictureFileIds: string[];
  /** DescriptiveAttributes/Mechanical/ProductSize, mm. */
  productSize?: { length: number; width: number; height: number };
  /** DescriptiveAttributes/Mechanical/Adjustabilities ('Fixed', 'Turn', 'Tilt', 'Cardanic', …). */
  adjustabilities: string[];
  /** DescriptiveAttributes/Marketing/ListPrices. */
  listPrices: { currency: string; price: number }[];
}

export interface GldfProduct {
  /** The container's file name, for messages. */
  source: string;
  header: { manufacturer: string; formatVersion: string; createdWithApplication: string; uniqueGldfId: string; defaultLanguage?: string };
  uniqueProductId: string;
  productNumber: LocaleTexts;
  name: LocaleTexts;
  pictureFileIds: string[];
  files: ReadonlyMap<string, GldfFile>;
  photometries: ReadonlyMap<string, GldfPhotometry>;
  lightSources: ReadonlyMap<string, GldfLightSource>;
  equipments: ReadonlyMap<string, GldfEquipment>;
  emitters: ReadonlyMap<string, GldfEmitter>;
  geometries: ReadonlyMap<string, GldfGeometry>;
  variants: GldfVariant[];
}

/** The container folder of each GLDF content type's files (the GLDF container layout). */
export function containerFolder(contentType: string): string {
  const kind = contentType.split('/')[0];
  if (kind === 'document') return 'doc';
  return kind;
}
