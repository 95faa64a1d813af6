import { describe, expect, it } from 'vitest';
import { refuse } from '../../../src/core/model/actions/action';
import { checkAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { createFormat } from '../../../src/ui/i18n/createFormat';
import { createTranslator } from '../../../src/ui/i18n/createTranslator';
import { loadMessages } from '../../../src/ui/i18n/loadMessages';
import { translateCoded } from '../../../src/ui/i18n/translateCoded';
import { catalog, only, run, withPreset } from '../../core/model/helpers';
import { noticeText } from '../../../src/ui/i18n/noticeText';

// The core refuses in English (CLI, logs, API); the refusal carries a code and params that the
// UI words in the user's language (docs/i18n.md, "Messages from the core").
describe('coded refusals', async () => {
  const de = createTranslator(await loadMessages('de'), 'de', (x) => createFormat('de').number(x));

  it('a move out of the room: English reason for the API, German from the code, same numbers', () => {
    const s = withPreset('single', 1, 1);
    const sys = only(s);
    const r = checkAction(s, 'moveSystem', { systemId: sys.id, x: 40, z: sys.z }, catalog);
    expect(r).not.toBe(true);
    if (r === true) return;
    expect(r.reason).toBe(`system ${sys.id} reaches outside the ${s.room.width} × ${s.room.depth} m room`);
    // Deep equality and JSON see only { ok, reason }: the code is metadata.
    expect(JSON.parse(JSON.stringify(r))).toEqual({ ok: false, reason: r.reason });
    expect(r.code).toBe('outside-room');
    expect(translateCoded(de, 'notices', r)).toBe(`System ${sys.id} ragt aus dem Raum (${String(s.room.width).replace('.', ',')} × ${String(s.room.depth).replace('.', ',')} m)`);
  });

  it('a preset with no free space (an InputError with a code) and a full driver (the overload wording)', () => {
    const small = createConfiguration({ width: 3, depth: 2, height: 3 });
    const none = checkAction(small, 'placePreset', { presetId: 'long-line' }, catalog);
    expect(none !== true && translateCoded(de, 'notices', none)).toBe('kein freier Platz für „Long line“ in diesem Raum');
    // The planner names the preset from the catalog's translations.
    expect(none !== true && noticeText(de, 'de', catalog, none)).toBe('kein freier Platz für „Lange Linie“ in diesem Raum');
    // Five 43 W spots on the Single rail preset's 240 W driver (three, and the two it has room for): a sixth is refused with the load before and the driver that would carry it.
    let s = withPreset('single', 1, 1);
    for (let k = 0; k < 2; k++) s = run(s, 'addModule', { railId: only(s).rails[0].id, type: 'spot' });
    const full = checkAction(s, 'addModule', { railId: only(s).rails[0].id, type: 'spot' }, catalog);
    expect(full !== true && full.code).toBe('driverFull');
    expect(full !== true && translateCoded(de, 'notices', full)).toBe('der 240-W-Treiber ist voll: 215 W belegt; wählen Sie in den Systemoptionen den 321,6-W-Treiber oder fügen Sie eine zweite Einspeisung hinzu');
  });

  it('an uncoded refusal, or one whose code has no message yet, falls back to its English sentence, never a key', () => {
    // Every refusal the core writes is coded now (i18nCore.test.ts): these stand for a future one.
    const uncoded = refuse('a reason written tomorrow');
    expect(translateCoded(de, 'notices', uncoded)).toBe('a reason written tomorrow');
    const untranslated = refuse('another reason written tomorrow', { code: 'notYetTranslated' });
    expect(untranslated.code).toBe('notYetTranslated');
    expect(translateCoded(de, 'notices', untranslated)).toBe('another reason written tomorrow');
  });
});
