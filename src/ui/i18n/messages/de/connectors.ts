import type en from '../en/connectors';
import type { AreaMessages } from '../../messageTypes';

export default {
  title: 'Ende von Schiene {n}',
  freeEnd: 'Freies Ende: einen Abzweig über einen Verbinder anfügen',
  current: 'Verbinder: {name}',
  ports: '{name}: {free} von {ports} Anschlüssen frei',
  change: 'Verbinder ändern',
  changeTo: 'Den Verbinder am Ende von Schiene {n} in {name} ändern',
  addBranch: 'Abzweig anfügen',
  addBranchVia: 'Abzweig über {name} anfügen',
  left: 'links',
  straight: 'geradeaus',
  right: 'rechts',
  branchLabel: 'Einen 1-m-Abzweig über {name}, {direction}, am Ende von Schiene {n} anfügen',
  branchChip: '{direction}',
} satisfies AreaMessages<typeof en>;
