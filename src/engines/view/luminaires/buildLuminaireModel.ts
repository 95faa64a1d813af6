import * as THREE from 'three';
import { ADAPTER, downlightCan, drawnOpening, emitterRadius, PROUD, spotHead, STEM_RADIUS, WALL, WIRE_RADIUS, YOKE, type ModelInput } from './luminaireDimensions';
import type { LuminaireModel, LuminairePart, PartFrame } from './luminaireModel';
import { boxPart, emitterPart, partFrom, rodPart } from './partMesh';

/** The adapter in the rail and what joins it to a model whose top is at `top`: a stem (one point) or two wires at ±`spread` along `axis`. */
function hanging(mount: number, top: number, frame: PartFrame, spread = 0, axis: 'x' | 'z' = 'x'): LuminairePart[] {
  if (!(mount > 0)) return [];
  const parts: LuminairePart[] = [boxPart(ADAPTER, 'housing', 'mount', [0, mount + ADAPTER[1] / 2, 0])];
  if (mount - top <= 0.002) return parts;
  if (spread <= 0) return [...parts, rodPart(STEM_RADIUS, top, mount, 'housing', frame)];
  for (const s of [-spread, spread]) parts.push(rodPart(WIRE_RADIUS, top, mount, 'cable', frame, axis === 'x' ? s : 0, axis === 'z' ? s : 0, 6));
  return parts;
}

/**
 * The model of a luminaire of a kind, in its frames (luminaireModel.ts), with the light-emitting
 * face(s) exactly the luminous opening (width along local x, length along local z: where the baker
 * puts its point sources), lying on the photometric centre (0.5 mm proud of the housing), facing
 * the optic's axis (local −y); the pendant's second face, up, emits the upper hemisphere.
 */
export function buildLuminaireModel(input: ModelInput): LuminaireModel {
  const o = drawnOpening(input);
  const parts: LuminairePart[] = [];
  const emitter = (y: number, side: -1 | 1) => emitterPart(o.shape, o.x, o.z, y, 'aim', side);
  const alongX = o.x >= o.z;
  const long = Math.max(o.x, o.z);
  const short = Math.min(o.x, o.z);
  const bar = (w: number, h: number, y0: number, len: number) => boxPart(alongX ? [len, h, w] : [w, h, len], 'housing', 'aim', [0, y0 + h / 2, 0]);
  switch (input.kind) {
    case 'spot': {
      const head = spotHead(o);
      // The head: a closed cylinder from the face (y = 0) to its back, turning about its centre.
      parts.push(partFrom(new THREE.CylinderGeometry(head.radius, head.radius, head.length, 32, 1, false), 'housing', 'aim', { at: [0, head.length / 2, 0] }));
      parts.push(emitter(-PROUD, -1));
      // The yoke (turns with the swivel only): two arms beside the head from the pivot to a crossbar
      // clear of the swept sphere: above it when hung, below it on a standing luminaire.
      const armX = head.radius + YOKE.clearance + YOKE.strip / 2;
      const standing = (input.stand ?? 0) > 0;
      const reach = head.crossbar - head.pivot;
      const [armFrom, armTo] = standing ? [head.pivot - reach, head.pivot + 0.02] : [head.pivot - 0.02, head.crossbar];
      for (const s of [-1, 1]) {
        parts.push(boxPart([YOKE.strip, armTo - armFrom, YOKE.depth], 'housing', 'swivel', [s * armX, (armFrom + armTo) / 2, 0]));
        // The pivot boss on the arm's outer side: a short cylinder along x.
        parts.push(partFrom(new THREE.CylinderGeometry(0.012, 0.012, 0.008, 16), 'housing', 'swivel', { at: [s * (armX + YOKE.strip / 2 + 0.004), head.pivot, 0], rotate: [0, 0, Math.PI / 2] }));
      }
      if (standing) {
        const bar = head.pivot - reach - YOKE.strip;
        parts.push(boxPart([2 * armX + YOKE.strip, YOKE.strip, YOKE.depth], 'housing', 'swivel', [0, bar + YOKE.strip / 2, 0]));
        // A stem down to a base plate on the floor (Ø 160 × 10 mm, assumed).
        const floor = -(input.stand ?? 0);
        if (bar - floor > 0.012) parts.push(rodPart(STEM_RADIUS, floor + 0.01, bar, 'housing', 'swivel'));
        parts.push(partFrom(new THREE.CylinderGeometry(0.08, 0.08, 0.01, 32), 'housing', 'mount', { at: [0, floor + 0.005, 0] }));
      } else {
        parts.push(boxPart([2 * armX + YOKE.strip, YOKE.strip, YOKE.depth], 'housing', 'swivel', [0, head.crossbar + YOKE.strip / 2, 0]));
        parts.push(...hanging(input.mount, head.crossbar + YOKE.strip, 'swivel'));
      }
      return { parts, pivot: [0, head.pivot, 0], emitterArea: o.area };
    }
    case 'downlight': {
      const can = downlightCan(o);
      parts.push(partFrom(new THREE.CylinderGeometry(can.radius, can.radius, can.height, 32, 1, false), 'housing', 'aim', { at: [0, can.height / 2, 0] }));
      // The trim ring round the opening, a torus lying flat at the face.
      const ring = (o.shape === 'round' ? emitterRadius(Math.max(o.x, o.z)) : Math.hypot(o.x, o.z) / 2) + 0.005;
      parts.push(partFrom(new THREE.TorusGeometry(ring, 0.005, 8, 32), 'housing', 'aim', { at: [0, 0.003, 0], rotate: [Math.PI / 2, 0, 0] }));
      parts.push(emitter(-PROUD, -1));
      parts.push(...hanging(input.mount, can.height, 'aim'));
      return { parts, pivot: [0, 0, 0], emitterArea: o.area };
    }
    case 'linear': {
      const len = long + 0.012;
      parts.push(bar(short + 2 * WALL, 0.04, 0, len));
      parts.push(emitter(-PROUD, -1));
      parts.push(...hanging(input.mount, 0.04, 'aim', len / 2 - 0.05, alongX ? 'x' : 'z'));
      return { parts, pivot: [0, 0, 0], emitterArea: o.area };
    }
    case 'washer': {
      // A box round the opening with a visor on its back (−x: the file's C180 side; the washer throws towards C0).
      const w = o.x + 2 * WALL;
      const d = o.z + 2 * WALL;
      parts.push(boxPart([w, 0.06, d], 'housing', 'aim', [0, 0.03, 0]));
      parts.push(boxPart([0.004, 0.03, d], 'housing', 'aim', [-w / 2 + 0.002, -0.015, 0]));
      parts.push(emitter(-PROUD, -1));
      parts.push(...hanging(input.mount, 0.06, 'aim'));
      return { parts, pivot: [0, 0, 0], emitterArea: o.area };
    }
    case 'pendant': {
      // A slim bar 50 mm high round the photometric centre: down light from its underside, up light from its top.
      const len = long + 0.012;
      parts.push(bar(short + 2 * WALL, 0.05, -0.025, len));
      parts.push(emitter(-0.025 - PROUD, -1));
      parts.push(emitter(0.025 + PROUD, 1));
      parts.push(...hanging(input.mount, 0.025, 'aim', len / 2 - 0.05, alongX ? 'x' : 'z'));
      return { parts, pivot: [0, 0, 0], emitterArea: o.area };
    }
  }
}
