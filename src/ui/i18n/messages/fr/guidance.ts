import type { AreaMessages } from '../../messageTypes';
import type en from '../en/guidance';

// Premier lancement (issue 27) : suggestions sur le plan vide et solutions proposées sur une commande refusée.
export default {
  firstRunTitle: 'Commencer par un modèle',
  firstRunHint: 'Touchez un modèle pour le placer dans votre pièce. Vous pourrez ensuite modifier chaque rail et chaque luminaire.',
  firstRunPlace: 'Placer {name}',
  firstRunAll: 'Tous les modèles',
  useDriver: 'Utiliser le driver de {capacity} W',
  addFeed: 'Ajouter une alimentation avec le driver de {capacity} W',
  lengthenRail: 'Allonger le rail {rail} à {length} m',
  distribution_start: 'Aligner les modules depuis le début',
  distribution_end: 'Aligner les modules depuis la fin',
  'distribution_inside-centred': 'Espacer les modules régulièrement',
  'distribution_outside-centred': 'Espacer les modules régulièrement, ceux des bouts aux extrémités',
  and: '{first}, puis {second}',
  withPrice: '{action} ({price})',
} satisfies AreaMessages<typeof en>;
