import { describe, expect, it } from 'vitest';
import { reasonBesideRemedy } from '../../../src/ui/planner/remedyReason';
import de from '../../../src/ui/i18n/messages/de/notices';
import en from '../../../src/ui/i18n/messages/en/notices';
import fr from '../../../src/ui/i18n/messages/fr/notices';
import it_ from '../../../src/ui/i18n/messages/it/notices';

describe('the reason beside a remedy keeps the problem, not where to go', () => {
  it('the full driver, in the four languages: the part before the semicolon, no "system options"', () => {
    expect(reasonBesideRemedy(en.driverFull)).toBe('the {capacity} W driver is full: {used} W used');
    expect(reasonBesideRemedy(de.driverFull)).toBe('der {capacity}-W-Treiber ist voll: {used} W belegt');
    // French: the narrow no-break space before ';' goes too.
    expect(reasonBesideRemedy(fr.driverFull)).toBe('le driver de {capacity} W est plein\u00a0: {used} W utilisés');
    expect(reasonBesideRemedy(it_.driverFull)).toBe('il driver da {capacity} W è pieno: {used} W in uso');
    for (const n of [en, de, fr, it_]) expect(reasonBesideRemedy(n.driverFullAddFeed)).not.toMatch(/;|option|System/);
  });

  it('a sentence without advice is kept whole', () => {
    expect(reasonBesideRemedy('no room for another Spot (0.15 m) on this rail')).toBe('no room for another Spot (0.15 m) on this rail');
  });
});
