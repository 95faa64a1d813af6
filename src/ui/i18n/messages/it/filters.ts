import type { AreaMessages } from '../../messageTypes';
import type en from '../en/filters';

export default {
  title: 'Filtro colore',
  loading: 'Caricamento degli spettri dei filtri…',
  none: 'Nessun filtro',
  search: 'Cerca filtri per nome o numero',
  searchPlaceholder: 'Nome o numero',
  noMatch: 'Nessun filtro corrisponde a «{query}»',
  swatch: 'Colore della luce attraverso il filtro',
  unfiltered: 'Senza filtro, {cct} K',
  chromaticity: 'CIE x {x}, y {y}',
  transmission: 'Trasmissione {percent}',
  white: 'Temperatura di colore {cct} K, Duv {duv}',
  notWhite: 'Luce colorata: nessuna temperatura di colore',
  choose: 'Filtro {name}: trasmissione {percent}',
  expertDetails: 'Dettagli per esperti',
  kind_cto: 'Riscaldante (CTO)',
  kind_ctb: 'Raffreddante (CTB)',
  kind_nd: 'Densità neutra',
  kind_colour: 'Colori',
} satisfies AreaMessages<typeof en>;
