// The 3D view's exposure control (docs/viewer.md, "Exposure"): automatic, or a fixed EV100.
export default {
  group: 'Exposure',
  auto: 'Auto',
  lock: 'Lock exposure',
  lockHint: 'Keep the current exposure, so another configuration or dimming shows brighter or darker',
  compensation: 'Exposure {ev} EV',
  resetCompensation: 'Reset',
  ev100: 'EV100 {ev}',
  ev100Field: 'Exposure value at ISO 100 (higher is darker)',
};
