import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { defaultSurfaceFinishes } from '../../../src/core/catalog/surfaceFinishes';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { finishColour, floorTint } from '../../../src/ui/planner/finishColour';
import { SurfacesPanel } from '../../../src/ui/planner/SurfacesPanel';

const finishes = defaultSurfaceFinishes;
const slate = finishes.find((f) => f.id === 'dark-slate')!;

function panel(config: Configuration, runs: [string, unknown][] = []) {
  const gate = createActionGate(
    config,
    defaultCatalog,
    (name, params) => runs.push([name, params]),
    () => {},
  );
  return renderToStaticMarkup(<SurfacesPanel room={config.room} finishes={finishes} gate={gate} />);
}

/** The option a select shows as chosen, from the static markup (React marks it `selected`). */
function chosen(html: string, testId: string): string {
  const select = new RegExp(`<select[^>]*data-testid="${testId}"[^>]*>(.*?)</select>`).exec(html);
  if (!select) throw new Error(`no select ${testId}`);
  const opt = /<option[^>]*selected=""[^>]*>([^<]*)<\/option>/.exec(select[1]);
  return opt ? opt[1] : '';
}

describe('finish colours', () => {
  it('listed finishes show their swatch; custom values their sRGB encoding (IEC 61966-2-1)', () => {
    expect(finishColour(slate.reflectance, finishes)).toBe('#545961');
    expect(finishColour(0.8, finishes)).toBe('#e7e7e7'); // white paint
    // 0.18 (not listed): 1.055·0.18^(1/2.4) − 0.055 = 0.4614 → 118 = 0x76
    expect(finishColour(0.18, finishes)).toBe('#767676');
    // the linear toe ends at 0.0031308: 12.92·0.0031308 = 0.04045 → 10 = 0x0a
    expect(finishColour([0, 0.0031308, 1], finishes)).toBe('#000aff');
  });
  it('the plan tint mixes 15 % of the floor colour into white', () => {
    // slate #545961: 255 + (84 − 255)·0.15 = 229.35 → e5; 89 → 230.1 → e6; 97 → 231.3 → e7
    expect(floorTint(slate.reflectance, finishes)).toBe('#e5e6e7');
    expect(floorTint(0.8, finishes, 1)).toBe('#e7e7e7');
    expect(floorTint(0.8, finishes, 0)).toBe('#ffffff');
  });
});

describe('Surfaces panel', () => {
  it('shows the default room as its listed finishes', () => {
    const html = panel(createConfiguration());
    expect(chosen(html, 'finish-floor')).toBe('Grey carpet — reflects 20%');
    expect(chosen(html, 'finish-walls')).toBe('Mid grey — reflects 50%');
    expect(chosen(html, 'finish-ceiling')).toBe('White paint — reflects 80%');
    expect(chosen(html, 'finish-east')).toBe('Mid grey — reflects 50%');
    // floor picker offers floor finishes only
    const floor = /data-testid="finish-floor"[^>]*>(.*?)<\/select>/.exec(html)![1];
    expect(floor).toContain('Dark slate');
    expect(floor).not.toContain('Sage green');
  });
  it('walls set one by one show as mixed; values not in the list as custom', () => {
    let c = createConfiguration();
    c = bindAction('setReflectance', { surface: 'east', value: slate.reflectance }, defaultCatalog).perform(c);
    c = bindAction('setReflectance', { surface: 'floor', value: 0.42 }, defaultCatalog).perform(c);
    const html = panel(c);
    expect(chosen(html, 'finish-walls')).toBe('Mixed (per wall)');
    expect(chosen(html, 'finish-east')).toBe('Dark slate — reflects 10%');
    expect(chosen(html, 'finish-north')).toBe('Mid grey — reflects 50%');
    expect(chosen(html, 'finish-floor')).toBe('Custom — reflects 42%');
  });
});
