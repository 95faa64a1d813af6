import type { MessageTree } from '../../messageTypes';
import common from './common';

export default {
  common,
} satisfies MessageTree;
