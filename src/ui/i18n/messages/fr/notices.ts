import type { AreaMessages } from '../../messageTypes';
import type en from '../en/notices';

export default {
  shareLinkNotice: 'Lien de partage : {notice}',
  driverFull: 'le driver de {capacity} W est plein : {used} W utilisés ; ajoutez une deuxième alimentation ou choisissez un driver plus puissant',
  feedOverload: 'l’alimentation {n} porterait {load} W, plus que son driver de {capacity} W ; ajoutez une deuxième alimentation ou choisissez un driver plus puissant',
  driverTooSmall: 'le {driver} de {capacity} W ne peut pas porter les {load} W de l’alimentation {n} ; choisissez un driver plus puissant ou ajoutez une alimentation',
  noFreeSpace: 'pas de place libre pour « {name} » dans cette pièce',
  noRoomForModule: 'pas de place pour un autre {name} ({length} m) sur ce rail',
  noFreeGap: 'aucun espace libre de ce rail ne peut accueillir un {name} ({length} m) : le plus grand fait {gap} m ; écartez des modules ou choisissez une répartition',
} satisfies AreaMessages<typeof en>;
