/** The catalog's presets: ready-made systems the shopper starts from (docs/catalog-format.md). */
import { z } from 'zod';
import { nonEmpty, positive, translations } from './catalogFields';
import { allowedTurn, turnRange } from './connectorTurns';
import type { ModuleTypeSpec } from './moduleTypeSchema';
import type { DriverSpec } from './powerSchema';
import { DISTRIBUTIONS, type ConnectorSpec } from './railSystemSchema';

const presetModuleSchema = z.strictObject({ type: nonEmpty, beam: nonEmpty.optional(), cct: z.number().int().optional() });
export const presetSchema = z.strictObject({
  id: nonEmpty,
  name: nonEmpty,
  names: translations,
  description: z.string(),
  descriptions: translations,
  rails: z
    .array(z.strictObject({ length: positive, distribution: z.enum(DISTRIBUTIONS), modules: z.array(presetModuleSchema) }))
    .min(1),
  joints: z.array(z.strictObject({ connector: nonEmpty, turn: z.number().finite(), parent: z.number().int().nonnegative().optional() })),
  /**
   * The driver the preset ships with (a driver id): its one feed at the chain start gets it instead
   * of the smallest driver that carries the load, so the shopper can add modules before the driver
   * is full (docs/catalog-format.md, "A preset's own driver"). Must carry the preset's own load.
   */
  driver: nonEmpty.optional(),
});

export type PresetSpec = z.infer<typeof presetSchema>;

/** Each preset: joints for its rails (known connectors, allowed turns, parents before), its own driver carrying its load, known module types, beams and CCTs. */
export function presetIssues(c: { presets: readonly PresetSpec[]; connectors: readonly ConnectorSpec[]; drivers: readonly DriverSpec[]; moduleTypes: readonly ModuleTypeSpec[] }, ctx: z.RefinementCtx): void {
  c.presets.forEach((p, i) => {
    if (p.joints.length !== p.rails.length - 1) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints'], message: `needs ${p.rails.length - 1} joints for ${p.rails.length} rails` });
    p.joints.forEach((j, k) => {
      const con = c.connectors.find((x) => x.id === j.connector);
      if (!con) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints', k, 'connector'], message: `unknown connector '${j.connector}'` });
      else if (!allowedTurn(con, j.turn)) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints', k, 'turn'], message: `${turnRange(con)} for connector '${con.id}'` });
      if (j.parent !== undefined && j.parent > k) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints', k, 'parent'], message: `must be a rail before rail ${k + 2} (at most ${k})` });
    });
    if (p.driver !== undefined) {
      const d = c.drivers.find((x) => x.id === p.driver);
      // The preset's load: its modules' beams (the type's default beam where none is named), as the feeds count it.
      let load = 0;
      for (const m of p.rails.flatMap((r) => r.modules)) {
        const t = c.moduleTypes.find((x) => x.id === m.type);
        load += t?.beams.find((b) => b.id === (m.beam ?? t.defaultBeam))?.watts ?? 0;
      }
      if (!d) ctx.addIssue({ code: 'custom', path: ['presets', i, 'driver'], message: `'${p.driver}' is not a driver id` });
      else if (load > d.capacity + 1e-6) ctx.addIssue({ code: 'custom', path: ['presets', i, 'driver'], message: `the ${d.capacity} W '${d.id}' cannot carry the preset's ${Math.round(load * 100) / 100} W` });
    }
    p.rails.forEach((rail, k) =>
      rail.modules.forEach((m, n) => {
        const t = c.moduleTypes.find((x) => x.id === m.type);
        const at = ['presets', i, 'rails', k, 'modules', n];
        if (!t) ctx.addIssue({ code: 'custom', path: [...at, 'type'], message: `unknown module type '${m.type}'` });
        else {
          if (m.beam !== undefined && !t.beams.some((b) => b.id === m.beam)) ctx.addIssue({ code: 'custom', path: [...at, 'beam'], message: `unknown beam '${m.beam}'` });
          if (m.cct !== undefined && !t.ccts.includes(m.cct)) ctx.addIssue({ code: 'custom', path: [...at, 'cct'], message: `${m.cct} K not offered` });
        }
      }),
    );
  });
}
