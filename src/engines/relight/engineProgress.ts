import type { EngineProgress } from './RelightEngine';

/** Share of the progress fraction taken by the direct bases (cheap: no bounces), the rest is the shared solve. */
const DIRECT_SHARE = 0.1;

/**
 * The engine's progress from its parts: `based` of `groups` direct bases baked, whether the scene's
 * own weights are solved (`solved`) and, during a fade, the faded-from weights too (`fromSolved`),
 * and how far the solve under way is (`solveFraction`, 0..1).
 */
export function engineProgress(groups: number, based: number, solved: boolean, fromSolved: boolean, solveFraction: number): EngineProgress {
  const lit = based === groups;
  // The pending work is the scene's own solve; during a fade the image is exact when both ends are solved.
  const done = lit && solved;
  const exact = done && fromSolved;
  const fraction = groups === 0 ? 1 : DIRECT_SHARE * (based / groups) + (1 - DIRECT_SHARE) * (done ? 1 : solveFraction);
  return { groupsDone: based, groups, fraction: Math.min(1, fraction), done, lit, exact };
}
