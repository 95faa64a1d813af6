/**
 * What the installer must know before the cart hand-off (docs/model.md, "Installation
 * needs"): per system its feeds with their drivers, loads and capacities, and how many
 * ceiling fixings its mounting needs; in total the feeds, the fixings and the load.
 * Derived from the same functions as validate() and the bill of materials (feedLoads,
 * suspensionCoordinates), so the three never disagree.
 */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration, FeedAt, Mounting } from '../configuration/configuration';
import { feedLabel, feedLoads } from './feedLoads';
import { suspensionCoordinates } from '../rails/suspensionPoints';

export interface FeedNeed {
  readonly feedId: string;
  /** "Feed 1". */
  readonly label: string;
  readonly at: FeedAt;
  readonly driver: { readonly id: string; readonly name: string; readonly article: string; readonly output: string };
  /** Watts of the modules it carries (at full output). */
  readonly load: number;
  /** The driver's rated output power, watts. */
  readonly capacity: number;
}

export interface SystemNeeds {
  readonly systemId: string;
  readonly mounting: Mounting;
  readonly feeds: readonly FeedNeed[];
  /** Suspension kits or surface clips: one ceiling fixing each. */
  readonly ceilingFixings: number;
  readonly load: number;
}

export interface InstallationNeeds {
  readonly systems: readonly SystemNeeds[];
  readonly feeds: number;
  readonly ceilingFixings: number;
  /** Sum of every module's watts. */
  readonly totalLoad: number;
}

const round = (w: number) => Math.round(w * 1e6) / 1e6;

/** The summary for a valid configuration (validate() empty). */
export function installationNeeds(config: Configuration, catalog: Catalog): InstallationNeeds {
  const systems = config.systems.map((s): SystemNeeds => {
    const feeds = feedLoads(s, catalog).map((l) => ({
      feedId: l.feed.id,
      label: feedLabel(l.index),
      at: l.feed.at,
      driver: { id: l.driver.id, name: l.driver.name, article: l.driver.article, output: l.driver.output },
      load: l.load,
      capacity: l.capacity,
    }));
    return { systemId: s.id, mounting: s.mounting, feeds, ceilingFixings: suspensionCoordinates(s, catalog).length, load: round(feeds.reduce((a, f) => a + f.load, 0)) };
  });
  return {
    systems,
    feeds: systems.reduce((a, s) => a + s.feeds.length, 0),
    ceilingFixings: systems.reduce((a, s) => a + s.ceilingFixings, 0),
    totalLoad: round(systems.reduce((a, s) => a + s.load, 0)),
  };
}
