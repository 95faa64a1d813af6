/** The catalog's rail system: the rail, its connectors, how it hangs (suspensions) or sits on the ceiling (clips). */
import { z } from 'zod/mini';
import { nonEmpty, positive, price, translations } from './catalogFields';

/** Module distributions along a rail; defined precisely in docs/model.md and src/core/model/rails/distribution.ts. */
export const DISTRIBUTIONS = ['start', 'end', 'inside-centred', 'outside-centred'] as const;
export type Distribution = (typeof DISTRIBUTIONS)[number];

export const railSchema = z.strictObject({
  article: nonEmpty,
  name: nonEmpty,
  names: translations,
  minLength: positive,
  maxLength: positive,
  step: positive,
  defaultLength: positive,
  /** Profile width in plan, metres (for footprints and clash tests). */
  width: positive,
  /** Grid a freely placed module's start snaps to, metres from the rail start (docs/model.md, "Free positions"); default: step. */
  placementStep: z.optional(positive),
  /** Unit price of a rail of length L: base + perMetre·L, rounded to cents. */
  price: z.strictObject({ base: price, perMetre: price }),
});

export const connectorSchema = z.strictObject({
  id: nonEmpty,
  article: nonEmpty,
  name: nonEmpty,
  names: translations,
  /** 0 for a straight connector, otherwise the corner angle in degrees (used turning left or right); a flexible connector: the turn a new joint gets. */
  angle: z.number().check(z.gte(0), z.lt(180)),
  /** Straight: gap between the joined rail ends. Corner or flexible: distance from each rail end to the hinge (corner) point. Metres. */
  arm: z.number().check(z.nonnegative()),
  price,
  /**
   * A flexible-angle (hinge) connector (docs/catalog-format.md): it turns by any multiple of
   * `step` degrees from −maxAngle to +maxAngle, 0 included; setJointTurn adjusts a joint's turn.
   */
  flex: z.optional(z.strictObject({ maxAngle: z.number().check(z.positive(), z.lt(180)), step: z.number().check(z.positive()) })),
  /**
   * Rail ends it joins (docs/catalog-format.md, "Connectors"): 2 (default) for straight, corner and
   * flexible; 3 for a T, 4 for an X. A node of more than two ports takes branches at −angle, 0 and +angle.
   */
  ports: z.optional(z.number().check(z.int(), z.gte(2), z.lte(4))),
  source: z.optional(z.string()),
});

export const suspensionSchema = z.strictObject({
  article: nonEmpty,
  name: nonEmpty,
  names: translations,
  /** Ceiling to photometric centre, metres. */
  min: positive,
  max: positive,
  default: positive,
  /** The photometric centre must stay at least this high above the floor (head room), metres. */
  minHeightAboveFloor: positive,
  price,
  /** Largest distance between two suspension points along the chain, metres (docs/model.md, "Suspension points"). */
  maxSpacing: positive,
  /** Largest overhang of a free chain end past its last suspension point, metres. */
  maxOverhang: positive,
  /** Where the mounting rules come from (free text). */
  source: z.optional(z.string()),
});

/** Mounting the rail directly on the ceiling (setMounting 'surface'): clips instead of suspensions. */
export const surfaceMountSchema = z.strictObject({
  article: nonEmpty,
  name: nonEmpty,
  names: translations,
  price,
  /** Largest distance between two clips along the chain, metres. */
  spacing: positive,
  /** Largest overhang of a free chain end past its last clip, metres. */
  maxOverhang: positive,
  /** Ceiling to photometric centre of a surface-mounted system, metres. */
  drop: positive,
  source: z.optional(z.string()),
});

export type RailSpec = z.infer<typeof railSchema>;
export type ConnectorSpec = z.infer<typeof connectorSchema>;
