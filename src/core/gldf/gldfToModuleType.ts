/**
 * One GLDF product → one module type of the rail catalog (docs/gldf.md, "Rules"). A product is
 * what a manufacturer sells as one luminaire with options; its variants differ by optic (→
 * beams) and colour temperature (→ CCTs). The catalog offers every beam in every CCT of a type,
 * so only CCTs every beam has are imported; the rest is reported. Values neither the GLDF nor
 * the mapping file give take the defaults below, each listed in the report.
 */
import type { BeamSpec, ModuleTypeSpec } from '../model/catalogSchema/moduleTypeSchema';
import { beamSpecs, type BeamOpening } from './gldfBeams';
import type { Accepted, Conversion, ConvertOptions, ConvertedProduct } from './gldfConversion';
import { GLDF_DEFAULTS, catalogSlug } from './gldfDefaults';
import type { ProductReport } from './gldfImportReport';
import { DEFAULT_RAIL_MOUNTINGS, type GldfProductMapping } from './gldfMapping';
import { firstText, names } from './gldfNames';
import type { GldfProduct, GldfVariant } from './gldfProduct';
import { acceptVariants, offeredVariants } from './gldfVariants';
import { checkEmitterObjects, l3dAimLimits, l3dModelOf, openingNote } from './l3dModelOf';
import type { UploadZip } from './readUploadZip';

export type { ConvertOptions, ConvertedProduct } from './gldfConversion';

/**
 * The steps: the variants that fit (gldfVariants.ts), the CCTs every beam offers, the default
 * CCT, the beams (gldfBeams.ts), the imported variants reported, the default beam, the length, the
 * L3D model, the aiming ranges, the picture, and the type assembled from them.
 */
export function gldfToModuleType(product: GldfProduct, zip: UploadZip, options: ConvertOptions): ConvertedProduct {
  const conv = startConversion(product, zip, options);
  const { map, report, files, typeId } = conv;
  const accepted = acceptVariants(conv, options.mountings ?? DEFAULT_RAIL_MOUNTINGS);
  const { beamOrder, ccts, used } = offeredVariants(conv, accepted);
  if (used.length === 0) {
    report.notes.push('no variant fits the rail catalog: no module type made');
    return { type: null, files: [], report };
  }
  const defaultCct = chooseDefaultCct(conv, ccts, used[0].cct);
  const { beams, openings } = beamSpecs(conv, beamOrder, used, defaultCct);
  reportImported(report, used, beams, beamOrder);
  for (const key of Object.keys(map.beams ?? {})) if (!beamOrder.includes(key)) report.notes.push(`mapping beams.${key}: no imported variant uses that photometry`);
  const defaultBeam = chooseDefaultBeam(conv, beams);
  const lead = used[0].variant;
  const length = typeLength(conv, lead);
  const model = attachModel(conv, lead, used, openings);
  const adjustable = adjustableFor(lead, map, conv.assume, model ? { limits: l3dAimLimits(model.luminaire), entry: model.entry, note: (n) => report.notes.push(n) } : null);
  if (map.filterHolder === undefined) conv.assume('filterHolder', 'none', 'GLDF does not say whether a colour filter fits (mapping: filterHolder)');
  attachPicture(conv);
  const name = names(product.name, product.header.defaultLanguage);
  const type: ModuleTypeSpec = {
    id: typeId,
    name: name.name,
    ...(name.names ? { names: name.names } : {}),
    length,
    ccts,
    defaultCct,
    beams,
    defaultBeam,
    ...(map.filterHolder ? { filterHolder: true } : {}),
    ...(adjustable ? { adjustable } : {}),
    ...(model ? { model: model.path } : {}),
    ...(model?.emitterObject !== undefined ? { modelEmitter: model.emitterObject } : {}),
  };
  report.typeId = typeId;
  return { type, files, report };
}

function startConversion(product: GldfProduct, zip: UploadZip, options: ConvertOptions): Conversion {
  const map = options.mapping ?? {};
  const typeId = map.id ?? catalogSlug(product.uniqueProductId);
  const report: ProductReport = { source: product.source, uniqueProductId: product.uniqueProductId, typeId: null, imported: [], skipped: [], assumed: [], flux: [], files: [], notes: [] };
  const assume = (field: string, value: string, why: string): void => void report.assumed.push({ field, value, why });
  if (!map.id) assume('id', typeId, 'from the GLDF UniqueProductId (mapping: id)');
  return { product, zip, options, map, typeId, report, files: [], assume };
}

/** The mapping's default CCT when the type offers it, else the first imported variant's. */
function chooseDefaultCct(conv: Conversion, ccts: readonly number[], firstCct: number): number {
  const { map } = conv;
  if (map.defaultCct === undefined) {
    conv.assume('defaultCct', `${firstCct} K`, 'the first imported variant’s (mapping: defaultCct)');
    return firstCct;
  }
  if (ccts.includes(map.defaultCct)) return map.defaultCct;
  conv.report.notes.push(`mapping defaultCct ${map.defaultCct} K is not offered (${ccts.join(', ')} K); ${firstCct} K used`);
  return firstCct;
}

function reportImported(report: ProductReport, used: readonly Accepted[], beams: readonly BeamSpec[], beamOrder: readonly string[]): void {
  for (const a of used) {
    report.imported.push({
      variant: a.variant.id,
      productNumber: firstText(a.variant.productNumber),
      ...(a.variant.gtin ? { gtin: a.variant.gtin } : {}),
      beam: beams[beamOrder.indexOf(a.photometryId)].id,
      cct: a.cct,
      ...(a.cri !== undefined ? { cri: a.cri } : {}),
      ratedFlux: a.flux,
      ratedPower: a.watts,
    });
  }
}

/** The mapping's default beam when it is a beam, else the first. */
function chooseDefaultBeam(conv: Conversion, beams: readonly BeamSpec[]): string {
  const { map } = conv;
  const first = beams[0].id;
  if (map.defaultBeam === undefined) {
    conv.assume('defaultBeam', first, 'the first beam (mapping: defaultBeam)');
    return first;
  }
  if (beams.some((b) => b.id === map.defaultBeam)) return map.defaultBeam;
  conv.report.notes.push(`mapping defaultBeam '${map.defaultBeam}' is not a beam; '${first}' used`);
  return first;
}

/** Rail length: the mapping's, else the lead variant's ProductSize length (mm → m), else the default. */
function typeLength(conv: Conversion, lead: GldfVariant): number {
  if (conv.map.length !== undefined) return conv.map.length;
  const size = lead.productSize?.length;
  const length = size && size > 0 ? size / 1000 : GLDF_DEFAULTS.length;
  conv.assume('length', `${length} m`, size && size > 0 ? `the GLDF ProductSize length of ${lead.id} (mapping: length)` : 'the GLDF gives no ProductSize (mapping: length)');
  return length;
}

/** The lead variant's L3D body copied (docs/gldf.md, "L3D"), its emitter object checked, and a note per beam whose opening differs from it. */
function attachModel(conv: Conversion, lead: GldfVariant, used: readonly Accepted[], openings: readonly BeamOpening[]): ReturnType<typeof l3dModelOf> {
  const { product, report } = conv;
  const model = l3dModelOf(product, conv.zip, lead, conv.typeId);
  if (!model) return model;
  conv.files.push({ path: model.path, bytes: model.bytes });
  report.files.push(model.path);
  const others = used.filter((u) => u.variant.geometryId !== lead.geometryId).map((u) => u.variant.id);
  if (others.length) report.notes.push(`variants ${others.join(', ')} name another geometry; the type is drawn with ${lead.id}'s (${model.entry})`);
  model.emitterObject = checkEmitterObjects(
    product,
    model,
    used.filter((u) => u.variant.geometryId === lead.geometryId).map((u) => u.variant),
  );
  for (const o of openings) report.notes.push(...[openingNote(model.luminaire, model.emitterObject, o.beamId, o.opening)].filter((n): n is string => n !== null));
  return model;
}

/** The product's first picture in the container, copied as images/<type>.<ext>. */
function attachPicture(conv: Conversion): void {
  const { product } = conv;
  const picture = product.pictureFileIds.map((id) => product.files.get(id)).find((f) => f?.type === 'localFileName');
  if (!picture) return;
  const ext = /\.(\w+)$/.exec(picture.path)?.[1]?.toLowerCase() ?? 'img';
  const picturePath = `images/${conv.typeId}.${ext}`;
  conv.files.push({ path: picturePath, bytes: conv.zip.read(picture.path) });
  conv.report.files.push(picturePath);
}

function adjustableFor(
  v: GldfVariant,
  map: GldfProductMapping,
  assume: (f: string, v: string, why: string) => void,
  joints: { limits: ModuleTypeSpec['adjustable'] | null; entry: string; note: (n: string) => void } | null,
): ModuleTypeSpec['adjustable'] {
  if (map.adjustable === false) return undefined;
  if (map.adjustable) return map.adjustable;
  // The L3D's joints say how far the head turns: they replace the typical ranges (docs/gldf.md "Aiming").
  if (joints?.limits) {
    const { tilt, rotation } = joints.limits;
    const stops = (r: { stops?: number }) => (r.stops ? ` in ${r.stops}° stops` : '');
    joints.note(`aiming from the joints of ${joints.entry}: tilt ${tilt.min}–${tilt.max}°${stops(tilt)}, rotation ${rotation.min}–${rotation.max}°${stops(rotation)}`);
    return joints.limits;
  }
  const a = new Set(v.adjustabilities);
  const tilts = a.has('Tilt') || a.has('Cardanic');
  const turns = a.has('Turn') || a.has('Cardanic') || a.has('Orientation');
  if (!tilts && !turns) {
    assume('adjustable', 'fixed, straight down', `the GLDF declares ${a.size ? `Adjustability ${[...a].join(', ')}` : 'no Adjustability'} (mapping: adjustable)`);
    return undefined;
  }
  const range = {
    tilt: tilts ? { ...GLDF_DEFAULTS.tilt } : { min: 0, max: 0 },
    rotation: turns ? { ...GLDF_DEFAULTS.rotation } : { min: 0, max: 0 },
  };
  assume('adjustable', `tilt ${range.tilt.min}–${range.tilt.max}°, rotation ${range.rotation.min}–${range.rotation.max}°`, `GLDF Adjustability ${[...a].join(', ')} gives no angles (mapping: adjustable)`);
  return range;
}
