import type { AreaMessages } from '../../messageTypes';
import type en from '../en/aim';

export default {
  title: 'Orientation',
  rotation: 'Rotation {degrees}°',
  tilt: 'Inclinaison {degrees}°',
  limits: 'Pivote de {rotationMin} à {rotationMax}°, s’incline de {tiltMin} à {tiltMax}°',
  straightDown: 'Vers le bas',
  aimAt: 'Orienter vers…',
  aimAtActive: 'Touchez le sol ou une surface pour orienter',
  aimAtHint: 'Touchez un point du plan ou de la vue 3D : le projecteur s’oriente vers lui',
  cancel: 'Annuler',
  spotlightView: 'Vue du projecteur',
  spotlightLeave: 'Quitter la vue du projecteur',
  spotlightHint: 'Faites glisser pour pivoter et incliner le projecteur ; la lumière suit, le calcul complet se fait au relâchement',
  spotlightNeedsModule: 'Sélectionnez un projecteur orientable pour regarder depuis lui',
  outlines: 'Contours du faisceau 50 % et du champ 10 %',
} satisfies AreaMessages<typeof en>;
