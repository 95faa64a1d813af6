/**
 * Daylight as bases of the relight engine (issue 30; docs/daylight.md, "Daylight in the relight
 * engine"): the sky (with the ground seen below the horizon) and the sun through the windows are
 * two groups of their own, beside the luminaire groups. Each is baked once as a direct basis (the
 * baker's daylight pass, daylightAtlasDirect.ts, restricted to its part) and bounces in the shared
 * indirect solve like any group. Their keys hold everything their direct light depends on (the
 * sky's kind, luminances and sun, the ground's luminance, the sun's beam, each window and its
 * glazing), never a luminaire: a change of the electric light keeps them, a change of the time
 * of day, the date or the sky rebakes them and keeps every luminaire group.
 */
import type { BakeScene } from '../bake/bakeScene';
import type { BakeDaylight } from '../bake/daylight/bakeDaylight';
import { daylightBakeInput, daylightWindowsInput } from '../bake/daylight/daylightBakeInput';
import { daylightFactorDaylight, groundReflectanceOf } from '../bake/daylight/workPlaneDaylightFactor';
import type { DaylightBakeInput } from '../bake/daylight/startDaylightBakeJob';
import type { LuminaireGroup } from './luminaireGroups';

/** The two daylight bases: the sky and the ground ('sky'), the sun's beam ('sun'). */
export type DaylightPartKind = 'sky' | 'sun' | 'overcast';

/** What a daylight group's basis is baked from: the daylight bake's input with only this part's sources. */
export interface DaylightPart {
  kind: DaylightPartKind;
  input: DaylightBakeInput;
}

/**
 * Which light the engine shows (weights): the luminaires, the daylight of the scene's sky, both, or
 * the daylight factor's: the windows under the CIE overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE
 * (a third daylight basis, baked when first shown; its maps' lux / 100 is the DF in %).
 */
export type LightSources = 'electric' | 'daylight' | 'both' | 'daylight-factor';

export const LIGHT_SOURCES: readonly LightSources[] = ['electric', 'daylight', 'both', 'daylight-factor'];

/** Numbers in a key to 6 significant digits: finer than any change a user can make, coarse enough to ignore float noise. */
const num = (v: number): string => v.toPrecision(6);
const vec = (v: readonly number[]): string => v.map(num).join(',');

function windowsKey(input: DaylightBakeInput): string {
  return input.windows.map((w) => `${w.opening}@${vec(w.corner)}/${vec(w.edgeA)}/${vec(w.edgeB)}:${num(w.glazing.normalTransmittance)},${w.glazing.panes},${num(w.glazing.frameFraction)}`).join(';');
}

function skyKey(d: BakeDaylight): string {
  const s = d.sky;
  const sky = s ? `${s.kind}${s.cieType ?? ''}:${num(s.horizontalIlluminance)},${num(s.zenithLuminance)},${s.sunDirection ? vec(s.sunDirection) : '-'}` : 'none';
  return `${sky}|ground ${num(d.groundLuminance)}`;
}

/** The part of `daylight` one basis bakes: the sky and the ground, or the sun's beam alone. */
function partDaylight(daylight: BakeDaylight, kind: 'sky' | 'sun'): BakeDaylight {
  return kind === 'sky' ? { ...daylight, sun: null } : { ...daylight, sky: null, groundLuminance: 0 };
}

/** The daylight factor's group: the same windows under the CIE overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE, no sun, the same ground. */
function overcastGroup(input: DaylightBakeInput, windows: string): LuminaireGroup {
  const rho = groundReflectanceOf(input.daylight);
  const daylight = daylightFactorDaylight(input.daylight);
  return { key: `daylight:overcast|ground ${num(rho)}|${windows}`, members: [], basis: [], daylight: { kind: 'overcast', input: { ...input, daylight } } };
}

/**
 * The daylight groups of a scene (`given` as the caller gave it, `enclosed` as the engine bakes it):
 * none without daylight, a shaped room and a window; 'sky' when there is a sky or a lit ground,
 * 'sun' when the sun shines, and with `withDaylightFactor` the overcast sky's 'overcast'. Their
 * members are empty and their basis luminaires none.
 */
export function daylightGroups(given: BakeScene, enclosed: BakeScene, withDaylightFactor = false): LuminaireGroup[] {
  // The daylight factor's sky needs no sun: after sunset (a scene with windows and no sky) it has the windows alone.
  const input = withDaylightFactor ? daylightWindowsInput(given, enclosed) : daylightBakeInput(given, enclosed);
  if (!input) return [];
  const windows = windowsKey(input);
  const { daylight } = input;
  const groups: LuminaireGroup[] = [];
  if (daylight.sky || daylight.groundLuminance > 0) {
    groups.push({ key: `daylight:sky|${skyKey(daylight)}|${windows}`, members: [], basis: [], daylight: { kind: 'sky', input: { ...input, daylight: partDaylight(daylight, 'sky') } } });
  }
  if (daylight.sun) {
    const sun = `${vec(daylight.sun.direction)}:${num(daylight.sun.normalIlluminance)}`;
    groups.push({ key: `daylight:sun|${sun}|${windows}`, members: [], basis: [], daylight: { kind: 'sun', input: { ...input, daylight: partDaylight(daylight, 'sun') } } });
  }
  if (withDaylightFactor) groups.push(overcastGroup(input, windows));
  return groups;
}
