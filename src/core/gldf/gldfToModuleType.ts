/**
 * One GLDF product → one module type of the rail catalog (docs/gldf.md, "Rules"). A product is
 * what a manufacturer sells as one luminaire with options; its variants differ by optic (→
 * beams) and colour temperature (→ CCTs). The catalog offers every beam in every CCT of a type,
 * so only CCTs every beam has are imported; the rest is reported. Values neither the GLDF nor
 * the mapping file give take the defaults below, each listed in the report.
 */
import { InputError } from '../inputError';
import type { BeamSpec, ModuleTypeSpec } from '../model/catalogSchema/moduleTypeSchema';
import { lumensWarning } from '../photometry/checks';
import { PhotometryParseError } from '../photometry/PhotometryParseError';
import { beamAndField, integrateFlux, parsePhotometry, type Photometry } from '../photometry';
import { GldfError, quoteName } from './GldfError';
import type { FluxCheck, ProductReport } from './gldfImportReport';
import { DEFAULT_RAIL_MOUNTINGS, type GldfBeamMapping, type GldfProductMapping } from './gldfMapping';
import type { GldfFile, GldfProduct, GldfVariant, LocaleTexts } from './gldfProduct';
import { checkEmitterObjects, l3dAimLimits, l3dModelOf, openingNote } from './l3dModelOf';
import type { UploadZip } from './readUploadZip';

/** Defaults for what neither the GLDF nor the mapping gives (docs/gldf.md, "Defaults"). */
export const GLDF_DEFAULTS = {
  /** Rail length a module occupies when the GLDF has no ProductSize: the demo catalog's spot. */
  length: 0.15,
  /** Price when neither the mapping nor a ListPrice in the catalog's currency gives one. */
  price: 0,
  roll: 0,
  /** CCT of a light source that states none. */
  cct: 3000,
  /** Aiming ranges of an adjustable head (GLDF Adjustability Tilt/Turn/Cardanic): the demo spot's. */
  tilt: { min: 0, max: 90 },
  rotation: { min: 0, max: 355 },
} as const;

/** Catalog languages and the GLDF Locale languages they take (a region is ignored: 'de-CH' is German). */
const LANGUAGES = ['en', 'de', 'fr', 'it'] as const;

export interface ConvertOptions {
  mapping?: GldfProductMapping;
  mountings?: readonly string[];
  currency: string;
}

export interface ConvertedProduct {
  type: ModuleTypeSpec | null;
  files: { path: string; bytes: Uint8Array }[];
  report: ProductReport;
}

interface Accepted {
  variant: GldfVariant;
  photometryId: string;
  file: GldfFile;
  cct: number;
  cri?: number;
  flux: number;
  watts: number;
  kind: 'luminaire' | 'lamp';
  emitterName?: LocaleTexts;
  /** The light source states no CCT: GLDF_DEFAULTS.cct. */
  cctAssumed?: boolean;
}

/** A catalog id from a GLDF id or number: lower case, runs of other characters as '-'. */
export function catalogSlug(value: string): string {
  const s = value
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '')
    .slice(0, 64)
    .replace(/-+$/, '');
  return s || 'product';
}

/** The text for a catalog language: the Locale of that language (any region), else undefined. */
function localeFor(texts: LocaleTexts | undefined, language: string): string | undefined {
  return texts?.find((l) => l.text && l.language.toLowerCase().split(/[-_]/)[0] === language)?.text;
}

/** The catalog's name (English, else the GLDF's default language, else the first) and its translations. */
function names(texts: LocaleTexts, defaultLanguage: string | undefined): { name: string; names?: Partial<Record<(typeof LANGUAGES)[number], string>> } {
  const name = localeFor(texts, 'en') ?? (defaultLanguage ? localeFor(texts, defaultLanguage.toLowerCase().split(/[-_]/)[0]) : undefined) ?? texts.find((l) => l.text)?.text ?? '';
  const out: Partial<Record<(typeof LANGUAGES)[number], string>> = {};
  for (const lang of LANGUAGES) {
    const t = localeFor(texts, lang);
    if (t !== undefined) out[lang] = t;
  }
  return Object.keys(out).length > 0 ? { name, names: out } : { name };
}

const firstText = (texts: LocaleTexts): string => texts.find((l) => l.text)?.text ?? '';

/** The longest common prefix of the beam's article numbers, trimmed at a separator ('LX-TS-N15-30', 'LX-TS-N15-40' → 'LX-TS-N15'). */
export function commonArticle(numbers: string[]): string {
  if (numbers.length < 2) return '';
  // Cut first: a hostile file's product numbers may be megabytes long.
  let prefix = numbers[0].slice(0, 100);
  for (const n of numbers) while (!n.startsWith(prefix)) prefix = prefix.slice(0, -1);
  return prefix.replace(/[-_./ ]+$/, '');
}

export function gldfToModuleType(product: GldfProduct, zip: UploadZip, options: ConvertOptions): ConvertedProduct {
  const map = options.mapping ?? {};
  const mountings = options.mountings ?? DEFAULT_RAIL_MOUNTINGS;
  const typeId = map.id ?? catalogSlug(product.uniqueProductId);
  const report: ProductReport = { source: product.source, uniqueProductId: product.uniqueProductId, typeId: null, imported: [], skipped: [], assumed: [], flux: [], files: [], notes: [] };
  const assume = (field: string, value: string, why: string): void => void report.assumed.push({ field, value, why });
  if (!map.id) assume('id', typeId, 'from the GLDF UniqueProductId (mapping: id)');

  const order = product.variants.map((v, i) => ({ v, i })).sort((a, b) => (a.v.sortOrder ?? Infinity) - (b.v.sortOrder ?? Infinity) || a.i - b.i);
  const accepted: Accepted[] = [];
  for (const { v } of order) {
    const reason = variantProblem(product, v, mountings);
    if (typeof reason === 'string') report.skipped.push({ variant: v.id, reason });
    else {
      if (v.mountings === null) assume(`mounting of ${v.id}`, 'fits the rail', 'the variant declares no Mountings');
      if (reason.cctAssumed) assume(`CCT of ${v.id}`, `${reason.cct} K`, 'its light source states no CorrelatedColorTemperature');
      accepted.push(reason);
    }
  }

  // Beams in order of first appearance; only CCTs that every beam offers.
  const beamOrder = [...new Set(accepted.map((a) => a.photometryId))];
  const cctsOf = (pid: string): Set<number> => new Set(accepted.filter((a) => a.photometryId === pid).map((a) => a.cct));
  const common = beamOrder.length === 0 ? [] : [...cctsOf(beamOrder[0])].filter((k) => beamOrder.every((pid) => cctsOf(pid).has(k))).sort((a, b) => a - b);
  const used: Accepted[] = [];
  for (const a of accepted) {
    const twin = used.find((u) => u.photometryId === a.photometryId && u.cct === a.cct);
    if (!common.includes(a.cct)) report.skipped.push({ variant: a.variant.id, reason: `${a.cct} K is not offered with every optic of the product (the catalog offers each beam in each CCT: ${common.join(', ') || 'none'} K)` });
    else if (twin) report.skipped.push({ variant: a.variant.id, reason: `same photometry and CCT as ${twin.variant.id}; not a separate catalog option` });
    else used.push(a);
  }
  if (used.length === 0) {
    report.notes.push('no variant fits the rail catalog: no module type made');
    return { type: null, files: [], report };
  }
  const ccts = common;
  const firstCct = used[0].cct;
  let defaultCct = firstCct;
  if (map.defaultCct !== undefined) {
    if (ccts.includes(map.defaultCct)) defaultCct = map.defaultCct;
    else report.notes.push(`mapping defaultCct ${map.defaultCct} K is not offered (${ccts.join(', ')} K); ${firstCct} K used`);
  } else assume('defaultCct', `${firstCct} K`, 'the first imported variant’s (mapping: defaultCct)');

  const files: ConvertedProduct['files'] = [];
  const beams: BeamSpec[] = [];
  const usedBeamIds = new Set<string>();
  const openings: { beamId: string; opening: Photometry['luminousOpening'] }[] = [];
  for (const pid of beamOrder) {
    const mine = used.filter((a) => a.photometryId === pid);
    const bm: GldfBeamMapping = map.beams?.[pid] ?? {};
    const lead = mine.find((a) => a.cct === defaultCct) ?? mine[0];
    const beamId = bm.id ?? catalogSlug(pid);
    if (usedBeamIds.has(beamId)) throw new GldfError(`${product.source}: two photometries become beam '${beamId}' of type '${typeId}'; give one an id in the mapping file`);
    usedBeamIds.add(beamId);
    if (!bm.id) assume(`beam ${beamId} id`, beamId, `from the GLDF Photometry id ${quoteName(pid)} (mapping: beams.${pid}.id)`);
    const ph = readPhotometry(zip, lead.file);
    const integrated = integrateFlux(ph);
    for (const a of mine) report.flux.push(fluxCheck(a, beamId, integrated));
    const label = names(bm.label ? [{ language: 'en', text: bm.label }] : (lead.emitterName ?? []), product.header.defaultLanguage);
    const labelText = label.name || `${beamId}`;
    if (!bm.label && !lead.emitterName?.some((l) => l.text)) assume(`beam ${beamId} label`, labelText, 'the light emitter has no Name (mapping: beams.<id>.label)');
    const labels = bm.labels ?? label.names;
    const numbers = mine.map((a) => firstText(a.variant.productNumber)).filter(Boolean);
    let article = bm.article ?? commonArticle(numbers);
    if (!bm.article) {
      if (!article) article = numbers[0] ?? lead.variant.id;
      assume(`beam ${beamId} article`, article, 'common prefix of the variants’ product numbers; the bill of materials adds -<cct> (mapping: beams.<id>.article)');
    }
    const listPrice = lead.variant.listPrices.find((p) => p.currency === options.currency)?.price;
    let price = bm.price ?? map.price ?? listPrice;
    if (price === undefined) {
      price = GLDF_DEFAULTS.price;
      assume(`beam ${beamId} price`, String(price), `no ListPrice in ${options.currency} and none in the mapping`);
    }
    const roll = bm.roll ?? GLDF_DEFAULTS.roll;
    if (bm.roll === undefined) assume(`beam ${beamId} roll`, `${roll}°`, 'C0 along the rail (mapping: beams.<id>.roll)');
    const watts = Math.max(...mine.map((a) => a.watts));
    if (mine.some((a) => a.watts !== watts)) report.notes.push(`beam ${beamId}: rated power differs by CCT; the largest, ${watts} W, sizes the drivers`);
    if (mine.some((a) => a.flux !== lead.flux)) report.notes.push(`beam ${beamId}: rated flux differs by CCT; the ${lead.cct} K variant's ${lead.flux} lm is the catalog's`);
    openings.push({ beamId, opening: ph.luminousOpening });
    const angle = beamAngle(ph);
    const ext = lead.file.contentType === 'ldc/ies' ? 'ies' : 'ldt';
    const photometryPath = `ies/${typeId}-${beamId}.${ext}`;
    files.push({ path: photometryPath, bytes: zip.read(lead.file.path) });
    report.files.push(photometryPath);
    beams.push({
      id: beamId,
      label: labelText,
      ...(labels ? { labels } : {}),
      ...(angle !== undefined ? { beamAngle: angle } : {}),
      article,
      photometry: photometryPath,
      lumens: lead.flux,
      watts,
      roll,
      price,
      source: `GLDF ${product.source}, variant ${lead.variant.id}${numbers.length ? ` (${firstText(lead.variant.productNumber)})` : ''}: rated ${lead.flux} lm, ${lead.watts} W${lead.cri !== undefined ? `, CRI ${lead.cri}` : ''}`,
    });
  }
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
  for (const key of Object.keys(map.beams ?? {})) if (!beamOrder.includes(key)) report.notes.push(`mapping beams.${key}: no imported variant uses that photometry`);

  let defaultBeam = beams[0].id;
  if (map.defaultBeam !== undefined) {
    if (beams.some((b) => b.id === map.defaultBeam)) defaultBeam = map.defaultBeam;
    else report.notes.push(`mapping defaultBeam '${map.defaultBeam}' is not a beam; '${defaultBeam}' used`);
  } else assume('defaultBeam', defaultBeam, 'the first beam (mapping: defaultBeam)');

  const lead = used[0].variant;
  let length = map.length;
  if (length === undefined) {
    const size = lead.productSize?.length;
    length = size && size > 0 ? size / 1000 : GLDF_DEFAULTS.length;
    assume('length', `${length} m`, size && size > 0 ? `the GLDF ProductSize length of ${lead.id} (mapping: length)` : 'the GLDF gives no ProductSize (mapping: length)');
  }
  const model = l3dModelOf(product, zip, lead, typeId);
  if (model) {
    files.push({ path: model.path, bytes: model.bytes });
    report.files.push(model.path);
    const others = used.filter((u) => u.variant.geometryId !== lead.geometryId).map((u) => u.variant.id);
    if (others.length) report.notes.push(`variants ${others.join(', ')} name another geometry; the type is drawn with ${lead.id}'s (${model.entry})`);
    model.emitterObject = checkEmitterObjects(
      product,
      model,
      used.filter((u) => u.variant.geometryId === lead.geometryId).map((u) => u.variant),
    );
    for (const o of openings) report.notes.push(...[openingNote(model.luminaire, model.emitterObject, o.beamId, o.opening)].filter((n): n is string => n !== null));
  }
  const adjustable = adjustableFor(lead, map, assume, model ? { limits: l3dAimLimits(model.luminaire), entry: model.entry, note: (n) => report.notes.push(n) } : null);
  if (map.filterHolder === undefined) assume('filterHolder', 'none', 'GLDF does not say whether a colour filter fits (mapping: filterHolder)');
  const picture = product.pictureFileIds.map((id) => product.files.get(id)).find((f) => f?.type === 'localFileName');
  if (picture) {
    const ext = /\.(\w+)$/.exec(picture.path)?.[1]?.toLowerCase() ?? 'img';
    const picturePath = `images/${typeId}.${ext}`;
    files.push({ path: picturePath, bytes: zip.read(picture.path) });
    report.files.push(picturePath);
  }
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

/** Why a variant cannot become a beam × CCT of the type, or what it offers. */
function variantProblem(product: GldfProduct, v: GldfVariant, mountings: readonly string[]): string | Accepted {
  if (v.mountings !== null && !v.mountings.some((m) => mountings.includes(m))) {
    return `mounting ${v.mountings.join(', ') || 'none'} does not fit the rail (${mountings.join(', ')})`;
  }
  if (v.emitterIds.length === 0) return 'its Geometry names no emitter';
  if (v.emitterIds.length > 1) return `${v.emitterIds.length} emitters; a rail module carries one photometry`;
  const emitter = product.emitters.get(v.emitterIds[0]);
  const light = emitter?.lightEmitters ?? [];
  if (light.length !== 1) return `emitter ${quoteName(v.emitterIds[0])} holds ${light.length} light emitters; a rail module carries one photometry`;
  const le = light[0];
  if (le.kind !== 'fixed' && le.kind !== 'changeable') return `a ${le.kind} emitter has no single photometry`;
  const photometry = product.photometries.get(le.photometryId ?? '');
  const file = photometry ? product.files.get(photometry.fileId) : undefined;
  if (!photometry || !file) return 'no photometry';
  if (file.type !== 'localFileName') return `photometry ${quoteName(photometry.id)} is a link, not a file in the container`;
  if (file.contentType !== 'ldc/eulumdat' && file.contentType !== 'ldc/ies') return `photometry ${quoteName(photometry.id)} is ${file.contentType} (IES and EULUMDAT are read)`;
  const source = product.lightSources.get(le.lightSourceId ?? '');
  let flux: number | undefined;
  let watts: number | undefined;
  if (le.kind === 'fixed') {
    flux = le.ratedLuminousFlux;
    watts = source?.ratedInputPower;
  } else {
    const eq = product.equipments.get(le.equipmentId ?? '');
    if (!eq) return 'a changeable light emitter without Equipment states no flux or power';
    flux = source?.ratedLuminousFlux !== undefined ? source.ratedLuminousFlux * eq.lightSourceCount : undefined;
    watts = eq.ratedInputPower;
  }
  if (!(flux !== undefined && flux > 0)) return 'no rated luminous flux above 0';
  if (!(watts !== undefined && watts > 0)) return 'no rated input power above 0';
  const cct = source?.cct !== undefined ? Math.round(source.cct) : GLDF_DEFAULTS.cct;
  return {
    variant: v,
    photometryId: photometry.id,
    file,
    cct,
    ...(source?.cri !== undefined ? { cri: source.cri } : {}),
    flux,
    watts,
    kind: le.kind === 'fixed' ? 'luminaire' : 'lamp',
    ...(le.name ? { emitterName: le.name } : {}),
    ...(source?.cct === undefined ? { cctAssumed: true } : {}),
  };
}

/** Parses the photometry from the container; a file the project's parser refuses refuses the GLDF. */
function readPhotometry(zip: UploadZip, file: GldfFile): Photometry {
  const bytes = zip.read(file.path);
  const ext = file.contentType === 'ldc/ies' ? '.ies' : '.ldt';
  const name = file.path.toLowerCase().endsWith(ext) ? file.path : `${file.path}${ext}`;
  try {
    return parsePhotometry(bytes, name);
  } catch (error) {
    // PhotometryParseError's message starts with the file name it was given (the entry's path, cut to 60 characters).
    if (error instanceof InputError) {
      const rest = error instanceof PhotometryParseError && error.message.startsWith(name) ? error.message.slice(name.length) : `: ${error.message}`;
      throw new GldfError(`${zip.source}: entry ${quoteName(file.path)}${rest}`);
    }
    throw error;
  }
}

function fluxCheck(a: Accepted, beam: string, integrated: number): FluxCheck {
  return {
    variant: a.variant.id,
    beam,
    photometry: a.file.path,
    ratedFlux: a.flux,
    integratedFlux: integrated,
    differencePercent: ((integrated - a.flux) / a.flux) * 100,
    kind: a.kind,
    warning: lumensWarning(integrated, a.flux, a.kind),
  };
}

/**
 * The catalog's beam angle: the half-peak full angle (beamAndField, IES/CIE definition) when
 * both plane pairs agree within 2° and it is under 90° — a round spot or flood; omitted for
 * asymmetric, wide or linear distributions, as the demo catalog does for its diffusers.
 */
function beamAngle(ph: Photometry): number | undefined {
  const { c0, c90 } = beamAndField(ph);
  if (!(c0.beam < 90 && Math.abs(c0.beam - c90.beam) <= 2)) return undefined;
  return Math.round((c0.beam + c90.beam) / 2);
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
