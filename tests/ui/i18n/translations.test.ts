import { describe, expect, it } from 'vitest';
import { LANGUAGES } from '../../../src/ui/i18n/languages';
import { loadCoreEnglish, loadMessages, registerEnglishAreas } from '../../../src/ui/i18n/loadMessages';
import lazyEnglish from '../../../src/ui/i18n/messages/en/lazy';
import optionsPanelEnglish from '../../../src/ui/i18n/messages/en/optionsPanel';
import panelExtrasEnglish from '../../../src/ui/i18n/messages/en/panelExtras';
import guidanceEnglish from '../../../src/ui/i18n/messages/en/guidance';
import scenesEnglish from '../../../src/ui/i18n/messages/en/scenes';
import a11yEnglish from '../../../src/ui/i18n/messages/en/a11y';
import roomShapeEnglish from '../../../src/ui/i18n/messages/en/roomShape';
import daylightEnglish from '../../../src/ui/i18n/messages/en/daylight';
import daylightPlanEnglish from '../../../src/ui/i18n/messages/en/daylightPlan';
import type { MessageTree, PluralMessage } from '../../../src/ui/i18n/messageTypes';
import { hasWord } from './findHardCodedText';
import defaultCatalog from '../../../src/core/catalog/default-catalog.json';

type Flat = Map<string, string | PluralMessage>;

function flatten(tree: MessageTree): Flat {
  const out: Flat = new Map();
  for (const [area, messages] of Object.entries(tree)) for (const [key, value] of Object.entries(messages as Record<string, string | PluralMessage>)) out.set(`${area}.${key}`, value);
  return out;
}

const forms = (v: string | PluralMessage): string[] => (typeof v === 'string' ? [v] : Object.values(v).filter((x): x is string => typeof x === 'string'));
const placeholders = (v: string | PluralMessage) => [...new Set(forms(v).flatMap((s) => [...s.matchAll(/\{(\w+)\}/g)].map((m) => m[1])))].sort();

/**
 * Values a translation may share with English: words every one of these languages writes the
 * same way (checked by hand). Anything else equal to English is an untranslated string.
 */
const SAME_AS_ENGLISH: Record<string, readonly string[]> = {
  de: [
    'common.ok',
    'view3d.compareToggle',
    'view3d.compareA',
    'view3d.compareB',
    'common.labelWithReason',
    'app.fieldInMetres',
    'options.kelvin',
    'planner.finishOption',
    'options.driverChoice',
    'live.cct',
    'live.universeShort',
    'view3d.modeLux',
    'planner.bomModule',
    'options.clipN',
    'a11y.system',
    'filters.chromaticity',
    'filters.transmission',
    'furniture.sideboard',
    'scenes.go',
    'scenes.goTo',
    'scenes.seconds',
  ],
  fr: [
    'common.ok',
    'roomShape.rectangle',
    'view3d.compareToggle',
    'view3d.compareA',
    'view3d.compareB',
    'app.fieldInMetres',
    'options.kelvin',
    'planner.finishOption',
    'options.driverChoice',
    'live.cct',
    'live.universeShort',
    'view3d.modeLux',
    'planner.bomModule',
    'planner.bomLineTotal',
    'planner.bomArticle',
    'options.panel',
    'commands.options',
    'app.surfaces',
    'options.rotation',
    'options.railTitle',
    'options.suspensionField',
    'options.mounting',
    'files.triangles',
    'live.sources',
    'live.connectedStatus',
    'view3d.selectedModule',
    'furniture.sofa',
    'planner.bomTotal',
    'planner.toolOptions',
    'a11y.railCount',
    'a11y.moduleCount',
    'aim.rotation',
    'filters.chromaticity',
    'filters.transmission',
    'scenes.go',
    'scenes.seconds',
  ],
  it: [
    'common.ok',
    'view3d.compareToggle',
    'view3d.compareA',
    'view3d.compareB',
    'common.labelWithReason',
    'app.fieldInMetres',
    'options.kelvin',
    'planner.finishOption',
    'options.driverChoice',
    'live.cct',
    'live.universeShort',
    'view3d.modeLux',
    'planner.bomModule',
    'finishes.terracotta',
    'options.clipN',
    'exposure.ev100',
    'filters.chromaticity',
    'scenes.go',
    'scenes.goTo',
    'scenes.seconds',
  ],
};

describe('translations', async () => {
  // The 3D chunk's English areas, as that chunk registers them.
  registerEnglishAreas(lazyEnglish);
  registerEnglishAreas(optionsPanelEnglish);
  registerEnglishAreas(panelExtrasEnglish);
  registerEnglishAreas({ guidance: guidanceEnglish });
  registerEnglishAreas({ scenes: scenesEnglish, a11y: a11yEnglish, roomShape: roomShapeEnglish, daylight: daylightEnglish, daylightPlan: daylightPlanEnglish });
  // And the English of the core's codes, which comes with the other languages (docs/i18n.md, "Bundles").
  await loadCoreEnglish();
  const en = flatten(await loadMessages('en'));

  for (const language of LANGUAGES.filter((l) => l !== 'en')) {
    it(`${language} has every English key, the same placeholders and plural forms, and no empty or untranslated value`, async () => {
      const tree = flatten(await loadMessages(language));
      expect([...tree.keys()].sort()).toEqual([...en.keys()].sort());
      const problems: string[] = [];
      for (const [key, source] of en) {
        const value = tree.get(key)!;
        if (typeof source !== typeof value) problems.push(`${key}: ${typeof source === 'string' ? 'a string' : 'a plural'} in English`);
        if (forms(value).some((s) => s.trim() === '')) problems.push(`${key}: empty`);
        if (JSON.stringify(placeholders(value)) !== JSON.stringify(placeholders(source))) problems.push(`${key}: placeholders ${placeholders(value)} ≠ ${placeholders(source)}`);
        const same = JSON.stringify(value) === JSON.stringify(source);
        // Areas other helpers own are checked for keys, emptiness and placeholders; identical wording only where it has words.
        if (same && forms(source).some((s) => hasWord(s.replace(/\{\w+\}/g, ''))) && !SAME_AS_ENGLISH[language].includes(key)) problems.push(`${key}: same as English`);
      }
      expect(problems).toEqual([]);
    });
  }

  it('the demo catalog names every module type, beam, preset, connector, fixing and feed kit in de, fr and it', () => {
    const c = defaultCatalog as unknown as Record<string, unknown> & {
      rail: { names?: object };
      suspension: { names?: object };
      surfaceMount: { names?: object };
      feed: { names?: object };
      connectors: { id: string; names?: object }[];
      moduleTypes: { id: string; names?: object; beams: { id: string; labels?: object }[] }[];
      presets: { id: string; names?: object; descriptions?: object }[];
    };
    const entries: [string, object | undefined][] = [
      ['rail', c.rail.names],
      ['suspension', c.suspension.names],
      ['surfaceMount', c.surfaceMount.names],
      ['feed', c.feed.names],
      ...c.connectors.map((x): [string, object | undefined] => [`connector ${x.id}`, x.names]),
      ...c.moduleTypes.flatMap((t): [string, object | undefined][] => [[`type ${t.id}`, t.names], ...t.beams.map((b): [string, object | undefined] => [`beam ${t.id}/${b.id}`, b.labels])]),
      ...c.presets.flatMap((p): [string, object | undefined][] => [
        [`preset ${p.id}`, p.names],
        [`preset ${p.id} description`, p.descriptions],
      ]),
    ];
    const missing = entries.filter(([, t]) => !t || !['de', 'fr', 'it'].every((l) => typeof (t as Record<string, unknown>)[l] === 'string')).map(([n]) => n);
    expect(entries.length).toBeGreaterThan(30);
    expect(missing).toEqual([]);
  });
});
