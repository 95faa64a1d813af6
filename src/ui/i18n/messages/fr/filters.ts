import type { AreaMessages } from '../../messageTypes';
import type en from '../en/filters';

export default {
  title: 'Filtre de couleur',
  loading: 'Chargement des spectres des filtres…',
  none: 'Sans filtre',
  search: 'Chercher un filtre par nom ou numéro',
  searchPlaceholder: 'Nom ou numéro',
  noMatch: 'Aucun filtre ne correspond à « {query} »',
  swatch: 'Couleur de la lumière à travers le filtre',
  unfiltered: 'Sans filtre, {cct} K',
  chromaticity: 'CIE x {x}, y {y}',
  transmission: 'Transmission {percent}',
  white: 'Température de couleur {cct} K, Duv {duv}',
  notWhite: 'Lumière colorée : pas de température de couleur',
  choose: 'Filtre {name}\u00a0: transmission {percent}',
  expertDetails: 'Détails pour experts',
  kind_cto: 'Réchauffant (CTO)',
  kind_ctb: 'Refroidissant (CTB)',
  kind_nd: 'Densité neutre',
  kind_colour: 'Couleurs',
} satisfies AreaMessages<typeof en>;
