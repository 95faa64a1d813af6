/** The note after a type change that could not keep the beam (issue #27, "choices that stick"), in German and English. */
import { describe, expect, it } from 'vitest';
import { createI18n } from '../../../src/ui/i18n/createI18n';
import { beamChangeNote } from '../../../src/ui/planner/beamChangeNote';
import '../../../src/ui/planner/registerOptionsEnglish';
import { catalog } from './testPlanner';

const spot30 = { id: 'm1', type: 'spot', beam: 'medium' };
const module = (type: string, beam: string) => ({ id: 'm1', type, beam, cct: 3000, dimming: 1 }) as never;

describe('beamChangeNote', () => {
  it('names the old and the new beam when the angle had to change (30° spot → 48° flood)', async () => {
    const de = createI18n({ locale: 'de' });
    await de.ready;
    const { t } = de.getSnapshot();
    const note = beamChangeNote(spot30, module('flood', 'flood48'), catalog, t, 'de');
    expect(note).toMatch(/„.*30°.*“.*„.*48°.*“/);
    expect(note).not.toMatch(/[a-z]+\.[a-z]+[A-Z]/); // no message key
    const en = createI18n({ locale: 'en' }).getSnapshot();
    expect(beamChangeNote(spot30, module('flood', 'flood48'), catalog, en.t, 'en')).toBe(
      'Flood has no “Spot 30°”: the nearest beam, “Flood 48°”, is set'.replace('Flood has', `${catalog.moduleTypes.find((m) => m.id === 'flood')!.name} has`),
    );
  });
  it('says nothing when the beam was kept, for a beam change on the same type, or for another module', () => {
    const { t } = createI18n({ locale: 'en' }).getSnapshot();
    expect(beamChangeNote(spot30, module('spot-warmdim', 'medium'), catalog, t, 'en')).toBeNull();
    expect(beamChangeNote(spot30, module('spot', 'narrow'), catalog, t, 'en')).toBeNull();
    expect(beamChangeNote({ ...spot30, id: 'm2' }, module('flood', 'flood48'), catalog, t, 'en')).toBeNull();
    // A washer has no angle to compare: its default is no surprise worth a note.
    expect(beamChangeNote(spot30, module('washer', 'left'), catalog, t, 'en')).toBeNull();
  });
});
