// Connector nodes and branches of a tree of rails (docs/planner.md, "Branches"): the options of a selected rail's end.
export default {
  title: 'End of rail {n}',
  freeEnd: 'Free end: add a branch through a connector',
  current: 'Connector: {name}',
  ports: '{name}: {free} of {ports} ports free',
  change: 'Change connector',
  changeTo: 'Change the connector at the end of rail {n} to the {name}',
  addBranch: 'Add a branch',
  addBranchVia: 'Add a branch through the {name}',
  left: 'left',
  straight: 'straight on',
  right: 'right',
  branchLabel: 'Add a 1 m branch through the {name}, {direction}, at the end of rail {n}',
  branchChip: '{direction}',
};
