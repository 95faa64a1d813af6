/**
 * A system's own rules, whatever its place in the plan: how it hangs, its joints and tree, its rails
 * and modules, its feeds, its moved fixing points — in that order, each stage only where the ones
 * before it let the next make sense.
 */
import type { Catalog } from '../catalogSchema/catalogSchema';
import { keyed } from '../configuration/coding';
import type { LightSystem } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { perCatalog } from '../catalogSchema/perCatalog';
import { fixingProblem } from '../rails/fixingRules';
import { treeProblem } from '../rails/railTree';
import { feedOverloadProblems, feedProblems } from './feedProblems';
import { hangingProblems } from './hangingProblems';
import { jointProblems, railProblems } from './railProblems';
import type { ReportProblem, ReportSubProblem } from './reporting';

/** A system's own rules, with paths relative to the system ('.rails[0].length'): the part of systemProblems that does not depend on where it stands, but for a finite x and z. */
export function systemOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  return ownProblems(s, '', roomHeight, catalog);
}

/**
 * A system's own problems, worked out once per system object, catalog and room height
 * (perCatalog.ts) with paths relative to the system: validate() after every action, and the clash
 * checks against every other system, ask again for the systems the action left alone.
 */
const ownByHeight = perCatalog((_s: LightSystem) => new Map<number, readonly Problem[]>());

export function ownProblems(s: LightSystem, at: string, roomHeight: number, catalog: Catalog): Problem[] {
  const known = ownByHeight(s, catalog);
  let list = known.get(roomHeight);
  if (!list) known.set(roomHeight, (list = computeOwnProblems(s, roomHeight, catalog)));
  return list.map((q) => ({ ...q, path: `${at}${q.path}` }));
}

function computeOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  const at = '';
  const out: Problem[] = [];
  // `key`: the sentence's own code where the rule has several (docs/i18n.md); its params then travel non-enumerable.
  const p: ReportProblem = (code, path, message, params, key) =>
    out.push(key ? keyed({ code, path: `${at}${path}`, message }, key, params) : { code, path: `${at}${path}`, message, ...(params ? { params } : {}) });
  // A sub-rule's problem (fixing points, free positions, the tree, aim, filter, patch) with its own coding.
  const sub: ReportSubProblem = (code, path, found) => p(code, path, found.message, found.params, found.key);
  hangingProblems(s, roomHeight, catalog, p);
  jointProblems(s, catalog, p);
  if (out.length === 0) {
    // The tree (railTree.ts): parents before children, one connector per node, its ports.
    const t = treeProblem(s, catalog);
    if (t) sub(t.code, `.joints[${t.joint}].${t.field}`, t);
  }
  railProblems(s, catalog, p, sub);
  feedProblems(s, catalog, p);
  if (out.length === 0) feedOverloadProblems(s, catalog, p);
  // Moved fixing points (fixingRules.ts), once the chain itself is sound.
  if (out.length === 0 && s.fixings !== undefined) {
    const f = Array.isArray(s.fixings) ? fixingProblem(s, s.fixings, catalog) : keyed({ code: 'fixing-order', index: 0, message: 'fixings must be a list of chain coordinates' }, 'fixingsNotList');
    if (f) sub(f.code, `.fixings[${f.index}]`, f);
  }
  return out;
}
