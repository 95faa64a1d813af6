// The colour filter (gel) picker of a selected module (docs/colour-filters.md). Filter names and
// numbers are the maker's and stay as published.
export default {
  title: 'Colour filter',
  loading: 'Loading the filters’ spectra…',
  none: 'No filter',
  search: 'Search filters by name or number',
  searchPlaceholder: 'Name or number',
  noMatch: 'No filter matches “{query}”',
  swatch: 'Colour of the light through the filter',
  unfiltered: 'Unfiltered, {cct} K',
  chromaticity: 'CIE x {x}, y {y}',
  transmission: 'Transmission {percent}',
  white: 'CCT {cct} K, Duv {duv}',
  notWhite: 'Coloured light: no colour temperature',
  choose: 'Filter {name}: transmission {percent}',
  expertDetails: 'Expert details',
  kind_cto: 'Warming (CTO)',
  kind_ctb: 'Cooling (CTB)',
  kind_nd: 'Neutral density',
  kind_colour: 'Colours',
};
