import type { AreaMessages } from '../../messageTypes';
import type en from '../en/scenes';

export default {
  title: 'Lichtszenen',
  go: 'GO',
  goTo: 'GO: {name}',
  back: 'ZURÜCK',
  fading: 'Überblendung',
  empty: 'Noch keine Szenen: Licht einstellen, Stimmung benennen und speichern.',
  defaultName: 'Szene {n}',
  nameLabel: 'Name der Szene',
  namePlaceholder: 'z. B. Abend',
  record: 'Speichern',
  recallHint: '{name} mit {seconds} s Überblendung abrufen',
  fadeLabel: 'Überblendzeit von {name}, Sekunden',
  seconds: 's',
  update: 'Aktualisieren',
  updateHint: 'Die aktuellen Helligkeiten in dieser Szene speichern',
  updateLabel: '{name} mit den aktuellen Helligkeiten aktualisieren',
  rename: 'Umbenennen',
  renameLabel: '{name} umbenennen',
  moveUp: '{name} nach oben',
  moveDown: '{name} nach unten',
  moduleOn: 'Modul {id} ein',
  deleteLabel: '{name} löschen',
} satisfies AreaMessages<typeof en>;
