import type { AreaMessages } from '../../messageTypes';
import type en from '../en/guidance';

// Erster Start (Issue 27): Vorschläge auf dem leeren Plan und Abhilfen an einem gesperrten Bedienelement.
export default {
  firstRunTitle: 'Mit einer Vorlage beginnen',
  firstRunHint: 'Tippen Sie auf eine Vorlage, um sie in Ihren Raum zu setzen. Schienen und Leuchten können Sie danach beliebig ändern.',
  firstRunPlace: '{name} platzieren',
  firstRunAll: 'Alle Vorlagen',
  useDriver: '{capacity}-W-Treiber verwenden',
  addFeed: 'Einspeisung mit {capacity}-W-Treiber hinzufügen',
  lengthenRail: 'Schiene {rail} auf {length} m verlängern',
  distribution_start: 'Module ab dem Anfang reihen',
  distribution_end: 'Module ab dem Ende reihen',
  'distribution_inside-centred': 'Module gleichmäßig verteilen',
  'distribution_outside-centred': 'Module gleichmäßig verteilen, äußere an den Enden',
  and: '{first}, dann {second}',
  withPrice: '{action} ({price})',
} satisfies AreaMessages<typeof en>;
