/**
 * Named room finishes ("white paint", "oak floor"): data the user picks from
 * instead of typing reflectances. Each has a linear-RGB reflectance (what the
 * baker uses) and an sRGB display colour (swatches, the plan's floor tint).
 * Format: docs/catalog-format.md, "Surface finishes".
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import { versionedDataProblem } from './catalogSchema';
import type { Reflectance, SurfaceName } from '../lightingScene/lightingScene';
import { reflectanceProblem, sameReflectance } from '../lightingScene/reflectance';
import { oneLine } from '../../untrustedJson';
import { describeIssues, schemaFieldNames } from '../../zodIssues';
import { safeParseInEnglish } from '../../zodEnglish';

/** Which picker a finish is offered in: floor, ceiling, or the walls. */
export const FINISH_USES = ['floor', 'ceiling', 'walls'] as const;
export type FinishUse = (typeof FINISH_USES)[number];

const reflectanceValue = z.union([z.number(), z.tuple([z.number(), z.number(), z.number()])]).check(
  z.superRefine((v, ctx) => {
    const problem = reflectanceProblem(v);
    if (problem) ctx.addIssue({ code: 'custom', message: problem });
  }),
);

const finishSchema = z.strictObject({
  id: z.string().check(z.regex(/^[a-z0-9-]{1,40}$/, 'must be 1-40 lower-case letters, digits or -')),
  name: z.string().check(z.minLength(1)),
  uses: z.array(z.enum(FINISH_USES)).check(z.minLength(1)),
  /** Linear RGB (or grey) reflectance, per channel in [0, MAX_REFLECTANCE]. */
  reflectance: reflectanceValue,
  /** sRGB display colour, '#rrggbb'. */
  display: z.string().check(z.regex(/^#[0-9a-f]{6}$/i, "must be an sRGB colour '#rrggbb'")),
  /** Where the reflectance comes from (free text). */
  source: z.string().check(z.minLength(1)),
});

const finishListSchema = z.strictObject({ formatVersion: z.literal(1), finishes: z.array(finishSchema).check(z.minLength(1)) }).check(
  z.superRefine((list, ctx) => {
    const seen = new Set<string>();
    list.finishes.forEach((f, i) => {
      if (seen.has(f.id)) ctx.addIssue({ code: 'custom', path: ['finishes', i, 'id'], message: `duplicate finish id '${f.id}'` });
      seen.add(f.id);
    });
    for (const use of FINISH_USES) {
      if (!list.finishes.some((f) => f.uses.includes(use))) ctx.addIssue({ code: 'custom', path: ['finishes'], message: `no finish is offered for the ${use}` });
    }
  }),
);

export type SurfaceFinish = z.infer<typeof finishSchema>;

export class SurfaceFinishError extends InputError {
  override name = 'SurfaceFinishError';
  constructor(message: string) {
    super(oneLine(message));
  }
}

const FINISH_FIELDS = schemaFieldNames(finishListSchema);

/** Validates a finish list (JSON data); throws SurfaceFinishError naming the field. */
export function parseSurfaceFinishes(data: unknown, source = 'surface finishes'): SurfaceFinish[] {
  const problem = versionedDataProblem(data, 'formatVersion', 1);
  if (problem) throw new SurfaceFinishError(`${source}: ${problem}`);
  const r = safeParseInEnglish(finishListSchema, data);
  if (!r.success) throw new SurfaceFinishError(`${source}: ${describeIssues(r.error.issues, FINISH_FIELDS)}`);
  return r.data.finishes;
}

/** The picker a surface belongs to. */
export function finishUse(surface: SurfaceName): FinishUse {
  return surface === 'floor' || surface === 'ceiling' ? surface : 'walls';
}

/** Finishes offered for a use, in list order. */
export function finishesFor(finishes: readonly SurfaceFinish[], use: FinishUse): SurfaceFinish[] {
  return finishes.filter((f) => f.uses.includes(use));
}

/** The finish whose reflectance a surface holds (any finish of the list), or null for a custom value. */
export function matchFinish(finishes: readonly SurfaceFinish[], value: Reflectance): SurfaceFinish | null {
  return finishes.find((f) => sameReflectance(f.reflectance, value)) ?? null;
}
