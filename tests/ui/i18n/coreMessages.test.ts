import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { checkAction } from '../../../src/core/model/actions/actionDefinitions';
import type { Refusal } from '../../../src/core/model/actions/action';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../../src/core/model/files/sceneFileError';
import { parseIes } from '../../../src/core/photometry/parseIes';
import { photometryWarnings } from '../../../src/core/photometry/checks';
import { codePhotometryError, codePhotometryWarning } from '../../../src/core/photometry/photometryCodes';
import { InputError } from '../../../src/core/inputError';
import { createFormat } from '../../../src/ui/i18n/createFormat';
import { createTranslator } from '../../../src/ui/i18n/createTranslator';
import { loadMessages } from '../../../src/ui/i18n/loadMessages';
import type { Language } from '../../../src/ui/i18n/languages';
import type { Translate } from '../../../src/ui/i18n/messageTypes';
import { coreParams, noticeText } from '../../../src/ui/i18n/noticeText';
import { translateCoded, type CodedMessage } from '../../../src/ui/i18n/translateCoded';
import refusals from '../../../src/ui/i18n/messages/en/refusals';
import fileErrors from '../../../src/ui/i18n/messages/en/fileErrors';
import scenes from '../../../src/ui/i18n/messages/en/scenes';
import photometry from '../../../src/ui/i18n/messages/en/photometry';
import { catalog, only, run, withPreset } from '../../core/model/helpers';

/**
 * The core's sentences in the shopper's language (docs/i18n.md, "Messages from the core"): real
 * refusals, file errors and photometry messages built by the core, worded in de, fr and it from
 * their codes, with the numbers in the locale's format; and every code in the English catalogue.
 */
const LOCALES: Record<Exclude<Language, 'en'>, string> = { de: 'de-CH', fr: 'fr-CH', it: 'it-CH' };

describe('core messages in every language', async () => {
  const tr: Record<Language, Translate> = {
    en: createTranslator(await loadMessages('en'), 'en', (x) => createFormat('en').number(x)),
    de: createTranslator(await loadMessages('de'), 'de-CH', (x) => createFormat('de-CH').number(x)),
    fr: createTranslator(await loadMessages('fr'), 'fr-CH', (x) => createFormat('fr-CH').number(x)),
    it: createTranslator(await loadMessages('it'), 'it-CH', (x) => createFormat('it-CH').number(x)),
  };
  const refused = (state: Configuration, name: string, params: unknown): Refusal => {
    const r = checkAction(state, name, params, catalog);
    if (r === true) throw new Error(`${name} was not refused`);
    return r;
  };
  /** English from the code equals the core's sentence byte for byte; de, fr and it differ from it, name no key and carry `numbers` in their locale's format. */
  const expectWorded = (msg: CodedMessage & { code?: string }, english: string, numbers: number[] = [], words: Partial<Record<Language, string>> = {}) => {
    expect(msg.code, english).toBeDefined();
    // English from the code is the core's sentence (zod's own words for a field aside: the UI says "missing").
    if (msg.detail?.code !== 'fieldMissing') expect(translateCoded(tr.en, 'notices', msg, coreParams(tr.en, 'en', catalog))).toBe(english);
    expect(noticeText(tr.en, 'en', catalog, msg)).toBe(english);
    for (const language of ['de', 'fr', 'it'] as const) {
      const text = noticeText(tr[language], language, catalog, msg);
      expect(text, `${language}: ${text}`).not.toBe(english);
      expect(text).not.toMatch(/\b(notices|refusals|fileErrors|photometry)\.\w/);
      expect(text).not.toMatch(/\{\w+\}/);
      for (const x of numbers) expect(text, `${language} shows ${x}`).toContain(createFormat(LOCALES[language]).number(x));
      if (words[language]) expect(text).toContain(words[language]);
    }
  };

  it('actions: the last feed, the last rail, a module past the end', () => {
    const single = withPreset('single', 1, 1);
    const sys = only(single);
    const lastFeed = refused(single, 'removeFeed', { feedId: sys.feeds[0].id });
    expect(lastFeed.code).toBe('keepOneFeed');
    expectWorded(lastFeed, 'a system keeps at least one power feed', [], { de: 'Einspeisung' });
    const lastRail = refused(single, 'removeRail', { railId: sys.rails[0].id });
    expectWorded(lastRail, lastRail.reason, [], { de: 'Schiene', fr: 'rail', it: 'binario' });
    // A module dragged past the end of the rail: the reach and the rail length in the locale's format.
    const mod = sys.rails[0].modules[0];
    const past = refused(single, 'moveModule', { moduleId: mod.id, offset: sys.rails[0].length - 0.05 });
    expect(['modulePastEnd', 'modulePastConnector']).toContain(past.code);
    expectWorded(past, past.reason, [Number(past.params!.reach), Number(past.params!.length)]);
  });

  it('a full driver: 153.6 W written as the locale writes it', () => {
    const s = withPreset('single', 1, 1);
    const rail = only(s).rails[0];
    // Modules until one is refused for the driver (the preset's driver leaves some headroom).
    let state = s;
    let r: Refusal | undefined;
    for (let i = 0; i < 12 && !r; i++) {
      const e = checkAction(state, 'addModule', { railId: rail.id, type: 'spot' }, catalog);
      if (e === true) state = run(state, 'addModule', { railId: rail.id, type: 'spot' });
      else r = e;
    }
    expect(r?.code).toMatch(/^driverFull|noRoomForModule|noFreeGap$/);
    expectWorded(
      r!,
      r!.reason,
      Object.values(r!.params ?? {}).filter((v): v is number => typeof v === 'number' && !Number.isInteger(v)),
    );
  });

  it('branches and connectors: a connector that does not turn, named from the catalog in each language', () => {
    const s = run(withPreset('single', 1, 1), 'addRail', { systemId: only(withPreset('single', 1, 1)).id, connector: 'straight', turn: 0 });
    const sys = only(s);
    const turn = refused(s, 'setJointTurn', { systemId: sys.id, joint: 0, degrees: 30 });
    expect(turn.code).toBe('connectorFixedAngle');
    expectWorded(turn, turn.reason);
    const straight = catalog.connectors.find((c) => c.id === 'straight')!;
    const de = noticeText(tr.de, 'de', catalog, turn);
    expect(de).toContain((straight as { names?: { de?: string } }).names?.de ?? straight.name);
  });

  it('objects: a sofa pushed through a wall names the sofa and the wall in the UI language', () => {
    const room = run(createConfiguration({ width: 4, depth: 4, height: 2.6 }), 'addObject', { source: { kind: 'library', item: 'sofa' } });
    const sofa = room.objects[0];
    const r = refused(room, 'moveObject', { objectId: sofa.id, placement: { on: 'floor', x: 0.2, z: 2 } });
    expect(r.code).toBe('objectCannotMove');
    expect(r.detail?.code).toMatch(/^objectThroughWall/);
    expectWorded(r, r.reason, [], { de: 'Westwand', fr: 'mur ouest', it: 'parete ovest' });
    expect(noticeText(tr.de, 'de', catalog, r)).toContain(tr.de('furniture.sofa'));
    const turn = refused(room, 'rotateObject', { objectId: sofa.id });
    expectWorded(turn, 'say how far to turn (by) or to which yaw');
  });

  it('room, feeds and patch: a room too small, a second feed at the same spot, an overlapping DMX patch', () => {
    const s = withPreset('single', 1, 1);
    const small = refused(s, 'setRoom', { width: 0.5, depth: s.room.depth, height: s.room.height });
    expectWorded(small, small.reason);
    const sys = only(s);
    const twin = refused(s, 'addFeed', { systemId: sys.id, at: sys.feeds[0].at });
    expect(twin.code).toBe('feedAlreadyThere');
    expectWorded(twin, twin.reason, [], { de: 'Kettenanfang', fr: 'début de la chaîne', it: 'inizio della catena' });
    const [a, b] = sys.rails[0].modules;
    const patched = run(s, 'setModulePatch', { moduleId: a.id, patch: { universe: 1, address: 1, resolution: 8, cct: false } });
    const overlap = refused(patched, 'setModulePatch', { moduleId: b.id, patch: { universe: 1, address: 1, resolution: 8, cct: false } });
    expect(overlap.code).toBe('dmxOverlap');
    expectWorded(overlap, overlap.reason);
  });

  it('scene files: not JSON (line and column), a newer version, a missing field, an invalid configuration', () => {
    const fail = (text: string): InputError => {
      try {
        deserializeConfiguration(text, catalog, '“plan.json”');
      } catch (e) {
        if (e instanceof SceneFileError) return e;
      }
      throw new Error('no SceneFileError');
    };
    const notJson = fail('{\n  "format": "luxbox-configuration",\n  oops\n}');
    expect(notJson.code).toBe('fileNotJsonAt');
    expect(notJson.params?.line).toBe(3);
    expectWorded(notJson, notJson.message, [], { de: 'Zeile 3', fr: 'ligne 3', it: 'riga 3' });
    const good = JSON.parse(serializeConfiguration(withPreset('single', 1, 1), catalog)) as Record<string, unknown>;
    const newer = fail(JSON.stringify({ ...good, version: 99 }));
    expect(newer.code).toBe('fileTooNew');
    expectWorded(newer, newer.message, [99]);
    const { room: _room, ...noRoom } = good.configuration as Record<string, unknown>;
    const missing = fail(JSON.stringify({ ...good, configuration: noRoom }));
    expect(missing.code).toBe('fileProblem');
    expect(missing.detail?.code).toBe('fieldMissing');
    expectWorded(missing, missing.message, [], { de: 'configuration.room', fr: 'configuration.room', it: 'configuration.room' });
    const config = good.configuration as { systems: { suspension: number }[] };
    const low = fail(JSON.stringify({ ...good, configuration: { ...config, systems: [{ ...config.systems[0], suspension: 9 }] } }));
    expect(low.code).toBe('fileInvalidAt');
    expect(low.detail?.code).toBe('suspension-range');
    expectWorded(low, low.message, [9], { de: 'Abhängung', fr: 'suspension', it: 'sospensione' });
  });

  it('photometric files: an IES file without TILT=, and a stated-lumens warning with its numbers', () => {
    let error: unknown;
    try {
      parseIes('this is not a photometric file\n1 2 3\n', 'ies/broken.ies');
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(InputError);
    const coded = codePhotometryError((error as Error).message)!;
    expect(coded.detail?.code).toBe('noTiltLine');
    for (const language of ['de', 'fr', 'it'] as const) {
      const text = translateCoded(tr[language], 'photometry', coded);
      expect(text).toContain('ies/broken.ies');
      expect(text).not.toContain('not an IES');
    }
    expect(translateCoded(tr.en, 'photometry', coded)).toBe((error as Error).message);
    const text = readFileSync(new URL('../../fixtures/photometry/lumens_mismatch_60x.ies', import.meta.url), 'utf8');
    const [warning] = photometryWarnings(parseIes(text, 'lumens_mismatch_60x.ies'));
    const w = codePhotometryWarning(warning);
    expect(w.code).toBe('lumensDiffer');
    // English digit grouping aside ("2,047 lm" on screen where the file report writes 2047), the sentence is the core's.
    expect(translateCoded(tr.en, 'photometry', w).replace(/(\d),(\d{3})/g, '$1$2')).toBe(warning);
    for (const language of ['de', 'fr', 'it'] as const) {
      const worded = translateCoded(tr[language], 'photometry', w);
      expect(worded).not.toBe(warning);
      expect(worded).toContain(createFormat(LOCALES[language]).number(60.21));
    }
  });

  it('every code of the inventory has de, fr and it wording with its parameters filled', () => {
    const areas = { refusals, fileErrors, photometry } as const;
    const sample = { name: 'Spot', id: 's1', n: 2, min: 0.5, max: 153.6, value: 7.5, count: 3, path: 'configuration.room', problem: '…' };
    for (const [area, messages] of Object.entries(areas)) {
      for (const [code, source] of Object.entries(messages)) {
        if (code.startsWith('what_')) continue;
        const placeholders = [...new Set((typeof source === 'string' ? source : source.other).match(/\{(\w+)\}/g) ?? [])].map((p) => p.slice(1, -1));
        const params = Object.fromEntries(placeholders.map((p) => [p, p in sample ? sample[p as keyof typeof sample] : `<${p}>`]));
        const template = typeof source === 'string' ? source : source.other;
        for (const language of ['de', 'fr', 'it'] as const) {
          const text = translateCoded(tr[language], area as 'refusals', { code, params, text: 'English' });
          expect(text, `${area}.${code} in ${language}`).not.toBe('English');
          const english = translateCoded(tr.en, area as 'refusals', { code, params, text: 'English' });
          if (/[a-z]{3}/i.test(template.replace(/\{[^}]*\}|'[^']*'|"[^"]*"/g, ''))) expect(text, `${area}.${code} in ${language}`).not.toBe(english);
          for (const p of placeholders) expect(text, `${area}.${code} in ${language} shows {${p}}`).toContain(typeof params[p] === 'number' ? createFormat(LOCALES[language]).number(params[p] as number) : String(params[p]));
        }
      }
    }
  });
});

/** Every code the core can emit, collected from its source, so a new sentence without a message fails here. */
describe('the English catalogue has every code the core emits', () => {
  const files = (dir: string): string[] => (readdirSyncRecursive(new URL(`../../../src/core/${dir}/`, import.meta.url)) as string[]).filter((f) => f.endsWith('.ts'));
  const source = ['model', 'photometry'].flatMap(files).concat(['inputError.ts', 'untrustedJson.ts', 'zodIssues.ts'].map((f) => new URL(`../../../src/core/${f}`, import.meta.url).pathname));
  it('collects the codes given to refusals, InputErrors, keyed problems and photometry patterns', async () => {
    // The scene actions' codes are worded by the scene panel from its area, which ships with that panel's chunk.
    const en = { ...(await loadMessages('en')), refusals, fileErrors, photometry, scenes };
    const known = new Set(Object.values(en).flatMap((area) => Object.keys(area as object)));
    const found = new Set<string>();
    for (const file of source) {
      const text = readFileSync(file, 'utf8');
      // `code: 'x'` (refusals, InputErrors, explain's CodedReason), keyed(…, 'x'), quoting(…, 'x', …), `p(…, 'x')` keys and photometry's [re, 'x', …].
      // Whitespace between tokens is \s*, line breaks included: a formatter may wrap any of these calls.
      for (const m of text.matchAll(/\bcode: '([a-z][A-Za-z0-9]*)'/g)) found.add(m[1]);
      // A sentence key handed back as a value (`key: 'x'`, the room-shape chunk's object sentences).
      for (const m of text.matchAll(/\bkey: '([a-z][A-Za-z0-9]*)'/g)) found.add(m[1]);
      for (const m of text.matchAll(/\bcode:\s*([^,}]*\?[^,}]*)/g)) for (const l of m[1].matchAll(/'([a-z][A-Za-z0-9]*)'/g)) found.add(l[1]);
      for (const m of text.matchAll(/keyed\([\s\S]*?\},\s*([^)]*?)(?:,\s*\{|\))/g)) for (const l of m[1].matchAll(/'([a-z][A-Za-z0-9]*)'/g)) found.add(l[1]);
      for (const m of text.matchAll(/quoting\([^;]*?`,\s*'([a-z][A-Za-z0-9]*)'/g)) found.add(m[1]);
      for (const m of text.matchAll(/\},\s*('([a-z][A-Za-z0-9]*)'),?\s*\)/g)) found.add(m[2]);
      for (const m of text.matchAll(/\/[gs]*,\s*'([a-z][A-Za-z0-9]*)',\s*\(/g)) found.add(m[1]);
      for (const m of text.matchAll(/\?\s*'([a-z][A-Za-z0-9]*[A-Z][A-Za-z0-9]*)'\s*:\s*'([a-z][A-Za-z0-9]*[A-Z][A-Za-z0-9]*)'/g)) {
        found.add(m[1]);
        found.add(m[2]);
      }
      for (const m of text.matchAll(/(?:const key = |KEYS = )[^;]*;/g)) for (const l of m[0].matchAll(/'([a-z][A-Za-z0-9]*[A-Z][A-Za-z0-9]*)'/g)) found.add(l[1]);
      for (const m of text.matchAll(/\{\s*[a-zA-Z]+: '([a-z][A-Za-z0-9]*)'(?:,\s*[a-zA-Z]+: '([a-z][A-Za-z0-9]*)')*/g)) if (/KEYS|notNumber/.test(m[0])) found.add(m[1]);
    }
    // Sentence codes are camelCase ('keepOneFeed'); kebab-case rule names and zod's own issue codes ('custom') are not.
    const codes = [...found].filter((c) => /[A-Z]/.test(c));
    // The collection finds the codes of every family (guards against a regex that finds nothing).
    for (const c of ['keepOneFeed', 'fixingOverhangStart', 'objectThroughWall', 'fileTooNew', 'fieldMissing', 'noTiltLine', 'lumensDiffer', 'aimTiltRange', 'roomWidthRange', 'objectOutsideOutline', 'underSlopeClips', 'roomShapeLoading'])
      expect(codes).toContain(c);
    const missing = codes.filter((c) => !known.has(c));
    expect(missing).toEqual([]);
  });
});

function readdirSyncRecursive(dir: URL): string[] {
  // eslint-disable-next-line @typescript-eslint/no-require-imports
  const { readdirSync, statSync } = require('node:fs') as typeof import('node:fs');
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const url = new URL(name, dir);
    if (statSync(url).isDirectory()) out.push(...readdirSyncRecursive(new URL(`${name}/`, dir)));
    else out.push(url.pathname);
  }
  return out;
}

describe('a broken share link in the startup banner', async () => {
  const de = createTranslator(await loadMessages('de'), 'de-CH', (x) => createFormat('de-CH').number(x));
  it('words the link and its problem in German (the link named in German, the parser’s reason kept as read)', async () => {
    const { decodeShareString } = await import('../../../src/core/model/files/shareLink');
    let error: unknown;
    try {
      // base64url of '{"format": oops}': not JSON, line 1.
      decodeShareString(Buffer.from('{"format": oops}').toString('base64url'), catalog);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(SceneFileError);
    const e = error as SceneFileError;
    const banner = { text: `This link could not be opened: ${e.message}. Showing an empty room instead.`, code: 'linkBroken', params: { problem: e.message }, detail: { text: e.message, code: e.code, params: e.params } };
    const text = translateCoded(de, 'app', banner, coreParams(de, 'de', catalog));
    expect(text).toContain('Dieser Link konnte nicht geöffnet werden: „Link zum Teilen“ ist kein gültiges JSON (');
    expect(text).not.toContain('could not be opened');
  });
});

describe('a coded message that lost a parameter', async () => {
  const de = createTranslator(await loadMessages('de'), 'de', (x) => createFormat('de').number(x));
  it('shows the English sentence rather than a placeholder', () => {
    // objectCannotMove quotes its problem as detail; without it the German would read "…: {problem}".
    expect(translateCoded(de, 'notices', { text: 'cannot move it there: Sofa o1 passes through the west wall', code: 'objectCannotMove' })).toBe('cannot move it there: Sofa o1 passes through the west wall');
    expect(translateCoded(de, 'notices', { text: 'x', code: 'objectCannotMove', detail: { text: 'y' } })).toBe('lässt sich nicht dorthin verschieben: y');
  });
});
