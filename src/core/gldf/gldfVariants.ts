/**
 * Which of a product's variants become the type's beams × CCTs (docs/gldf.md, "Rules"): each
 * variant on its own (mounting, one emitter with one photometry file, rated flux and power), then
 * only CCTs every beam offers, one variant per beam × CCT.
 */
import type { Accepted, Conversion } from './gldfConversion';
import { GLDF_DEFAULTS } from './gldfDefaults';
import { quoteName } from './GldfError';
import type { GldfProduct, GldfVariant } from './gldfProduct';

/** The variants that can be a beam × CCT, in the product's sort order; the others reported as skipped. */
export function acceptVariants(conv: Conversion, mountings: readonly string[]): Accepted[] {
  const { product, report, assume } = conv;
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
  return accepted;
}

/** The beams (photometry ids) in order of first appearance, the CCTs every beam offers, and the variants used: one per beam × common CCT. */
export function offeredVariants(conv: Conversion, accepted: readonly Accepted[]): { beamOrder: string[]; ccts: number[]; used: Accepted[] } {
  const beamOrder = [...new Set(accepted.map((a) => a.photometryId))];
  const cctsOf = (pid: string): Set<number> => new Set(accepted.filter((a) => a.photometryId === pid).map((a) => a.cct));
  const common = beamOrder.length === 0 ? [] : [...cctsOf(beamOrder[0])].filter((k) => beamOrder.every((pid) => cctsOf(pid).has(k))).sort((a, b) => a - b);
  const used: Accepted[] = [];
  for (const a of accepted) {
    const twin = used.find((u) => u.photometryId === a.photometryId && u.cct === a.cct);
    if (!common.includes(a.cct)) conv.report.skipped.push({ variant: a.variant.id, reason: `${a.cct} K is not offered with every optic of the product (the catalog offers each beam in each CCT: ${common.join(', ') || 'none'} K)` });
    else if (twin) conv.report.skipped.push({ variant: a.variant.id, reason: `same photometry and CCT as ${twin.variant.id}; not a separate catalog option` });
    else used.push(a);
  }
  return { beamOrder, ccts: common, used };
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
