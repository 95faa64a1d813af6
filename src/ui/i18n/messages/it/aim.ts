import type { AreaMessages } from '../../messageTypes';
import type en from '../en/aim';

export default {
  title: 'Orientamento',
  rotation: 'Rotazione {degrees}°',
  tilt: 'Inclinazione {degrees}°',
  limits: 'Ruota da {rotationMin} a {rotationMax}°, si inclina da {tiltMin} a {tiltMax}°',
  straightDown: 'Verso il basso',
  aimAt: 'Punta verso…',
  aimAtActive: 'Tocca il pavimento o una superficie per puntare',
  aimAtHint: 'Tocca un punto nella pianta o nella vista 3D: il faretto si gira verso di esso',
  cancel: 'Annulla',
  spotlightView: 'Vista dal faretto',
  spotlightLeave: 'Esci dalla vista dal faretto',
  spotlightHint: 'Trascina per ruotare e inclinare il faretto; la luce segue, il calcolo completo parte al rilascio',
  spotlightNeedsModule: 'Seleziona un faretto orientabile per guardare da esso',
  outlines: 'Contorni del fascio 50 % e del campo 10 %',
} satisfies AreaMessages<typeof en>;
