import type { AreaMessages } from '../../messageTypes';
import type en from '../en/filters';

export default {
  title: 'Farbfilter',
  loading: 'Filterspektren werden geladen…',
  none: 'Kein Filter',
  search: 'Filter nach Name oder Nummer suchen',
  searchPlaceholder: 'Name oder Nummer',
  noMatch: 'Kein Filter passt zu „{query}“',
  swatch: 'Farbe des Lichts durch den Filter',
  unfiltered: 'Ohne Filter, {cct} K',
  chromaticity: 'CIE x {x}, y {y}',
  transmission: 'Transmission {percent}',
  white: 'Farbtemperatur {cct} K, Duv {duv}',
  notWhite: 'Farbiges Licht: keine Farbtemperatur',
  choose: 'Filter {name}: Transmission {percent}',
  expertDetails: 'Expertendetails',
  kind_cto: 'Wärmer (CTO)',
  kind_ctb: 'Kühler (CTB)',
  kind_nd: 'Neutraldichte',
  kind_colour: 'Farben',
} satisfies AreaMessages<typeof en>;
