/**
 * The plan's tint for a module and its footprint: the colour temperature's tint (cctTint.ts), or,
 * with a colour filter in front, the filtered light's colour normalised for display
 * (src/core/colour/displaySwatch.ts), so a red gel's footprint reads red in the plan.
 */
import { swatchCss } from '../../core/colour/displaySwatch';
import type { ModuleInstance } from '../../core/model/configuration/configuration';
import { moduleLightColour } from '../../core/model/modules/moduleFilter';
import { cctTint } from './cctTint';

export function moduleTint(module: Pick<ModuleInstance, 'cct' | 'filter'>): string {
  if (module.filter === undefined) return cctTint(module.cct);
  try {
    return swatchCss(moduleLightColour(module).linearRgb);
  } catch {
    // A filter the library lacks (validate() reports it), or spectra still loading (PlanSvg
    // re-renders when they arrive), draws as the unfiltered module.
    return cctTint(module.cct);
  }
}
