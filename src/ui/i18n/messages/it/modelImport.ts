// The import preview's summary of how the model was oriented.
import type { AreaMessages } from '../../messageTypes';
import type en from '../en/modelImport';

export default {
  orientTurned: {
    one: '{count} parte chiusa era rivolta verso l’interno ed è stata girata verso l’esterno',
    many: '{count} di parti chiuse erano rivolte verso l’interno e sono state girate verso l’esterno',
    other: '{count} parti chiuse erano rivolte verso l’interno e sono state girate verso l’esterno',
  },
  orientTwoSided: {
    one: '{count} superficie aperta è illuminata e riflette su entrambi i lati',
    many: '{count} di superfici aperte sono illuminate e riflettono su entrambi i lati',
    other: '{count} superfici aperte sono illuminate e riflettono su entrambi i lati',
  },
  orientOneSided: {
    one: '{count} superficie aperta è illuminata solo sul davanti (a una faccia nel file)',
    many: '{count} di superfici aperte sono illuminate solo sul davanti (a una faccia nel file)',
    other: '{count} superfici aperte sono illuminate solo sul davanti (a una faccia nel file)',
  },
  orientUndecided: {
    one: '{count} parte non ha un interno chiaro (facce non orientabili allo stesso modo): è illuminata su entrambi i lati',
    many: '{count} di parti non hanno un interno chiaro (facce non orientabili allo stesso modo): sono illuminate su entrambi i lati',
    other: '{count} parti non hanno un interno chiaro (facce non orientabili allo stesso modo): sono illuminate su entrambi i lati',
  },
  orientClosed: 'Tutte le parti sono chiuse e rivolte verso l’esterno',
} satisfies AreaMessages<typeof en>;
