// Screen-reader announcements of the plan (src/ui/planner/PlanAnnouncer.tsx, docs/accessibility.md).
export default {
  selected: '{what} selected',
  changed: 'Changed: {what}',
  cleared: 'Nothing selected',
  undone: 'Undone. {what}',
  redone: 'Redone. {what}',
  module: 'Module {index} of {count} on rail {rail}',
  moduleInSystem: 'Module {index} of {count} on rail {rail} of system {system}',
  rail: 'Rail {rail} of system {system}, {length}',
  object: 'Object {index}',
  system: 'System {system}',
  railCount: { one: '{count} rail', other: '{count} rails' },
  moduleCount: { one: '{count} module', other: '{count} modules' },
  systemCount: { one: '{count} lighting system', other: '{count} lighting systems' },
  objectCount: { one: '{count} object', other: '{count} objects' },
  room: 'Room: {systems}, {modules}, {objects}',
  moduleOff: 'off',
};
