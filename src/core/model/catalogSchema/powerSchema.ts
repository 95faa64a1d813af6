/** The catalog's power: where feeds may sit, the feed kit, the drivers (docs/model.md, "Power feeds"). */
import { z } from 'zod/mini';
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
  positions: z.array(z.enum(FEED_POSITION_KINDS)).check(z.minLength(1)),
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
  source: z.optional(z.string()),
});

export type DriverSpec = z.infer<typeof driverSchema>;
