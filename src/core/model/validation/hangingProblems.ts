/** How a system hangs: a finite position, its rotation, the suspension range, the mounting and the head room below it. */
import type { Catalog } from '../catalogSchema/catalogSchema';
import { MOUNTINGS, type LightSystem } from '../configuration/configuration';
import { photometricDrop } from '../rails/suspensionPoints';
import { EPS, fmt, type ReportProblem } from './reporting';

export function hangingProblems(s: LightSystem, roomHeight: number, catalog: Catalog, p: ReportProblem): void {
  if (![s.x, s.z, s.rotation].every(Number.isFinite)) p('position', '', `system ${s.id} has a non-finite position or rotation`, { id: s.id }, 'systemPosition');
  else if (s.rotation < 0 || s.rotation >= 360) p('rotation', '.rotation', `rotation must be in [0, 360) degrees (got ${s.rotation})`, { value: s.rotation }, 'rotationRange');
  const susp = catalog.suspension;
  const inRange = Number.isFinite(s.suspension) && s.suspension >= susp.min - EPS && s.suspension <= susp.max + EPS;
  if (!inRange) p('suspension-range', '.suspension', `suspension must be between ${susp.min} and ${susp.max} m (got ${s.suspension})`, { min: susp.min, max: susp.max, value: s.suspension });
  if (!(MOUNTINGS as readonly string[]).includes(s.mounting)) p('mounting', '.mounting', `mounting must be ${MOUNTINGS.join(' or ')} (got ${String(s.mounting)})`, { value: String(s.mounting) }, 'mountingUnknown');
  else if ((inRange || s.mounting === 'surface') && roomHeight - photometricDrop(s, catalog) < susp.minHeightAboveFloor - EPS) {
    // Head room from where the modules really are: the suspension, or the surface mount's drop below the ceiling.
    const hang = fmt(roomHeight - photometricDrop(s, catalog));
    const surface = s.mounting === 'surface';
    const message = `modules would hang at ${hang} m${surface ? ' on the ceiling' : ''}, below the minimum ${susp.minHeightAboveFloor} m above the floor`;
    // The pendant wording keeps the rule's code as its key (coded before the surface mount's own).
    if (surface) p('suspension-floor', '.mounting', message, { hang: Number(hang), min: susp.minHeightAboveFloor }, 'suspensionFloorSurface');
    else p('suspension-floor', '.suspension', message, { hang: Number(hang), min: susp.minHeightAboveFloor });
  }
}
