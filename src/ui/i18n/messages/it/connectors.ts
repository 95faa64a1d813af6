import type en from '../en/connectors';
import type { AreaMessages } from '../../messageTypes';

export default {
  title: 'Estremità del binario {n}',
  freeEnd: 'Estremità libera: aggiungi una diramazione con un connettore',
  current: 'Connettore: {name}',
  ports: '{name}: {free} di {ports} attacchi liberi',
  change: 'Cambia connettore',
  changeTo: 'Sostituisci il connettore alla fine del binario {n} con: {name}',
  addBranch: 'Aggiungi una diramazione',
  addBranchVia: 'Aggiungi una diramazione con: {name}',
  left: 'a sinistra',
  straight: 'dritto',
  right: 'a destra',
  branchLabel: 'Aggiungi una diramazione di 1 m con {name}, {direction}, alla fine del binario {n}',
  branchChip: '{direction}',
} satisfies AreaMessages<typeof en>;
