import type { AreaMessages } from '../../messageTypes';
import type en from '../en/aim';

export default {
  title: 'Ausrichtung',
  rotation: 'Drehung {degrees}°',
  tilt: 'Neigung {degrees}°',
  limits: 'Dreht {rotationMin}–{rotationMax}°, neigt {tiltMin}–{tiltMax}°',
  straightDown: 'Senkrecht nach unten',
  aimAt: 'Ausrichten auf…',
  aimAtActive: 'Boden oder Fläche antippen zum Ausrichten',
  aimAtHint: 'Einen Punkt im Plan oder in der 3D-Ansicht antippen: der Strahler dreht sich dorthin',
  cancel: 'Abbrechen',
  spotlightView: 'Strahleransicht',
  spotlightLeave: 'Strahleransicht verlassen',
  spotlightHint: 'Ziehen schwenkt und neigt den Strahler; das Licht folgt, die volle Berechnung läuft beim Loslassen',
  spotlightNeedsModule: 'Einen verstellbaren Strahler wählen, um aus ihm zu schauen',
  outlines: 'Umrisse Halbwertswinkel 50 % und Feld 10 %',
} satisfies AreaMessages<typeof en>;
