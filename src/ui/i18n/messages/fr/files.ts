import type { AreaMessages } from '../../messageTypes';
import type en from '../en/files';

export default {
  saved: '{name} enregistré',
  cannotOpen: '« {name} » ne peut pas être ouvert : {problem}',
  opened: '{name} ouvert',
  couldNotOpen: '« {name} » n’a pas pu être ouvert ({problem})',
  saveFile: 'Enregistrer le fichier',
  openFile: 'Ouvrir un fichier…',
  unitMetres: 'mètres (m)',
  unitCentimetres: 'centimètres (cm)',
  unitMillimetres: 'millimètres (mm)',
  unitInches: 'pouces (in)',
  unitDetected: '{unit} — détectée',
  modelUnreadable: '{names} : lecture impossible ({problem})',
  modelRefused: '{name} ne peut pas être ajouté : {reason}',
  importModel: 'Importer un modèle…',
  importHint: 'Un .obj avec son .mtl (choisir les deux), un .gltf ou un .glb.',
  readingModel: 'Lecture du modèle…',
  triangles: { one: '{count} triangle', many: '{count} de triangles', other: '{count} triangles' },
  unitsOfFile: 'Unités du fichier (détectées : {detected})',
  importWarnings: 'Avertissements d’importation',
  addToRoom: 'Ajouter à la pièce',
} satisfies AreaMessages<typeof en>;
