import { keyed } from '../configuration/coding';
import type { Configuration } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { firstPatchOverlap, formatPatchRange } from '../modules/dmxPatch';

/**
 * Channels shared by two patched modules (one problem: the first overlap, on the
 * later module in module order). Each patch's own ranges are a module rule
 * (ownProblems); this is the one rule across systems besides clashes.
 */
export function patchProblems(config: Configuration): Problem[] {
  const hit = firstPatchOverlap(config);
  if (!hit) return [];
  const { at, other } = hit;
  return [
    keyed({ code: 'dmx-overlap', path: `${at.path}.dmx`, message: `DMX ${formatPatchRange(at.patch)} of module ${at.module.id} overlaps module ${other.module.id} (${formatPatchRange(other.patch)})` }, 'dmxOverlap', {
      range: formatPatchRange(at.patch),
      id: at.module.id,
      other: other.module.id,
      otherRange: formatPatchRange(other.patch),
    }),
  ];
}
