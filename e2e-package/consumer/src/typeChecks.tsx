// Compiled (not run) against the tarball's declarations by scripts/checkPackage.mjs: what a shop
// writes type-checks, and each @ts-expect-error marks a mistake the types must catch (tsc fails
// on an unused @ts-expect-error, so a type that got looser fails the check).
import { Luxbox } from 'luxbox/react';
import { mountLuxbox, type LuxboxInstance, type LuxboxOptions } from 'luxbox';
import { LuxboxConfiguratorElement } from 'luxbox/element';
import { integrateFlux, parsePhotometry, type LightingScene } from 'luxbox/engine';

export const good = <Luxbox catalog="/catalog.json" locale="de-CH" quality="best" exposure={5.5} onChange={(json: string) => json.length} />;
// @ts-expect-error: no such quality level
export const badQuality = <Luxbox quality="ultra" />;
// @ts-expect-error: onChange receives the scene-file JSON as a string
export const badOnChange = <Luxbox onChange={(json: number) => json} />;

export function useInstance(lx: LuxboxInstance): number {
  const bom = lx.getBillOfMaterials();
  return bom.total + bom.lines.length;
}

// Actions are typed by name and parameters (ActionName, ActionParams from the model's schemas).
export function actions(lx: LuxboxInstance): number {
  lx.runAction('placePreset', { presetId: 'single' });
  lx.runAction('setModuleDimming', { moduleId: 'm1', dimming: 0.5 });
  // @ts-expect-error: no action of that name
  lx.runAction('placePresett', { presetId: 'single' });
  // @ts-expect-error: placePreset's parameter is presetId
  lx.runAction('placePreset', { preset: 'single' });
  // @ts-expect-error: dimming is a number
  lx.runAction('setModuleDimming', { moduleId: 'm1', dimming: 'half' });
  const listed = lx.listActions({ deleteSystem: { systemId: 's1' } });
  return listed.length + lx.getLightingScene().luminaires.length;
}

export const options: LuxboxOptions = { room: { width: 6, depth: 4.5, height: 3 }, exposure: 'auto' };
// @ts-expect-error: the room needs a height
export const badOptions: LuxboxOptions = { room: { width: 6, depth: 4.5 } };

export const mount: (element: HTMLElement, options?: LuxboxOptions) => LuxboxInstance = mountLuxbox;

export function element(): LuxboxConfiguratorElement {
  const el = document.createElement('luxbox-configurator');
  el.quality = 'fast';
  el.addEventListener('luxbox-bom', (event) => console.log(event));
  return el;
}

export function flux(text: string): number {
  return integrateFlux(parsePhotometry(text, 'lamp.ies'));
}

export const sceneVersion = (scene: LightingScene): number => scene.version;
