/** The catalog's power: where feeds may sit, the feed kit, the drivers (docs/model.md, "Power feeds"). */
import { z } from 'zod';
import { nonEmpty, positive, price, translations } from './catalogFields';

/** Where the catalog lets power feeds sit: the chain's two ends, its connectors. */
export const FEED_POSITION_KINDS = ['ends', 'joints'] as const;

/** Where power feeds may sit and the feed kit each one needs (docs/model.md, "Power feeds"). */
export const feedSchema = z.strictObject({
  article: nonEmpty,
  name: nonEmpty,
  names: translations,
  price,
  /** 'ends': the chain's start and end; 'joints': any connector. A one-rail system has no joints, so 'ends' is required. */
  positions: z.array(z.enum(FEED_POSITION_KINDS)).min(1),
  /** What the rail takes, e.g. '48 V DC'; every driver must supply it. */
  output: nonEmpty,
  /** Driver id a new system's feed gets. */
  defaultDriver: nonEmpty,
});

export const driverSchema = z.strictObject({
  id: nonEmpty,
  name: nonEmpty,
  article: nonEmpty,
  /** Rated output power, watts: the most module input power one feed may carry. */
  capacity: positive,
  /** Output, e.g. '48 V DC'; must equal feed.output. */
  output: nonEmpty,
  price,
  source: z.string().optional(),
});

export type DriverSpec = z.infer<typeof driverSchema>;

/** Feeds at the ends at least, no position twice, a known default driver, every driver's output what the rail takes. */
export function powerIssues(c: { feed: z.infer<typeof feedSchema>; drivers: readonly DriverSpec[] }, ctx: z.RefinementCtx): void {
  if (!c.feed.positions.includes('ends')) ctx.addIssue({ code: 'custom', path: ['feed', 'positions'], message: "must include 'ends' (a one-rail system has no joints)" });
  if (new Set(c.feed.positions).size !== c.feed.positions.length) ctx.addIssue({ code: 'custom', path: ['feed', 'positions'], message: 'must not repeat a position' });
  if (!c.drivers.some((d) => d.id === c.feed.defaultDriver)) ctx.addIssue({ code: 'custom', path: ['feed', 'defaultDriver'], message: `'${c.feed.defaultDriver}' is not a driver id` });
  c.drivers.forEach((d, i) => {
    if (d.output !== c.feed.output) ctx.addIssue({ code: 'custom', path: ['drivers', i, 'output'], message: `'${d.output}' does not match feed.output '${c.feed.output}'` });
  });
}
