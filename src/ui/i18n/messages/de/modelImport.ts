// The import preview's summary of how the model was oriented.
import type { AreaMessages } from '../../messageTypes';
import type en from '../en/modelImport';

export default {
  orientTurned: { one: '{count} geschlossenes Teil zeigte nach innen und wurde nach außen gedreht', other: '{count} geschlossene Teile zeigten nach innen und wurden nach außen gedreht' },
  orientTwoSided: { one: '{count} offene Fläche wird beidseitig beleuchtet und reflektiert beidseitig', other: '{count} offene Flächen werden beidseitig beleuchtet und reflektieren beidseitig' },
  orientOneSided: { one: '{count} offene Fläche wird nur von vorne beleuchtet (in der Datei einseitig)', other: '{count} offene Flächen werden nur von vorne beleuchtet (in der Datei einseitig)' },
  orientUndecided: {
    one: '{count} Teil hat kein eindeutiges Innen (Flächen lassen sich nicht gleich ausrichten): es wird beidseitig beleuchtet',
    other: '{count} Teile haben kein eindeutiges Innen (Flächen lassen sich nicht gleich ausrichten): sie werden beidseitig beleuchtet',
  },
  orientClosed: 'Alle Teile sind geschlossen und zeigen nach außen',
} satisfies AreaMessages<typeof en>;
