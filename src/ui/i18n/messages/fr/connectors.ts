import type en from '../en/connectors';
import type { AreaMessages } from '../../messageTypes';

export default {
  title: 'Extrémité du rail {n}',
  freeEnd: 'Extrémité libre : ajouter une dérivation par un connecteur',
  current: 'Connecteur : {name}',
  ports: '{name} : {free} sur {ports} raccords libres',
  change: 'Changer de connecteur',
  changeTo: 'Remplacer le connecteur au bout du rail {n} par : {name}',
  addBranch: 'Ajouter une dérivation',
  addBranchVia: 'Ajouter une dérivation par : {name}',
  left: 'à gauche',
  straight: 'tout droit',
  right: 'à droite',
  branchLabel: 'Ajouter une dérivation de 1 m par {name}, {direction}, au bout du rail {n}',
  branchChip: '{direction}',
} satisfies AreaMessages<typeof en>;
