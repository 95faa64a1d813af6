/** A system's power feeds: where they sit and their drivers (the loads they carry: systemOwnProblems.ts). */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { LightSystem } from '../configuration/configuration';
import { describeFeedAt, feedAtParam, feedLabel } from '../power/feedLoads';
import { firstNodeJoints, jointParent } from '../rails/railTree';
import type { ReportProblem } from './reporting';

/** A system's feeds: at least one, known drivers, positions the catalog allows on this chain, no two at one spot. */
export function feedProblems(s: LightSystem, catalog: Catalog, p: ReportProblem): void {
  if (s.feeds.length === 0) p('no-feed', '.feeds', `system ${s.id} has no power feed`, { id: s.id }, 'noFeed');
  // First feed at each position, keyed 'start' / 'end' / 'joint:k': one pass, even for a hostile file's thousands of feeds.
  const firstJoint = firstNodeJoints(s);
  const first = new Map<string, number>();
  s.feeds.forEach((f, k) => {
    const fp = `.feeds[${k}]`;
    if (!catalog.drivers.some((d) => d.id === f.driver)) p('unknown-driver', `${fp}.driver`, `unknown driver '${f.driver}'`, { id: f.driver }, 'unknownDriver');
    const at = f.at;
    if (typeof at === 'object' && 'joint' in at) {
      if (!catalog.feed.positions.includes('joints')) p('feed-position', `${fp}.at`, `${catalog.name} feeds only at the chain ends, not at connectors`, { catalog: catalog.name }, 'feedOnlyAtEnds');
      else if (!Number.isInteger(at.joint) || at.joint < 0 || at.joint >= s.joints.length)
        p(
          'feed-position',
          `${fp}.at`,
          `${feedLabel(k)} is at connector ${at.joint + 1}, but the chain has ${s.joints.length} connector${s.joints.length === 1 ? '' : 's'}`,
          { n: k + 1, joint: at.joint + 1, count: s.joints.length },
          'feedAtMissingConnector',
        );
    } else if (typeof at === 'object' && 'end' in at) {
      if (!Number.isInteger(at.end) || at.end < 0 || at.end >= s.rails.length)
        p(
          'feed-position',
          `${fp}.at`,
          `${feedLabel(k)} is at the end of rail ${at.end + 1}, but the system has ${s.rails.length} rail${s.rails.length === 1 ? '' : 's'}`,
          { n: k + 1, rail: at.end + 1, count: s.rails.length },
          'feedAtMissingRail',
        );
      else if (firstJoint[at.end] !== undefined)
        p('feed-position', `${fp}.at`, `${feedLabel(k)} is at the end of rail ${at.end + 1}, but a connector sits there (feed at the connector instead)`, { n: k + 1, rail: at.end + 1 }, 'feedAtRailEndConnector');
    } else if (at !== 'start' && at !== 'end') p('feed-position', `${fp}.at`, `a feed sits at 'start', 'end', { joint: k } or { end: i } (got ${String(at)})`, { value: String(at) }, 'feedPositionUnknown');
    // One key per physical position: the joints of one node share it, and 'end' is the last rail's end.
    const key = typeof at !== 'object' ? (at === 'end' ? `end:${s.rails.length - 1}` : String(at)) : 'joint' in at ? `node:${s.joints[at.joint] ? jointParent(s.joints[at.joint], at.joint) : `?${at.joint}`}` : `end:${at.end}`;
    const twin = first.get(key);
    if (twin === undefined) first.set(key, k);
    else p('feed-duplicate', `${fp}.at`, `${feedLabel(twin)} and ${feedLabel(k)} both sit at ${describeFeedAt(f.at)}`, { n: twin + 1, other: k + 1, feedAt: feedAtParam(f.at) }, 'feedsBothAt');
  });
}
