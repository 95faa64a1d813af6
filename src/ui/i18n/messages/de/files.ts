import type { AreaMessages } from '../../messageTypes';
import type en from '../en/files';

export default {
  saved: '{name} gespeichert',
  cannotOpen: '„{name}“ kann nicht geöffnet werden: {problem}',
  opened: '{name} geöffnet',
  couldNotOpen: '„{name}“ konnte nicht geöffnet werden ({problem})',
  saveFile: 'Datei speichern',
  openFile: 'Datei öffnen…',
  unitMetres: 'Meter (m)',
  unitCentimetres: 'Zentimeter (cm)',
  unitMillimetres: 'Millimeter (mm)',
  unitInches: 'Zoll (in)',
  unitDetected: '{unit} — erkannt',
  modelUnreadable: '{names}: konnte nicht gelesen werden ({problem})',
  modelRefused: '{name} kann nicht hinzugefügt werden: {reason}',
  importModel: 'Modell importieren…',
  importHint: 'Eine .obj mit ihrer .mtl (beide auswählen), eine .gltf oder eine .glb.',
  readingModel: 'Modell wird gelesen…',
  triangles: { one: '{count} Dreieck', other: '{count} Dreiecke' },
  unitsOfFile: 'Einheiten der Datei (erkannt: {detected})',
  importWarnings: 'Hinweise zum Import',
  addToRoom: 'Zum Raum hinzufügen',
} satisfies AreaMessages<typeof en>;
