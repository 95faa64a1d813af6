/**
 * A module type of the rail catalog back to a GLDF product (docs/gldf.md, "Export"): the
 * inverse of gldfToModuleType, so a manufacturer can round-trip. Element names and order follow
 * vendor/gldf/gldf.xsd (1.0.0-rc.3). Every beam × CCT is one Variant; each beam is one Photometry
 * (id = beam id) with its file, each beam × CCT one FixedLightSource (CCT, power) and one
 * FixedLightEmitter (rated flux, the beam's localized label). What GLDF cannot carry and the
 * rail catalog needs (length on the rail, roll, aiming ranges, filter holder, the default beam,
 * articles the product numbers do not give back) goes into a mapping entry that the import reads
 * (gldfMapping.ts), so export + import with that mapping gives the module type back.
 */
import { zipSync, type Zippable } from 'fflate';
import type { Catalog } from '../model/catalogSchema/catalogSchema';
import type { BeamSpec, ModuleTypeSpec } from '../model/catalogSchema/moduleTypeSchema';
import { GldfError } from './GldfError';
import type { GldfBeamMapping, GldfProductMapping } from './gldfMapping';
import { GLDF_DEFAULTS, catalogSlug, commonArticle } from './gldfDefaults';
import { l3dAimLimits, l3dLightEmittingObjectNames } from './l3dModelOf';
import { readL3dStructure } from './readL3dStructure';

export interface GldfExportOptions {
  /** GldfCreationTimeCode and the zip entries' time (a fixed one gives identical bytes run to run). */
  createdAt: Date;
  /** Reads a file of the catalog folder by its catalog path (`ies/spot.ies`); throws when absent. */
  readFile: (path: string) => Uint8Array;
  /** The product picture (from `images/<type id>.png|jpg` of an imported folder), if there is one. */
  picture?: { name: string; bytes: Uint8Array };
}

export interface GldfExport {
  /** The .gldf container: product.xml, ldc/…, image/…. */
  bytes: Uint8Array;
  /** product.xml, as in the container. */
  productXml: string;
  /** The mapping entry (keyed by the type id, the product's UniqueProductId) for what GLDF cannot say. */
  mapping: GldfProductMapping;
  /** Fields that neither the GLDF nor the mapping carries (lost on a round trip). */
  notes: string[];
}

const LANGUAGES = ['en', 'de', 'fr', 'it'] as const;

/** The ids a mapping file may give (gldfMapping.ts `catalogId`): others cannot come back through it. */
const MAPPING_ID = /^[a-z0-9][a-z0-9-]{0,63}$/;

const esc = (s: string): string => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/** Locale texts: the main text as English (the import reads English first), the translations beside it. */
function locales(text: string, translations: Partial<Record<(typeof LANGUAGES)[number], string>> | undefined): string {
  const out = [`<Locale language="en">${esc(text)}</Locale>`];
  for (const lang of LANGUAGES) {
    const t = translations?.[lang];
    if (lang !== 'en' && t !== undefined) out.push(`<Locale language="${lang}">${esc(t)}</Locale>`);
  }
  return out.join('');
}

/** The GLDF content type and container folder of a photometry path (IES or EULUMDAT by extension). */
function photometryKind(path: string): { contentType: 'ldc/ies' | 'ldc/eulumdat'; ext: 'ies' | 'ldt' } {
  return /\.ies$/i.test(path) ? { contentType: 'ldc/ies', ext: 'ies' } : { contentType: 'ldc/eulumdat', ext: 'ldt' };
}

/** The CCTs in variant order: the default first, so the import takes it as the default again (docs/gldf.md, "Defaults"). */
function cctOrder(type: ModuleTypeSpec): number[] {
  return [type.defaultCct, ...type.ccts.filter((k) => k !== type.defaultCct)];
}

/** The bill of materials' article for a beam in a CCT (billOfMaterials: `<beam article>-<cct>`). */
const variantArticle = (beam: BeamSpec, cct: number): string => `${beam.article}-${cct}`;

function sameRange(a: ModuleTypeSpec['adjustable'], b: ModuleTypeSpec['adjustable']): boolean {
  return JSON.stringify(a) === JSON.stringify(b);
}

/** GLDF Adjustability for the catalog's ranges: tilts and turns → Cardanic; only one → Tilt or Turn. */
function adjustabilities(type: ModuleTypeSpec): string[] {
  const a = type.adjustable;
  if (!a) return [];
  const tilts = a.tilt.max > a.tilt.min;
  const turns = a.rotation.max > a.rotation.min;
  return tilts && turns ? ['Cardanic'] : tilts ? ['Tilt'] : turns ? ['Turn'] : [];
}

/** What the import would make of the Adjustability written (gldfToModuleType adjustableFor). */
function importedAdjustable(kinds: string[]): ModuleTypeSpec['adjustable'] {
  if (kinds.length === 0) return undefined;
  const tilts = kinds.includes('Tilt') || kinds.includes('Cardanic');
  const turns = kinds.includes('Turn') || kinds.includes('Cardanic');
  return { tilt: tilts ? { ...GLDF_DEFAULTS.tilt } : { min: 0, max: 0 }, rotation: turns ? { ...GLDF_DEFAULTS.rotation } : { min: 0, max: 0 } };
}

/** What the export's steps fill: the container's entries and product.xml's element lists, in document order. */
interface GldfExportParts {
  catalog: Catalog;
  type: ModuleTypeSpec;
  options: GldfExportOptions;
  notes: string[];
  entries: Zippable;
  files: string[];
  photometries: string[];
  lightSources: string[];
  emitters: string[];
  variants: string[];
  /** The next Variant's sortOrder. */
  sort: number;
  /** The L3D body, when the type has one (exportModel). */
  model: ExportedModel | null;
}

interface ExportedModel {
  fileName: string;
  emitterObject: string;
  limits: ModuleTypeSpec['adjustable'] | null;
}

/**
 * The steps: the L3D body, each beam (file, Photometry, and per CCT a light source, an emitter
 * and a Variant), the mapping entry for what GLDF cannot say, the picture, then product.xml and
 * the container.
 */
export function exportGldfProduct(catalog: Catalog, typeId: string, options: GldfExportOptions): GldfExport {
  const type = catalog.moduleTypes.find((t) => t.id === typeId);
  if (!type) throw new GldfError(`catalog '${catalog.id}' has no module type '${typeId}' (its types: ${catalog.moduleTypes.map((t) => t.id).join(', ')})`);
  const created = new Date(Math.floor(options.createdAt.getTime() / 1000) * 1000);
  const parts: GldfExportParts = { catalog, type, options, notes: [], entries: {}, files: [], photometries: [], lightSources: [], emitters: [], variants: [], sort: 0, model: null };
  parts.model = exportModel(parts);
  const ccts = cctOrder(type);
  const beamMappings: NonNullable<GldfProductMapping['beams']> = {};
  for (const beam of type.beams) {
    const { pid, mapping } = exportBeam(parts, beam, ccts);
    if (mapping) beamMappings[pid] = mapping;
  }
  const mapping = typeMapping(parts, beamMappings);
  const pictures = exportPicture(parts);
  const xml = productXml(parts, created, pictures);
  parts.entries['product.xml'] = new TextEncoder().encode(xml);
  return { bytes: zipSync(parts.entries, { level: 6, mtime: created }), productXml: xml, mapping, notes: parts.notes };
}

/** The L3D body (catalog `model`) goes back as a ModelGeometry; the import reads its joints' ranges, so the mapping need not repeat them. */
function exportModel(parts: GldfExportParts): ExportedModel | null {
  const { type } = parts;
  if (!type.model) return null;
  let bytes: Uint8Array;
  try {
    bytes = parts.options.readFile(type.model);
  } catch (error) {
    throw new GldfError(`module type '${type.id}': model ${type.model} cannot be read (${error instanceof Error ? error.message : String(error)})`);
  }
  const { luminaire } = readL3dStructure(bytes, `module type '${type.id}': model ${type.model}`);
  // The type's own emitter object (catalog `modelEmitter`, from the GLDF it came from), else the model's first.
  const emitterObject = type.modelEmitter ?? l3dLightEmittingObjectNames(luminaire.structure)[0];
  if (!emitterObject) throw new GldfError(`module type '${type.id}': model ${type.model} has no LightEmittingObject for the emitters to name`);
  if (!l3dLightEmittingObjectNames(luminaire.structure).includes(emitterObject)) throw new GldfError(`module type '${type.id}': modelEmitter '${emitterObject}' is no LightEmittingObject of ${type.model}`);
  const fileName = `${catalogSlug(type.id)}.l3d`;
  parts.entries[`geo/${fileName}`] = bytes;
  parts.files.push(`<File id="f-geometry" contentType="geo/l3d" type="localFileName">${esc(fileName)}</File>`);
  return { fileName, emitterObject, limits: l3dAimLimits(luminaire) };
}

/** A variant's Geometry: the model's emitter object when there is a model, else the emitter alone. */
function geometry(model: ExportedModel | null, emitterId: string): string {
  return model
    ? `<Geometry><ModelGeometryReference geometryId="geo-model"><EmitterReference emitterId="${emitterId}"><EmitterObjectExternalName>${esc(model.emitterObject)}</EmitterObjectExternalName></EmitterReference></ModelGeometryReference></Geometry>`
    : `<Geometry><EmitterReference emitterId="${emitterId}"/></Geometry>`;
}

/** One beam: its photometry file and Photometry, a light source, emitter and Variant per CCT; returns its Photometry id and its mapping entry (null: none needed). */
function exportBeam(parts: GldfExportParts, beam: BeamSpec, ccts: readonly number[]): { pid: string; mapping: GldfBeamMapping | null } {
  const { type, notes } = parts;
  const kind = photometryKind(beam.photometry);
  // xs:ID values are NCNames: a beam id that is not one gets a Photometry id that is, and the mapping gives the id back.
  const pid = /^[A-Za-z_][\w.-]*$/.test(beam.id) ? beam.id : `ph-${beam.id.replace(/[^\w.-]/g, '-')}`;
  const fileId = `f-${pid}`;
  // Entry names from ids that are safe as names (a catalog id may hold any character; the import refuses a File name that is a path).
  const fileName = `${catalogSlug(type.id)}-${pid}.${kind.ext}`;
  let bytes: Uint8Array;
  try {
    bytes = parts.options.readFile(beam.photometry);
  } catch (error) {
    throw new GldfError(`module type '${type.id}', beam '${beam.id}': photometry ${beam.photometry} cannot be read (${error instanceof Error ? error.message : String(error)})`);
  }
  parts.entries[`ldc/${fileName}`] = bytes;
  parts.files.push(`<File id="${fileId}" contentType="${kind.contentType}" type="localFileName">${esc(fileName)}</File>`);
  parts.photometries.push(`<Photometry id="${pid}"><PhotometryFileReference fileId="${fileId}"/></Photometry>`);
  // A label that is only the beam id stays out of the file: the import then takes the id again (and no translations appear).
  const label = beam.labels || beam.label !== beam.id ? `<Name>${locales(beam.label, beam.labels)}</Name>` : '';
  if (label && beam.labels?.en !== beam.label) notes.push(`beam '${beam.id}': its labels come back with en = '${beam.label}' (the label is the English Locale text)`);
  for (const cct of ccts) exportBeamInCct(parts, beam, pid, label, cct);
  return { pid, mapping: beamMapping(notes, beam, pid, ccts) };
}

/** The beam in one CCT: a FixedLightSource (CCT, power), a FixedLightEmitter (rated flux, label) and the Variant that names them. */
function exportBeamInCct(parts: GldfExportParts, beam: BeamSpec, pid: string, label: string, cct: number): void {
  const { type, catalog } = parts;
  const key = `${pid}-${cct}`;
  parts.lightSources.push(
    `<FixedLightSource id="ls-${key}"><Name><Locale language="en">${esc(`${beam.label} ${cct} K`)}</Locale></Name><RatedInputPower>${beam.watts}</RatedInputPower>` +
      `<ColorInformation><CorrelatedColorTemperature>${cct}</CorrelatedColorTemperature></ColorInformation></FixedLightSource>`,
  );
  parts.emitters.push(
    `<Emitter id="em-${key}"><FixedLightEmitter>${label}<PhotometryReference photometryId="${pid}"/>` +
      `<LightSourceReference fixedLightSourceId="ls-${key}"/><RatedLuminousFlux>${beam.lumens}</RatedLuminousFlux></FixedLightEmitter></Emitter>`,
  );
  const kinds = adjustabilities(type);
  const mechanical = kinds.length ? `<Mechanical><Adjustabilities>${kinds.map((k) => `<Adjustability>${k}</Adjustability>`).join('')}</Adjustabilities></Mechanical>` : '';
  const marketing = `<Marketing><ListPrices><ListPrice currency="${catalog.currency}">${beam.price}</ListPrice></ListPrices></Marketing>`;
  parts.variants.push(
    `<Variant id="v-${key}" sortOrder="${parts.sort++}"><ProductNumber><Locale language="en">${esc(variantArticle(beam, cct))}</Locale></ProductNumber>` +
      `<Name>${locales(`${type.name} ${beam.label} ${cct} K`, undefined)}</Name>` +
      // The rail hangs from the ceiling: its modules are surface-mounted on it (docs/gldf.md, "Mounting").
      `<Mountings><Ceiling><SurfaceMounted/></Ceiling></Mountings>` +
      geometry(parts.model, `em-${key}`) +
      `<DescriptiveAttributes>${mechanical}${marketing}</DescriptiveAttributes></Variant>`,
  );
}

/** What the import cannot recover of a beam from the GLDF: its id, its article, its roll (null: nothing). */
function beamMapping(notes: string[], beam: BeamSpec, pid: string, ccts: readonly number[]): GldfBeamMapping | null {
  const bm: GldfBeamMapping = {};
  if (catalogSlug(pid) !== beam.id) {
    if (MAPPING_ID.test(beam.id)) bm.id = beam.id;
    else notes.push(`beam '${beam.id}' comes back as '${catalogSlug(pid)}' (imported ids are lower-case letters, digits and -)`);
  }
  // The import recovers an article as the common prefix of its variants' numbers; where that fails (one CCT, or 3000/3500 sharing '-3'), the mapping says it.
  if (commonArticle(ccts.map((k) => variantArticle(beam, k))) !== beam.article) bm.article = beam.article;
  if (beam.roll !== GLDF_DEFAULTS.roll) bm.roll = beam.roll;
  return Object.keys(bm).length > 0 ? bm : null;
}

/** The type's mapping entry (length, beams, id, default beam, aiming, filter holder) and notes on what comes back changed. */
function typeMapping(parts: GldfExportParts, beamMappings: NonNullable<GldfProductMapping['beams']>): GldfProductMapping {
  const { type, notes, model } = parts;
  const mapping: GldfProductMapping = { length: type.length };
  if (Object.keys(beamMappings).length > 0) mapping.beams = beamMappings;
  if (catalogSlug(type.id) !== type.id) {
    if (MAPPING_ID.test(type.id)) mapping.id = type.id;
    else notes.push(`its id comes back as '${catalogSlug(type.id)}' (imported ids are lower-case letters, digits and -)`);
  }
  if (type.defaultBeam !== type.beams[0].id) {
    if (MAPPING_ID.test(type.defaultBeam)) mapping.defaultBeam = type.defaultBeam;
    else notes.push(`its default beam comes back as the first, '${catalogSlug(type.beams[0].id)}'`);
  }
  const kinds = adjustabilities(type);
  const imported = kinds.length && model?.limits ? model.limits : importedAdjustable(kinds);
  if (!sameRange(type.adjustable, imported)) mapping.adjustable = type.adjustable ?? false;
  if (type.filterHolder) mapping.filterHolder = true;
  if (type.names?.en !== type.name) notes.push(`its names come back with en = '${type.name}' (the name is the English Locale text)`);
  if (type.dimming) notes.push(`its dimming curve (${type.dimming.curve}) has no GLDF element and is not exported`);
  if (type.ccts.some((k, i) => i > 0 && k < type.ccts[i - 1])) notes.push(`its CCTs come back in ascending order (${[...type.ccts].sort((a, b) => a - b).join(', ')} K)`);
  notes.push('each beam\u2019s source text is provenance: the import writes its own, naming the GLDF file and variant');
  return mapping;
}

/** The product picture as image/<type>.<ext>; returns the ProductMetaData's Pictures element ('' without one). */
function exportPicture(parts: GldfExportParts): string {
  const { type, options } = parts;
  if (!options.picture) return '';
  const ext = /\.(png|jpe?g)$/i.exec(options.picture.name)?.[1]?.toLowerCase();
  if (!ext) throw new GldfError(`module type '${type.id}': picture ${options.picture.name} is not PNG or JPEG`);
  const name = `${catalogSlug(type.id)}.${ext}`;
  parts.entries[`image/${name}`] = options.picture.bytes;
  parts.files.push(`<File id="f-picture" contentType="image/${ext === 'png' ? 'png' : 'jpg'}" type="localFileName">${esc(name)}</File>`);
  return `<Pictures><Image fileId="f-picture" imageType="Product Picture"/></Pictures>`;
}

function productXml(parts: GldfExportParts, created: Date, pictures: string): string {
  const { catalog, type } = parts;
  return (
    `<?xml version="1.0" encoding="UTF-8"?>\n` +
    `<Root><Header><Manufacturer>${esc(catalog.name)}</Manufacturer><FormatVersion major="1" minor="0" pre-release="3"/>` +
    `<CreatedWithApplication>luxbox catalog export</CreatedWithApplication><GldfCreationTimeCode>${created.toISOString().replace('.000Z', 'Z')}</GldfCreationTimeCode>` +
    `<UniqueGldfId>${esc(`${catalog.id}-${type.id}`)}</UniqueGldfId><DefaultLanguage>en</DefaultLanguage></Header>` +
    `<GeneralDefinitions><Files>${parts.files.join('')}</Files><Photometries>${parts.photometries.join('')}</Photometries>` +
    `<LightSources>${parts.lightSources.join('')}</LightSources><Emitters>${parts.emitters.join('')}</Emitters>` +
    (parts.model ? `<Geometries><ModelGeometry id="geo-model"><GeometryFileReference fileId="f-geometry"/></ModelGeometry></Geometries>` : '') +
    `</GeneralDefinitions>` +
    `<ProductDefinitions><ProductMetaData><UniqueProductId>${esc(type.id)}</UniqueProductId>` +
    `<ProductNumber><Locale language="en">${esc(type.id)}</Locale></ProductNumber><Name>${locales(type.name, type.names)}</Name>${pictures}</ProductMetaData>` +
    `<Variants>${parts.variants.join('')}</Variants></ProductDefinitions></Root>\n`
  );
}
