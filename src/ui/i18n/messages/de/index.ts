import type { MessageTree } from '../../messageTypes';
import common from './common';
import exposure from './exposure';
import filters from './filters';

export default {
  common,
  exposure,
  filters,
} satisfies MessageTree;
