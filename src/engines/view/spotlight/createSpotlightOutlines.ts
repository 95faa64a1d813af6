import * as THREE from 'three';
import { aimAxis } from '../../../core/model/modules/aim';
import { coneRoomOutline, type RoomBox } from '../../../core/model/modules/coneOutline';
import type { ModuleAim } from '../../../core/model/configuration/configuration';
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';

/** Outline colours: beam (50 %) warm yellow, field (10 %) orange, both readable on light and dark surfaces. */
export const BEAM_OUTLINE_COLOR = 0xffd23f;
export const FIELD_OUTLINE_COLOR = 0xff7a1a;
/** Rays per outline: a smooth curve where it crosses from the floor onto a wall. */
const OUTLINE_RAYS = 180;

/** Where the outlined cones come from: the module's photometric centre and heading, and its beam and field. */
export interface OutlinedModule {
  position: Vec3;
  heading: number;
  beamDeg: number;
  fieldDeg: number;
}

export interface SpotlightOutlines {
  /** The two outlines, drawn over everything ('spotlight-outlines'). */
  readonly group: THREE.Group;
  /** The beam and field outlines where the cones along the aim meet the room (none without a room, or at 0° or 180°). */
  update(module: OutlinedModule, aim: ModuleAim, room: RoomBox | null): void;
  dispose(): void;
}

/** The spotlight view's beam (50 %) and field (10 %) outlines as two line loops. */
export function createSpotlightOutlines(): SpotlightOutlines {
  const group = new THREE.Group();
  group.name = 'spotlight-outlines';
  group.renderOrder = 10;
  const lines = [BEAM_OUTLINE_COLOR, FIELD_OUTLINE_COLOR].map((color) => {
    const line = new THREE.LineLoop(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color, depthTest: false, transparent: true }));
    line.renderOrder = 10;
    line.frustumCulled = false;
    group.add(line);
    return line;
  });
  return {
    group,
    update(module, aim, room) {
      const axis = aimAxis(module.heading, aim);
      [module.beamDeg, module.fieldDeg].forEach((full, k) => {
        const hits = room && full > 0 && full < 180 ? coneRoomOutline(module.position, axis, full / 2, room, OUTLINE_RAYS) : [];
        const g = new THREE.BufferGeometry();
        g.setAttribute(
          'position',
          new THREE.Float32BufferAttribute(
            hits.flatMap((h) => h.point),
            3,
          ),
        );
        lines[k].geometry.dispose();
        lines[k].geometry = g;
      });
    },
    dispose() {
      group.removeFromParent();
      for (const l of lines) {
        l.geometry.dispose();
        (l.material as THREE.Material).dispose();
      }
    },
  };
}
