// Notes shown by both the planner and the 3D view.
export default {
  photometryWarnings: 'Photometric data warnings',
  photometryWarningCount: { one: 'Photometric data: {count} warning', other: 'Photometric data: {count} warnings' },
};
