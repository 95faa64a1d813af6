/** The catalog's presets: ready-made systems the shopper starts from (docs/catalog-format.md). */
import { z } from 'zod/mini';
import { nonEmpty, positive, translations } from './catalogFields';
import { DISTRIBUTIONS } from './railSystemSchema';

const presetModuleSchema = z.strictObject({ type: nonEmpty, beam: z.optional(nonEmpty), cct: z.optional(z.number().check(z.int())) });
export const presetSchema = z.strictObject({
  id: nonEmpty,
  name: nonEmpty,
  names: translations,
  description: z.string(),
  descriptions: translations,
  rails: z.array(z.strictObject({ length: positive, distribution: z.enum(DISTRIBUTIONS), modules: z.array(presetModuleSchema) })).check(z.minLength(1)),
  joints: z.array(z.strictObject({ connector: nonEmpty, turn: z.number(), parent: z.optional(z.number().check(z.int(), z.nonnegative())) })),
  /**
   * The driver the preset ships with (a driver id): its one feed at the chain start gets it instead
   * of the smallest driver that carries the load, so the shopper can add modules before the driver
   * is full (docs/catalog-format.md, "A preset's own driver"). Must carry the preset's own load.
   */
  driver: z.optional(nonEmpty),
});

export type PresetSpec = z.infer<typeof presetSchema>;
