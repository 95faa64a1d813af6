// English: the source of every key. One line per area; de, fr and it register the same areas.
import common from './common';
import exposure from './exposure';
import filters from './filters';
import scenes from './scenes';

export default {
  common,
  exposure,
  filters,
  scenes,
};
