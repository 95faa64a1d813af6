import type { AreaMessages } from '../../messageTypes';
import type en from '../en/notices';

export default {
  shareLinkNotice: 'Lien de partage : {notice}',
  driverFull: 'le driver de {capacity} W est plein : {used} W utilisés ; choisissez le driver de {larger} W dans les options du système ou ajoutez une deuxième alimentation',
  driverFullAddFeed: 'le driver de {capacity} W est plein : {used} W utilisés ; ajoutez une deuxième alimentation dans les options du système',
  feedOverload: 'l’alimentation {n} porterait {load} W, plus que son driver de {capacity} W ; ajoutez une deuxième alimentation ou choisissez un driver plus puissant',
  driverTooSmall: 'le {driver} de {capacity} W ne peut pas porter les {load} W de l’alimentation {n} ; choisissez un driver plus puissant ou ajoutez une alimentation',
  noFreeSpace: 'pas de place libre pour « {name} » dans cette pièce',
  noRoomForModule: 'pas de place pour un autre {name} ({length} m) sur ce rail',
  noFreeGap: 'aucun espace libre de ce rail ne peut accueillir un {name} ({length} m) : le plus grand fait {gap} m ; écartez des modules ou choisissez une répartition',
  'outside-room': 'le système {id} dépasse de la pièce de {width} × {depth} m',
  'self-overlap': 'le système {id} se croise lui-même',
  'system-overlap': 'le système {id} chevauche le système {other}',
  'suspension-range': 'la suspension doit être comprise entre {min} et {max} m (reçu {value})',
  'suspension-floor': 'les modules pendraient à {hang} m, sous le minimum de {min} m au-dessus du sol',
  'rail-length-range': 'la longueur du rail doit être comprise entre {min} et {max} m (reçu {value})',
  'rail-length-grid': 'la longueur du rail doit être un multiple de {step} m (reçu {value})',
  'modules-do-not-fit': 'les modules du rail {rail} ne tiennent pas sur ses {length} m avec la répartition « {distribution} »',
} satisfies AreaMessages<typeof en>;
