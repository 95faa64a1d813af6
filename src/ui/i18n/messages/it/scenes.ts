import type { AreaMessages } from '../../messageTypes';
import type en from '../en/scenes';

export default {
  title: 'Scene luminose',
  go: 'GO',
  goTo: 'GO: {name}',
  back: 'INDIETRO',
  fading: 'Dissolvenza incrociata',
  empty: 'Nessuna scena: regola le luci, dai un nome all’atmosfera e registrala.',
  defaultName: 'Scena {n}',
  nameLabel: 'Nome della scena',
  namePlaceholder: 'p. es. Sera',
  record: 'Registra',
  recallHint: 'Richiama {name} con una dissolvenza di {seconds} s',
  fadeLabel: 'Durata della dissolvenza di {name}, secondi',
  seconds: 's',
  update: 'Aggiorna',
  updateHint: 'Salva i livelli attuali in questa scena',
  updateLabel: 'Aggiorna {name} con i livelli attuali',
  rename: 'Rinomina',
  renameLabel: 'Rinomina {name}',
  moveUp: 'Sposta su {name}',
  moveDown: 'Sposta giù {name}',
  moduleOn: 'Modulo {id} acceso',
  deleteLabel: 'Elimina {name}',
} satisfies AreaMessages<typeof en>;
