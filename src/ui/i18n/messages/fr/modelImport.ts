// The import preview's summary of how the model was oriented.
import type { AreaMessages } from '../../messageTypes';
import type en from '../en/modelImport';

export default {
  orientTurned: {
    one: '{count} partie fermée était tournée vers l’intérieur et a été retournée',
    many: '{count} de parties fermées étaient tournées vers l’intérieur et ont été retournées',
    other: '{count} parties fermées étaient tournées vers l’intérieur et ont été retournées',
  },
  orientTwoSided: {
    one: '{count} surface ouverte est éclairée et réfléchit des deux côtés',
    many: '{count} de surfaces ouvertes sont éclairées et réfléchissent des deux côtés',
    other: '{count} surfaces ouvertes sont éclairées et réfléchissent des deux côtés',
  },
  orientOneSided: {
    one: '{count} surface ouverte n’est éclairée que de face (simple face dans le fichier)',
    many: '{count} de surfaces ouvertes ne sont éclairées que de face (simple face dans le fichier)',
    other: '{count} surfaces ouvertes ne sont éclairées que de face (simple face dans le fichier)',
  },
  orientUndecided: {
    one: '{count} partie n’a pas d’intérieur net (faces impossibles à orienter de même) : elle est éclairée des deux côtés',
    many: '{count} de parties n’ont pas d’intérieur net (faces impossibles à orienter de même) : elles sont éclairées des deux côtés',
    other: '{count} parties n’ont pas d’intérieur net (faces impossibles à orienter de même) : elles sont éclairées des deux côtés',
  },
  orientClosed: 'Toutes les parties sont fermées et tournées vers l’extérieur',
} satisfies AreaMessages<typeof en>;
