import type { MessageTree } from '../../messageTypes';
import common from './common';
import filters from './filters';

export default {
  common,
  filters,
} satisfies MessageTree;
