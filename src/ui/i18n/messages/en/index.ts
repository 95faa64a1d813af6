// English: the source of every key. One line per area; de, fr and it register the same areas.
import aim from './aim';
import common from './common';
import exposure from './exposure';
import filters from './filters';
import scenes from './scenes';

export default {
  aim,
  common,
  exposure,
  filters,
  scenes,
};
