/**
 * Remedies (issue 27, "No dead ends"; docs/model.md, "Remedies"): for a refused action, the
 * change that would make it enabled — a larger driver, a second feed, a longer rail, or a longer
 * rail and a larger driver together — as data the UI offers as one tap next to the refused
 * control. Pure: it only asks the model (attemptAction) what each candidate would do, so a remedy
 * is offered exactly when performing it makes the refused action pass validate().
 */
import { attemptAction, checkAction, type ActionName } from '../actions/actionDefinitions';
import { billOfMaterials } from '../power/billOfMaterials';
import { type Catalog } from '../catalogSchema/catalogSchema';
import { DISTRIBUTIONS } from '../catalogSchema/railSystemSchema';
import { isFreeRail } from '../rails/freePositions';
import type { Configuration, FeedAt, LightSystem } from '../configuration/configuration';
import { allowedFeedPositions, driversBySize, feedAtParam, sameFeedAt } from '../power/feedLoads';
import type { MessageParams } from '../../inputError';

/** One model action of a remedy. */
export interface RemedyStep {
  readonly name: ActionName;
  readonly params: Record<string, unknown>;
}

export type RemedyPartKind = 'useDriver' | 'addFeed' | 'lengthenRail' | 'setDistribution';

/** One part of a remedy: its kind (the planner words it, planner.remedy* messages) and parameters. */
export interface RemedyPart {
  readonly kind: RemedyPartKind;
  /** useDriver: capacity (W); addFeed: capacity, feedAt; lengthenRail: rail (1-based), length (m); setDistribution: distribution. */
  readonly params: MessageParams;
}

/** What makes a refused action enabled: its steps, run in order as one undoable change. */
export interface Remedy {
  readonly steps: readonly RemedyStep[];
  /** What the steps do, in order (kinds worded by the UI, docs/i18n.md), for wording them: "use the 321.6 W driver". */
  readonly parts: readonly RemedyPart[];
  /** English: "use the 321.6 W driver (+28 EUR)". */
  readonly label: string;
  /** What the steps add to the bill of materials' total (may be 0 or negative). */
  readonly priceDelta: number;
  readonly currency: string;
}

/**
 * The actions a remedy is sought for: those that add light (a module, a heavier type or beam, more
 * chain). Others (a smaller driver, removing a feed) are choices to undo, not to enable at a cost.
 */
const REMEDIABLE = new Set<ActionName>(['addModule', 'setModuleType', 'setModuleBeam', 'addRail', 'addBranch']);

/** Codes of refusals that say a module does not fit on its rail (addModule's explain). */
const FIT_REFUSALS = new Set(['noRoomForModule', 'noFreeGap', 'typeDoesNotFit']);

/** The system an action's parameters point at (railId, moduleId, feedId or systemId), if any. */
function systemOf(state: Configuration, params: Record<string, unknown>): LightSystem | undefined {
  const id = (k: string) => (typeof params[k] === 'string' ? (params[k] as string) : undefined);
  const railId = id('railId');
  const moduleId = id('moduleId');
  const feedId = id('feedId');
  const systemId = id('systemId');
  return state.systems.find(
    (s) =>
      s.id === systemId ||
      (railId !== undefined && s.rails.some((r) => r.id === railId)) ||
      (moduleId !== undefined && s.rails.some((r) => r.modules.some((m) => m.id === moduleId))) ||
      (feedId !== undefined && s.feeds.some((f) => f.id === feedId)),
  );
}

interface Candidate {
  steps: RemedyStep[];
  kind: 'driver' | 'feed';
  capacity: number;
  at?: FeedAt;
}

/** Power candidates on one system: each feed on each larger driver (smallest first), then a new feed at each free allowed position, on each driver. */
function powerCandidates(system: LightSystem, catalog: Catalog): Candidate[] {
  const drivers = driversBySize(catalog);
  const out: Candidate[] = [];
  for (const feed of system.feeds) {
    const current = catalog.drivers.find((d) => d.id === feed.driver)?.capacity ?? 0;
    for (const d of drivers) if (d.capacity > current) out.push({ steps: [{ name: 'setFeedDriver', params: { feedId: feed.id, driver: d.id } }], kind: 'driver', capacity: d.capacity });
  }
  for (const at of allowedFeedPositions(system, catalog)) {
    if (system.feeds.some((f) => sameFeedAt(f.at, at))) continue;
    for (const d of drivers) out.push({ steps: [{ name: 'addFeed', params: { systemId: system.id, at, driver: d.id } }], kind: 'feed', capacity: d.capacity, at });
  }
  return out;
}

function run(state: Configuration, steps: readonly RemedyStep[], catalog: Catalog): Configuration | null {
  let s = state;
  for (const step of steps) {
    const o = attemptAction(s, step.name, step.params, catalog);
    if (!o.ok) return null;
    s = o.next;
  }
  return s;
}

/** The cheapest candidate (by the bill of materials) after which `name(params)` is enabled; ties: the first. */
function cheapest(state: Configuration, prefix: RemedyStep[], candidates: Candidate[], name: string, params: unknown, catalog: Catalog, baseTotal: number): { c: Candidate; after: Configuration; delta: number } | null {
  let best: { c: Candidate; after: Configuration; delta: number } | null = null;
  for (const c of candidates) {
    const after = run(state, [...prefix, ...c.steps], catalog);
    if (!after || checkAction(after, name, params, catalog) !== true) continue;
    const delta = billOfMaterials(after, catalog).total - baseTotal;
    if (!best || delta < best.delta - 1e-9) best = { c, after, delta };
  }
  return best;
}

const round2 = (x: number) => Math.round(x * 100) / 100;

/** The English wording of a part (the planner words the kinds in its language, remedyText.ts). */
export function remedyPartText(part: RemedyPart): string {
  const p = part.params;
  switch (part.kind) {
    case 'useDriver':
      return `use the ${p.capacity} W driver`;
    case 'addFeed':
      return `add a feed with the ${p.capacity} W driver`;
    case 'lengthenRail':
      return `lengthen rail ${p.rail} to ${p.length} m`;
    case 'setDistribution':
      return `arrange the rail's modules '${p.distribution}'`;
  }
}

function powerPart(c: Candidate): RemedyPart {
  const capacity = round2(c.capacity);
  return c.kind === 'driver' ? { kind: 'useDriver', params: { capacity } } : { kind: 'addFeed', params: { capacity, feedAt: feedAtParam(c.at!) } };
}

/**
 * The remedy for a refused action: null when the action is enabled, is not one that adds light
 * (REMEDIABLE), concerns no system, or when nothing below makes it enabled. Power refusals: the cheapest (by the bill of materials) of a
 * larger driver on one feed or a new feed at a free allowed position. An addModule or a longer
 * module type (setModuleType) that does not fit: the first rail change after which it fits — another distribution (free), else the shortest
 * longer rail on the catalog's length steps, alone or with another distribution — followed, when
 * the module then overloads a driver, by the cheapest power change.
 */
export function remedyFor(state: Configuration, name: ActionName, params: Record<string, unknown>, catalog: Catalog): Remedy | null {
  if (!REMEDIABLE.has(name)) return null;
  const verdict = checkAction(state, name, params, catalog);
  if (verdict === true) return null;
  const system = systemOf(state, params);
  if (!system) return null;
  const bom = billOfMaterials(state, catalog);
  const base = bom.total;
  const currency = bom.currency;
  const make = (steps: RemedyStep[], parts: RemedyPart[], after: Configuration): Remedy => {
    const priceDelta = round2(billOfMaterials(after, catalog).total - base);
    const sign = priceDelta < 0 ? '−' : '+';
    return { steps, parts, label: `${parts.map(remedyPartText).join(' and ')} (${sign}${Math.abs(priceDelta)} ${currency})`, priceDelta, currency };
  };

  if (!FIT_REFUSALS.has(verdict.code ?? '')) {
    const best = cheapest(state, [], powerCandidates(system, catalog), name, params, catalog, base);
    return best ? make(best.c.steps, [powerPart(best.c)], best.after) : null;
  }

  // A module that does not fit: rail changes in order of preference.
  // addModule names its rail; setModuleType (a longer type) the module, whose rail it is.
  const railIndex = system.rails.findIndex((r) => r.id === params.railId || r.modules.some((m) => m.id === params.moduleId));
  if (railIndex < 0) return null;
  const rail = system.rails[railIndex];
  const { step, maxLength } = catalog.rail;
  const fits: { steps: RemedyStep[]; parts: RemedyPart[] }[] = [];
  const others = DISTRIBUTIONS.filter((d) => d !== rail.distribution || isFreeRail(rail));
  const distribute = (d: string): { step: RemedyStep; part: RemedyPart } => ({ step: { name: 'setDistribution', params: { railId: rail.id, distribution: d } }, part: { kind: 'setDistribution', params: { distribution: d } } });
  for (const d of others) fits.push({ steps: [distribute(d).step], parts: [distribute(d).part] });
  for (let k = 1; round2(rail.length + k * step) <= maxLength + 1e-9; k++) {
    const length = round2(rail.length + k * step);
    const lengthen = { step: { name: 'setRailLength' as const, params: { railId: rail.id, length } }, part: { kind: 'lengthenRail' as const, params: { rail: railIndex + 1, length } } };
    fits.push({ steps: [lengthen.step], parts: [lengthen.part] });
    for (const d of others) fits.push({ steps: [lengthen.step, distribute(d).step], parts: [lengthen.part, distribute(d).part] });
  }
  for (const fit of fits) {
    const after = run(state, fit.steps, catalog);
    if (!after) continue;
    const v = checkAction(after, name, params, catalog);
    if (v === true) return make(fit.steps, fit.parts, after);
    if (FIT_REFUSALS.has(v.code ?? '')) continue;
    const s2 = systemOf(after, params);
    const best = s2 ? cheapest(state, fit.steps, powerCandidates(s2, catalog), name, params, catalog, base) : null;
    if (best) return make([...fit.steps, ...best.c.steps], [...fit.parts, powerPart(best.c)], best.after);
  }
  return null;
}
