import type { AreaMessages } from '../../messageTypes';
import type en from '../en/files';

export default {
  saved: '{name} salvato',
  cannotOpen: '«{name}» non può essere aperto: {problem}',
  opened: '{name} aperto',
  couldNotOpen: 'Non è stato possibile aprire «{name}» ({problem})',
  saveFile: 'Salva file',
  openFile: 'Apri file…',
  unitMetres: 'metri (m)',
  unitCentimetres: 'centimetri (cm)',
  unitMillimetres: 'millimetri (mm)',
  unitInches: 'pollici (in)',
  unitDetected: '{unit} — rilevata',
  modelUnreadable: '{names}: impossibile leggere ({problem})',
  modelRefused: '{name} non può essere aggiunto: {reason}',
  importModel: 'Importa modello…',
  importHint: 'Un .obj con il suo .mtl (selezionali entrambi), un .gltf o un .glb.',
  readingModel: 'Lettura del modello…',
  triangles: { one: '{count} triangolo', many: '{count} di triangoli', other: '{count} triangoli' },
  unitsOfFile: 'Unità del file (rilevate: {detected})',
  importWarnings: 'Avvisi di importazione',
  addToRoom: 'Aggiungi alla stanza',
} satisfies AreaMessages<typeof en>;
