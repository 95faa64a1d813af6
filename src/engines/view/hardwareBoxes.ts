import type { Vec3 } from '../../core/model/lightingScene';
import { MODULE_HEIGHT, RAIL_HEIGHT, type Fixtures } from './fixtures';

/** One box of the drawn hardware: which part (picks the colour), its size along its own x, y, z, centre, turn about the vertical. */
export interface HardwareBox {
  part: 'rail' | 'moduleOn' | 'moduleOff' | 'cable';
  size: Vec3;
  position: Vec3;
  /** Radians about the world y axis. */
  yaw: number;
  /** 'module:<id>' for modules (tests and tools find them by name), else ''. */
  name: string;
}

/**
 * The hardware as boxes (metres): a rail is 50 mm wide and RAIL_HEIGHT high
 * along its run; a module is its length less a 6 mm gap, 44 mm wide, sitting
 * on its photometric centre; a cable is 6 mm thick from ceiling to rail.
 */
export function hardwareBoxes(f: Fixtures): HardwareBox[] {
  const boxes: HardwareBox[] = [];
  for (const r of f.rails) {
    const dx = r.end[0] - r.start[0];
    const dz = r.end[2] - r.start[2];
    boxes.push({ part: 'rail', size: [Math.hypot(dx, dz), RAIL_HEIGHT, 0.05], position: [(r.start[0] + r.end[0]) / 2, r.start[1], (r.start[2] + r.end[2]) / 2], yaw: Math.atan2(-dz, dx), name: '' });
  }
  for (const m of f.modules) {
    boxes.push({
      part: m.on ? 'moduleOn' : 'moduleOff',
      size: [Math.max(0.03, m.length - 0.006), MODULE_HEIGHT, 0.044],
      position: [m.centre[0], m.centre[1] + MODULE_HEIGHT / 2, m.centre[2]],
      yaw: (m.heading * Math.PI) / 180,
      name: `module:${m.id}`,
    });
  }
  for (const c of f.cables) {
    const h = c.top[1] - c.bottom[1];
    if (!(h > 0)) continue;
    boxes.push({ part: 'cable', size: [0.006, h, 0.006], position: [c.top[0], (c.top[1] + c.bottom[1]) / 2, c.top[2]], yaw: 0, name: '' });
  }
  return boxes;
}
