/**
 * Validity of a configuration, defined on the state alone (independent of the
 * actions that produced it). The always-valid guarantee is: validate() of any
 * state reachable through enabled actions is empty; the property test in
 * tests/core/model checks it.
 */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { lightSceneProblems } from '../cues/lightScenes';
import { allObjectProblems } from '../objects/objectProblems';
import { systemElementTree, type PlanRect, type SystemElementTree } from '../rails/geometry';
import { patchProblems } from './patchProblems';
import { forEachOverlap } from './planOverlaps';
import { idProblems, roomProblems } from './roomProblems';
import { roomFitProblem } from './systemProblems';
import { ownProblems } from './systemOwnProblems';

export interface ValidateOptions {
  /**
   * Stop at the first stage that finds a problem (room, ids, each system's own
   * rules, room bounds, self-crossing, overlaps between systems) and, in the
   * pair stages, at the first clash: what readers of untrusted files need (they
   * report one problem), so a cheap problem is never hidden behind pair checks.
   */
  firstOnly?: boolean;
  /** Counts the exact (separating-axis) rectangle tests, for tests of the broad phase. */
  stats?: { pairTests: number };
}

/**
 * All problems of a configuration, in a stable order: room, ids, then per
 * system its own rules or else its geometry (outside, self-overlap, clashes
 * with other systems). Pair checks use a uniform grid over the plan, so a hall
 * with hundreds of rails costs O(n) exact rectangle tests, not O(n²).
 */
export function validate(config: Configuration, catalog: Catalog, options: ValidateOptions = {}): Problem[] {
  const first = options.firstOnly === true;
  const stats = options.stats ?? { pairTests: 0 };
  const problems: Problem[] = roomProblems(config);
  if (first && problems.length > 0) return problems;
  problems.push(...idProblems(config));
  if (first && problems.length > 0) return problems;
  problems.push(...patchProblems(config));
  if (first && problems.length > 0) return problems;
  problems.push(...lightSceneProblems(config));
  if (first && problems.length > 0) return problems;
  const n = config.systems.length;
  const own = config.systems.map((s, i) => ownProblems(s, `systems[${i}]`, config.room.height, catalog));
  if (first) {
    const bad = own.find((p) => p.length > 0);
    if (bad) return [...problems, ...bad];
  }
  // Geometry only for systems whose own rules hold (it needs sound references and numbers).
  const trees: (SystemElementTree | null)[] = config.systems.map((s, i) => (own[i].length === 0 ? systemElementTree(s, catalog) : null));
  const elements = trees.map((t) => t?.elements ?? null);
  const outside = config.systems.map((s, i) => {
    const el = elements[i];
    return el !== null ? roomFitProblem(s, i, el, config.room, catalog) : null;
  });
  if (first) {
    const out = outside.find((p) => p !== null);
    if (out) return [...problems, out];
  }
  // One grid over every element of every sound system: self-crossings (same
  // system, elements that do not touch by design: SystemElementTree.near) and clashes between systems.
  const rects: PlanRect[] = [];
  const owner: number[] = [];
  const chainIndex: number[] = [];
  elements.forEach((el, i) => el?.forEach((group, a) => group.forEach((r) => (rects.push(r), owner.push(i), chainIndex.push(a)))));
  const selfCrossing = new Set<number>();
  const clashes = Array.from({ length: n }, () => new Set<number>());
  forEachOverlap(
    rects,
    stats,
    (p, q) => {
      const [i, j] = [owner[p], owner[q]];
      if (i === j) {
        if (trees[i]!.near[chainIndex[p]].has(chainIndex[q]) || selfCrossing.has(i)) return 'skip';
        selfCrossing.add(i);
      } else {
        if (clashes[i].has(j)) return 'skip';
        clashes[i].add(j);
        clashes[j].add(i);
      }
      return first ? 'stop' : 'continue';
    },
    (p, q) => {
      // Cheap pre-filter: pairs whose answer is already known need no exact test.
      const [i, j] = [owner[p], owner[q]];
      return i === j ? !trees[i]!.near[chainIndex[p]].has(chainIndex[q]) && !selfCrossing.has(i) : !clashes[i].has(j);
    },
  );
  config.systems.forEach((s, i) => {
    if (own[i].length > 0) return problems.push(...own[i]);
    const at = `systems[${i}]`;
    if (outside[i]) problems.push(outside[i]);
    if (selfCrossing.has(i)) problems.push({ code: 'self-overlap', path: at, message: `system ${s.id} runs into itself`, params: { id: s.id } });
    [...clashes[i]].sort((a, b) => a - b).forEach((j) => problems.push({ code: 'system-overlap', path: at, message: `system ${s.id} overlaps system ${config.systems[j].id}`, params: { id: s.id, other: config.systems[j].id } }));
  });
  if (first && problems.length > 0) return problems;
  // Objects last: they never clash with systems or each other (overlapping furniture is the user's business).
  problems.push(...allObjectProblems(config, first));
  return problems;
}
