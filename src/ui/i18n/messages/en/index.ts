// English: the source of every key. One line per area; de, fr and it register the same areas.
import common from './common';

export default {
  common,
};
