/** A module's own rules: a known type and beam, an offered CCT, dimming in range, its filter, aim and DMX patch. */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Rail } from '../configuration/configuration';
import { aimProblem } from '../modules/aim';
import { patchRangeIssue } from '../modules/dmxPatch';
import { moduleFilterProblem } from '../modules/moduleFilter';
import type { ReportProblem, ReportSubProblem } from './reporting';

/** The problems of rail `r`'s modules (`rp`: the rail's path); false when a module's type is unknown (the rail's fit cannot be judged). */
export function moduleProblems(r: Rail, rp: string, catalog: Catalog, p: ReportProblem, sub: ReportSubProblem): boolean {
  let refsOk = true;
  r.modules.forEach((m, n) => {
    const mp = `${rp}.modules[${n}]`;
    const type = catalog.moduleTypes.find((t) => t.id === m.type);
    if (!type) {
      refsOk = false;
      p('unknown-module-type', `${mp}.type`, `unknown module type '${m.type}'`, { id: m.type }, 'unknownModuleType');
      return;
    }
    const named = { name: type.name, typeId: type.id };
    if (!type.beams.some((b) => b.id === m.beam)) p('unknown-beam', `${mp}.beam`, `${type.name} has no beam '${m.beam}'`, { ...named, beam: m.beam }, 'unknownBeam');
    if (!type.ccts.includes(m.cct)) p('cct', `${mp}.cct`, `${type.name} is not available in ${m.cct} K (offered: ${type.ccts.join(', ')} K)`, { ...named, cct: String(m.cct), ccts: type.ccts.join(', ') }, 'cctNotOffered');
    if (!Number.isFinite(m.dimming) || m.dimming < 0 || m.dimming > 1) p('dimming', `${mp}.dimming`, `dimming must be between 0 and 1 (got ${m.dimming})`, { value: m.dimming }, 'dimmingRange');
    const filter = m.filter !== undefined ? moduleFilterProblem(type, m.filter, catalog) : null;
    if (filter) sub(filter.code, `${mp}.filter`, filter);
    const aim = m.aim !== undefined ? aimProblem(m.aim, type) : null;
    if (aim) sub(aim.field === 'aim' ? 'aim-fixed' : 'aim-range', `${mp}.${aim.field}`, aim);
    const patch = m.dmx ? patchRangeIssue(m.dmx, type) : null;
    if (patch) sub('dmx-range', `${mp}.dmx`, patch);
  });
  return refsOk;
}
