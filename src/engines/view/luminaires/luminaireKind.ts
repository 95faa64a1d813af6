import type { ModuleTypeSpec } from '../../../core/model/catalogSchema/moduleTypeSchema';

/**
 * The kinds of luminaire the view draws (buildLuminaireModel.ts): a track spot (cylindrical head in a
 * yoke that turns and tilts with the aim), a downlight (a can with a trim ring round its opening), a
 * linear diffuser, a wall washer (a box with a visor on its back), a pendant (a slim bar hung below
 * the rail, emitting down and up).
 */
export const LUMINAIRE_KINDS = ['spot', 'downlight', 'linear', 'washer', 'pendant'] as const;
export type LuminaireKind = (typeof LUMINAIRE_KINDS)[number];

/**
 * The default catalog's module types (src/core/catalog/default-catalog.json): the spots, the warm-dim
 * spot and the flood have spotlight optics (a beam angle) → the spot head; the linear diffuser; the
 * wall washer; the direct/indirect linear (a Zumtobel LINETIK S suspended profile) → the pendant.
 */
const DEFAULT_CATALOG_KINDS: Readonly<Record<string, LuminaireKind>> = {
  spot: 'spot',
  'spot-warmdim': 'spot',
  flood: 'spot',
  linear: 'linear',
  washer: 'washer',
  updown: 'pendant',
};

/**
 * The kind of a catalog module type: the default catalog's by id; another catalog's by what the
 * type says: adjustable or a beam with a beam angle → spot; 0.5 m of rail or more → linear; else a downlight.
 */
export function kindOfModuleType(type: Pick<ModuleTypeSpec, 'id' | 'adjustable' | 'beams' | 'length'>): LuminaireKind {
  const known = DEFAULT_CATALOG_KINDS[type.id];
  if (known) return known;
  if (type.adjustable || type.beams.some((b) => b.beamAngle !== undefined)) return 'spot';
  return type.length >= 0.5 ? 'linear' : 'downlight';
}

/**
 * The kind of a lighting scene's luminaire (no catalog type), from its photometry and aim: more than
 * 20 % of the flux upward → pendant; an opening at least 4 × longer than wide → linear; pitched → spot;
 * else a downlight.
 */
export function kindOfLuminaire(opening: { width: number; length: number }, flux: { down: number; up: number }, pitch: number): LuminaireKind {
  const total = flux.down + flux.up;
  if (total > 0 && flux.up / total > 0.2) return 'pendant';
  const long = Math.max(Math.abs(opening.width), Math.abs(opening.length));
  const short = Math.min(Math.abs(opening.width), Math.abs(opening.length));
  if (long > 0 && long >= 4 * short) return 'linear';
  return pitch !== 0 ? 'spot' : 'downlight';
}
