import * as THREE from 'three';
import type { Fixtures } from '../fixtures';
import { RAIL_HEIGHT } from '../fixtures';
import type { PartRole } from './luminaireModel';

/** A piece of the track in world coordinates, with the role that shades it. */
export interface TrackPiece {
  role: Exclude<PartRole, 'emitter'>;
  geometry: THREE.BufferGeometry;
}

/**
 * Cross-sections (metres). The rail: the catalog's width (`rail.width`, 50 mm) × RAIL_HEIGHT
 * (35 mm), a U-channel open at the bottom (3 mm walls, 4 mm top), the shape of 48 V track profiles
 * whose adapters sit inside. Connectors: a sleeve 3 mm round the profile over the catalog's node
 * footprint (systemElementTree). Suspension: steel wire Ø 2 mm (catalog: "steel wire, ceiling
 * canopy"; 1.5–2 mm is the usual wire of such kits, assumed), a canopy Ø 60 × 12 mm at the ceiling
 * and a gripper Ø 8 × 30 mm on the rail (assumed sizes).
 */
const WALL = 0.003;
const TOP = 0.004;
const SLEEVE = 0.003;
const WIRE_RADIUS = 0.001;
const CANOPY = { radius: 0.03, height: 0.012 };
const GRIPPER = { radius: 0.004, height: 0.03 };

function placed(g: THREE.BufferGeometry, at: THREE.Vector3, yaw: number): THREE.BufferGeometry {
  g.applyMatrix4(new THREE.Matrix4().makeRotationY(yaw).setPosition(at));
  return g;
}

export function trackPieces(f: Fixtures): TrackPiece[] {
  const pieces: TrackPiece[] = [];
  const railWidth = f.railWidth;
  for (const r of f.rails) {
    const dx = r.end[0] - r.start[0];
    const dz = r.end[2] - r.start[2];
    const len = Math.hypot(dx, dz);
    if (!(len > 0)) continue;
    const yaw = Math.atan2(-dz, dx);
    const c = new THREE.Vector3((r.start[0] + r.end[0]) / 2, r.start[1], (r.start[2] + r.end[2]) / 2);
    // Along local x: the top plate and two side walls.
    pieces.push({ role: 'housing', geometry: placed(new THREE.BoxGeometry(len, TOP, railWidth).translate(0, RAIL_HEIGHT / 2 - TOP / 2, 0), c, yaw) });
    for (const s of [-1, 1]) pieces.push({ role: 'housing', geometry: placed(new THREE.BoxGeometry(len, RAIL_HEIGHT - TOP, WALL).translate(0, -TOP / 2, (s * (railWidth - WALL)) / 2), c, yaw) });
  }
  for (const { rect, y } of f.connectors) {
    const yaw = Math.atan2(-rect.axis[1], rect.axis[0]);
    const g = new THREE.BoxGeometry(2 * rect.halfLength, RAIL_HEIGHT + 2 * SLEEVE, 2 * rect.halfWidth + 2 * SLEEVE);
    pieces.push({ role: 'housing', geometry: placed(g, new THREE.Vector3(rect.centre[0], y, rect.centre[1]), yaw) });
  }
  for (const c of f.cables) {
    const h = c.top[1] - c.bottom[1];
    if (!(h > 0)) continue;
    pieces.push({ role: 'cable', geometry: new THREE.CylinderGeometry(WIRE_RADIUS, WIRE_RADIUS, h, 6, 1, true).translate(c.top[0], (c.top[1] + c.bottom[1]) / 2, c.top[2]) });
    pieces.push({ role: 'housing', geometry: new THREE.CylinderGeometry(CANOPY.radius, CANOPY.radius, CANOPY.height, 24).translate(c.top[0], c.top[1] - CANOPY.height / 2, c.top[2]) });
    pieces.push({ role: 'cable', geometry: new THREE.CylinderGeometry(GRIPPER.radius, GRIPPER.radius, Math.min(GRIPPER.height, h), 12).translate(c.top[0], c.bottom[1] + Math.min(GRIPPER.height, h) / 2, c.top[2]) });
  }
  return pieces;
}
