import './registerGuidanceEnglish';
import type { Remedy, RemedyPart } from '../../core/model/guidance/remedy';
import type { Format } from '../i18n/createFormat';
import type { Translate } from '../i18n/messageTypes';
import type { Language } from '../i18n/languages';

function partText(t: Translate, part: RemedyPart): string {
  const p = part.params;
  switch (part.kind) {
    case 'useDriver':
      return t('guidance.useDriver', { capacity: p.capacity });
    case 'addFeed':
      return t('guidance.addFeed', { capacity: p.capacity });
    case 'lengthenRail':
      return t('guidance.lengthenRail', { rail: p.rail, length: p.length });
    case 'setDistribution':
      switch (p.distribution) {
        case 'start':
          return t('guidance.distribution_start');
        case 'end':
          return t('guidance.distribution_end');
        case 'inside-centred':
          return t('guidance.distribution_inside-centred');
        default:
          return t('guidance.distribution_outside-centred');
      }
  }
}

/** A remedy in the UI language: "Use the 321.6 W driver (+€28.00)", the price difference in the locale's currency format. */
export function remedyText(t: Translate, format: Format, language: Language, remedy: Remedy): string {
  // A later part continues the sentence: its capital goes, except in German, where nouns keep theirs.
  const continued = (s: string) => (language === 'de' ? s : s.charAt(0).toLowerCase() + s.slice(1));
  const action = remedy.parts.map((p) => partText(t, p)).reduce((first, second) => t('guidance.and', { first, second: continued(second) }));
  const sign = remedy.priceDelta < 0 ? '−' : '+';
  return t('guidance.withPrice', { action, price: `${sign}${format.money(Math.abs(remedy.priceDelta), remedy.currency)}` });
}
