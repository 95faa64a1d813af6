/** The catalog's module types: beams (optics with their photometry), CCTs, filter holder, adjustable heads, dimming curve. */
import { z } from 'zod/mini';
import { nonEmpty, onGrid, positive, price, translations } from './catalogFields';
import { dimmingCurveSchema } from './dimmingCurve';

const beamSchema = z.strictObject({
  id: nonEmpty,
  label: nonEmpty,
  labels: translations,
  /** Full beam angle (degrees) where the optic has one; omitted for diffusers and washers. */
  beamAngle: z.optional(positive),
  article: nonEmpty,
  /** Photometric file, relative to the web root (public/), e.g. 'ies/bega_84693_narrow_spot.ies'. */
  photometry: z.string().check(z.regex(/^[\w./-]+\.(ies|IES|ldt|LDT)$/, 'must be a relative path to an .ies or .ldt file')),
  /** Luminaire lumens and input watts as the photometric file states them. */
  lumens: positive,
  watts: positive,
  /** Roll (degrees) that turns the file's frame so the optic sits as intended on the rail (C0 along the rail when 0). */
  roll: z.number().check(z.gte(-180), z.lte(180)),
  price,
  /** Where lumens and watts come from (free text). */
  source: z.optional(z.string()),
});

/**
 * One axis of an adjustable head: min..max degrees (0 ≤ min ≤ max < `limit`; rotation is relative to the
 * rail, tilt from straight down) and optional detents every `stops` degrees from 0, on which min and
 * max must lie (and which divide 360 for rotation, so the circle closes on a stop).
 */
function aimRangeSchema(limit: number) {
  return z.strictObject({ min: z.number().check(z.gte(0), z.lt(limit)), max: z.number().check(z.gte(0), z.lt(limit)), stops: z.optional(positive.check(z.lte(90))) }).check(
    z.superRefine((r, ctx) => {
      if (r.min > r.max) ctx.addIssue({ code: 'custom', path: ['min'], message: 'must not exceed max' });
      if (r.stops !== undefined) {
        for (const key of ['min', 'max'] as const) if (!onGrid(r[key], r.stops)) ctx.addIssue({ code: 'custom', path: [key], message: `must be a multiple of stops ${r.stops}` });
        if (limit === 360 && !onGrid(360, r.stops)) ctx.addIssue({ code: 'custom', path: ['stops'], message: 'must divide 360' });
      }
    }),
  );
}

export const moduleTypeSchema = z
  .strictObject({
    id: nonEmpty,
    name: nonEmpty,
    names: translations,
    /** Length of rail the module occupies, metres. */
    length: positive,
    ccts: z.array(z.number().check(z.int(), z.gte(1000), z.lte(20000))).check(z.minLength(1)),
    defaultCct: z.number().check(z.int()),
    beams: z.array(beamSchema).check(z.minLength(1)),
    defaultBeam: nonEmpty,
    /** Takes a colour filter (gel) from the catalog's `filters` (docs/colour-filters.md); absent: no holder. */
    filterHolder: z.optional(z.boolean()),
    /** An adjustable head (docs/aiming.md): how far it turns and tilts, degrees; absent: fixed, straight down. */
    adjustable: z.optional(z.strictObject({ tilt: aimRangeSchema(180), rotation: aimRangeSchema(360) })),
    /**
     * The luminaire's L3D geometry (docs/gldf.md "L3D in the 3D view"), relative to the web root like
     * a photometry path, e.g. 'geo/track-spot.l3d': the 3D view draws its body, the plan its outline.
     */
    model: z.optional(z.string().check(z.regex(/^[\w./-]+\.(l3d|L3D)$/, 'must be a relative path to an .l3d file'))),
    /**
     * The light-emitting object of `model` the photometry belongs to (a GLDF emitter's
     * EmitterObjectExternalName, docs/gldf.md); absent: the model's first one facing down.
     */
    modelEmitter: z.optional(z.string().check(z.minLength(1), z.maxLength(200))),
    /** How the CCT follows the level (dimmingCurve.ts, docs/catalog-format.md "Dimming curve"); omitted: constant-cct. */
    dimming: z.optional(dimmingCurveSchema),
  })
  .check(
    z.superRefine((t, ctx) => {
      if (t.dimming?.curve === 'dim-to-warm') {
        const d = t.dimming;
        if (d.cctMin >= d.cctFull) ctx.addIssue({ code: 'custom', path: ['dimming', 'cctMin'], message: `${d.cctMin} K must be below cctFull (${d.cctFull} K)` });
        if (t.ccts.length !== 1 || t.ccts[0] !== d.cctFull) ctx.addIssue({ code: 'custom', path: ['ccts'], message: `a dim-to-warm type offers exactly its cctFull (${d.cctFull} K)` });
      }
      if (t.modelEmitter !== undefined && t.model === undefined) ctx.addIssue({ code: 'custom', path: ['modelEmitter'], message: 'names an object of `model`, which is absent' });
      if (!t.ccts.includes(t.defaultCct)) ctx.addIssue({ code: 'custom', path: ['defaultCct'], message: `${t.defaultCct} K is not one of ccts` });
      if (!t.beams.some((b) => b.id === t.defaultBeam)) ctx.addIssue({ code: 'custom', path: ['defaultBeam'], message: `'${t.defaultBeam}' is not a beam id` });
      if (new Set(t.beams.map((b) => b.id)).size !== t.beams.length) ctx.addIssue({ code: 'custom', path: ['beams'], message: 'beam ids must be unique' });
    }),
  );

export type ModuleTypeSpec = z.infer<typeof moduleTypeSchema>;
export type BeamSpec = ModuleTypeSpec['beams'][number];
