import type { AreaMessages } from '../../messageTypes';
import type en from '../en/scenes';

export default {
  title: 'Scènes lumineuses',
  go: 'GO',
  goTo: 'GO : {name}',
  back: 'RETOUR',
  fading: 'Fondu enchaîné',
  empty: 'Aucune scène : réglez les lumières, nommez l’ambiance et enregistrez-la.',
  defaultName: 'Scène {n}',
  nameLabel: 'Nom de la scène',
  namePlaceholder: 'p. ex. Soirée',
  record: 'Enregistrer',
  recallHint: 'Rappeler {name} avec un fondu de {seconds} s',
  fadeLabel: 'Durée du fondu de {name}, secondes',
  seconds: 's',
  update: 'Mettre à jour',
  updateHint: 'Enregistrer les niveaux actuels dans cette scène',
  updateLabel: 'Mettre à jour {name} avec les niveaux actuels',
  rename: 'Renommer',
  renameLabel: 'Renommer {name}',
  moveUp: 'Monter {name}',
  moveDown: 'Descendre {name}',
  moduleOn: 'Module {id} allumé',
  deleteLabel: 'Supprimer {name}',
} satisfies AreaMessages<typeof en>;
