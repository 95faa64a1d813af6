import type { MessageTree } from '../../messageTypes';
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
} satisfies MessageTree;
