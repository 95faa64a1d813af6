import type { MessageTree } from '../../messageTypes';
import common from './common';
import exposure from './exposure';
import filters from './filters';
import scenes from './scenes';

export default {
  common,
  exposure,
  filters,
  scenes,
} satisfies MessageTree;
