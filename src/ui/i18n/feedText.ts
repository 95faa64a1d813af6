import type { Translate } from './messageTypes';

/**
 * Where a power feed sits, in words (the UI's counterpart of the core's English describeFeedAt):
 * the chain start or end, a connector, or the free end of a rail.
 */
export function feedAtText(t: Translate, at: unknown): string {
  if (at === 'start') return t('planner.feedAtStart');
  if (at === 'end') return t('planner.feedAtEnd');
  if (typeof at === 'object' && at !== null) {
    if ('joint' in at && typeof at.joint === 'number') return t('planner.feedAtConnector', { n: at.joint + 1 });
    if ('end' in at && typeof at.end === 'number') return t('planner.feedAtRailEnd', { n: at.end + 1 });
  }
  return String(at);
}
