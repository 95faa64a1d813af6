/**
 * One beam of the type per GLDF photometry (docs/gldf.md, "Rules"): its id, label, article, price,
 * roll and rated values from the variant of the default CCT (else the first), the photometry file
 * copied, and each variant's rated flux checked against the file's integral.
 */
import { InputError } from '../inputError';
import type { BeamSpec } from '../model/catalogSchema/moduleTypeSchema';
import { lumensWarning } from '../photometry/checks';
import { PhotometryParseError } from '../photometry/PhotometryParseError';
import { beamAndField, integrateFlux, parsePhotometry, type Photometry } from '../photometry';
import type { Accepted, Conversion } from './gldfConversion';
import { GLDF_DEFAULTS, catalogSlug, commonArticle } from './gldfDefaults';
import { GldfError, quoteName } from './GldfError';
import type { FluxCheck } from './gldfImportReport';
import type { GldfBeamMapping } from './gldfMapping';
import { firstText, names } from './gldfNames';
import type { GldfFile } from './gldfProduct';
import type { UploadZip } from './readUploadZip';

/** A beam's luminous opening, for the notes on the L3D model's emitter. */
export interface BeamOpening {
  beamId: string;
  opening: Photometry['luminousOpening'];
}

/** The beams in `beamOrder`, each from the used variants of its photometry. */
export function beamSpecs(conv: Conversion, beamOrder: readonly string[], used: readonly Accepted[], defaultCct: number): { beams: BeamSpec[]; openings: BeamOpening[] } {
  const beams: BeamSpec[] = [];
  const openings: BeamOpening[] = [];
  const usedBeamIds = new Set<string>();
  for (const pid of beamOrder) {
    const mine = used.filter((a) => a.photometryId === pid);
    const lead = mine.find((a) => a.cct === defaultCct) ?? mine[0];
    const beamId = claimBeamId(conv, pid, usedBeamIds);
    const ph = readPhotometry(conv.zip, lead.file);
    const integrated = integrateFlux(ph);
    for (const a of mine) conv.report.flux.push(fluxCheck(a, beamId, integrated));
    openings.push({ beamId, opening: ph.luminousOpening });
    beams.push(beamSpec(conv, pid, beamId, mine, lead, ph));
  }
  return { beams, openings };
}

/** The beam's id (the mapping's, else the photometry id as a slug), unique within the type. */
function claimBeamId(conv: Conversion, pid: string, usedBeamIds: Set<string>): string {
  const bm: GldfBeamMapping = conv.map.beams?.[pid] ?? {};
  const beamId = bm.id ?? catalogSlug(pid);
  if (usedBeamIds.has(beamId)) throw new GldfError(`${conv.product.source}: two photometries become beam '${beamId}' of type '${conv.typeId}'; give one an id in the mapping file`);
  usedBeamIds.add(beamId);
  if (!bm.id) conv.assume(`beam ${beamId} id`, beamId, `from the GLDF Photometry id ${quoteName(pid)} (mapping: beams.${pid}.id)`);
  return beamId;
}

function beamSpec(conv: Conversion, pid: string, beamId: string, mine: readonly Accepted[], lead: Accepted, ph: Photometry): BeamSpec {
  const { product, report, assume } = conv;
  const bm: GldfBeamMapping = conv.map.beams?.[pid] ?? {};
  const label = names(bm.label ? [{ language: 'en', text: bm.label }] : (lead.emitterName ?? []), product.header.defaultLanguage);
  const labelText = label.name || `${beamId}`;
  if (!bm.label && !lead.emitterName?.some((l) => l.text)) assume(`beam ${beamId} label`, labelText, 'the light emitter has no Name (mapping: beams.<id>.label)');
  const labels = bm.labels ?? label.names;
  const numbers = mine.map((a) => firstText(a.variant.productNumber)).filter(Boolean);
  const article = beamArticle(conv, bm, beamId, numbers, lead);
  const price = beamPrice(conv, bm, beamId, lead);
  const roll = bm.roll ?? GLDF_DEFAULTS.roll;
  if (bm.roll === undefined) assume(`beam ${beamId} roll`, `${roll}°`, 'C0 along the rail (mapping: beams.<id>.roll)');
  const watts = Math.max(...mine.map((a) => a.watts));
  if (mine.some((a) => a.watts !== watts)) report.notes.push(`beam ${beamId}: rated power differs by CCT; the largest, ${watts} W, sizes the drivers`);
  if (mine.some((a) => a.flux !== lead.flux)) report.notes.push(`beam ${beamId}: rated flux differs by CCT; the ${lead.cct} K variant's ${lead.flux} lm is the catalog's`);
  const angle = beamAngle(ph);
  const ext = lead.file.contentType === 'ldc/ies' ? 'ies' : 'ldt';
  const photometryPath = `ies/${conv.typeId}-${beamId}.${ext}`;
  conv.files.push({ path: photometryPath, bytes: conv.zip.read(lead.file.path) });
  report.files.push(photometryPath);
  return {
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
  };
}

/** The mapping's article, else the common prefix of the variants' product numbers (the bill of materials adds -<cct>). */
function beamArticle(conv: Conversion, bm: GldfBeamMapping, beamId: string, numbers: string[], lead: Accepted): string {
  let article = bm.article ?? commonArticle(numbers);
  if (!bm.article) {
    if (!article) article = numbers[0] ?? lead.variant.id;
    conv.assume(`beam ${beamId} article`, article, 'common prefix of the variants’ product numbers; the bill of materials adds -<cct> (mapping: beams.<id>.article)');
  }
  return article;
}

/** The beam's or the type's mapped price, else the lead variant's ListPrice in the catalog's currency, else the default. */
function beamPrice(conv: Conversion, bm: GldfBeamMapping, beamId: string, lead: Accepted): number {
  const listPrice = lead.variant.listPrices.find((p) => p.currency === conv.options.currency)?.price;
  let price = bm.price ?? conv.map.price ?? listPrice;
  if (price === undefined) {
    price = GLDF_DEFAULTS.price;
    conv.assume(`beam ${beamId} price`, String(price), `no ListPrice in ${conv.options.currency} and none in the mapping`);
  }
  return price;
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
