import * as THREE from 'three';
import type { Photometry } from '../../../core/photometry/types';
import type { LuminaireKind } from './luminaireKind';
import type { LuminaireModel, LuminairePart, PartFrame } from './luminaireModel';
import { boxPart, emitterPart, emitterRadius, partFrom, rodPart } from './partMesh';

/**
 * Dimensions the catalog does not give (metres). Assumed: typical sizes of 48 V track luminaires
 * chosen for this view, not taken from any product's drawing (the catalog has none); the only
 * measured size is the luminous opening, from the photometric file:
 * - WALL: housing wall round the luminous opening, 6 mm (die-cast or extruded aluminium heads);
 * - spot head: a cylinder 0.9 × as long as its diameter (at least 60 mm);
 * - yoke: 6 mm steel strip, 20 mm wide, 8 mm clear of the head's swept sphere, so any aim fits;
 * - adapter: 40 × 28 × 34 mm, the part of a track adapter that sits inside the profile;
 * - stem Ø 16 mm; pendant and linear hangers: steel wire Ø 2 mm (as the suspension);
 * - bodies: linear diffuser 40 mm high, wall washer 60 mm with a 30 mm visor, pendant 50 mm.
 */
const WALL = 0.006;
const YOKE = { strip: 0.006, depth: 0.02, clearance: 0.008 };
const ADAPTER: [number, number, number] = [0.04, 0.028, 0.034];
const STEM_RADIUS = 0.008;
const WIRE_RADIUS = 0.001;
/** The emitter sits this far proud of the housing face it lies on (no depth fighting; 0.5 mm). */
const PROUD = 0.0005;
/** The least stem between a spot's yoke and the rail (metres). */
const MIN_STEM = 0.02;

/** What a model is built from: the photometry's luminous opening (null: none known), the module's length on the rail. */
export interface ModelInput {
  kind: LuminaireKind;
  opening: Photometry['luminousOpening'] | null;
  /** Length of rail the module occupies (m). */
  length: number;
  /**
   * Height of the rail's underside above the photometric centre (m) when the module hangs in a
   * rail (the adapter sits above it, stem or hangers bridge the gap); 0: no rail (a lighting scene's luminaire).
   */
  mount: number;
}

/** The opening drawn: the photometry's (width along local x, length along local z, as the baker's point sources) or one for the kind. */
function drawnOpening(input: ModelInput): { x: number; z: number; shape: 'round' | 'rectangular'; area: number } {
  const o = input.opening;
  const round = (s: string) => s === 'circular' || s === 'elliptical' || s === 'spherical' || s === 'cylindrical';
  const x = o ? Math.abs(o.width) : 0;
  const z = o ? Math.abs(o.length) : 0;
  if (o && x > 0 && z > 0 && Number.isFinite(x * z)) {
    const shape = round(o.shape) ? 'round' : 'rectangular';
    return { x, z, shape, area: shape === 'round' ? (Math.PI * x * z) / 4 : x * z };
  }
  // A point opening (or none known): the face a luminaire of this kind would show; its area is then the model's.
  const L = Math.max(0.05, input.length);
  const face: Record<LuminaireKind, [number, number, 'round' | 'rectangular']> = {
    spot: [0.6 * Math.min(L, 0.15), 0.6 * Math.min(L, 0.15), 'round'],
    downlight: [0.6 * Math.min(L, 0.15), 0.6 * Math.min(L, 0.15), 'round'],
    linear: [0.04, L - 0.02, 'rectangular'],
    pendant: [0.02, L - 0.02, 'rectangular'],
    washer: [0.6 * L, 0.05, 'rectangular'],
  };
  const [fx, fz, shape] = face[input.kind];
  return { x: fx, z: fz, shape, area: shape === 'round' ? (Math.PI * fx * fz) / 4 : fx * fz };
}

/** Height above the photometric centre of a model's top before any stem or hanger (m): what the rail must clear. */
export function modelHeight(input: Omit<ModelInput, 'mount'>): number {
  const o = drawnOpening({ ...input, mount: 0 });
  switch (input.kind) {
    case 'spot': {
      const { length, crossbar } = spotHead(o);
      return Math.max(length, crossbar + YOKE.strip) + MIN_STEM;
    }
    case 'downlight':
      return downlightCan(o).height;
    case 'linear':
      return 0.04;
    case 'washer':
      return 0.06;
    case 'pendant':
      return 0.025 + 0.04;
  }
}

function spotHead(o: { x: number; z: number; shape: 'round' | 'rectangular' }): { radius: number; length: number; pivot: number; crossbar: number } {
  const inner = o.shape === 'round' ? emitterRadius(Math.max(o.x, o.z)) : Math.hypot(o.x, o.z) / 2;
  const radius = Math.max(0.02, inner + WALL);
  const length = Math.max(0.06, 0.9 * 2 * radius);
  const pivot = length / 2;
  // The farthest point of the head from its pivot sweeps a sphere; the crossbar stays clear of it.
  const crossbar = pivot + Math.hypot(length / 2, radius) + YOKE.clearance;
  return { radius, length, pivot, crossbar };
}

function downlightCan(o: { x: number; z: number; shape: 'round' | 'rectangular' }): { radius: number; height: number } {
  const inner = o.shape === 'round' ? emitterRadius(Math.max(o.x, o.z)) : Math.hypot(o.x, o.z) / 2;
  const radius = Math.max(0.02, inner + WALL + 0.006);
  return { radius, height: Math.max(0.05, 0.6 * radius) };
}

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
  const bar = (w: number, h: number, y0: number, len: number) =>
    boxPart(alongX ? [len, h, w] : [w, h, len], 'housing', 'aim', [0, y0 + h / 2, 0]);
  switch (input.kind) {
    case 'spot': {
      const head = spotHead(o);
      // The head: a closed cylinder from the face (y = 0) to its back, turning about its centre.
      parts.push(partFrom(new THREE.CylinderGeometry(head.radius, head.radius, head.length, 32, 1, false), 'housing', 'aim', { at: [0, head.length / 2, 0] }));
      parts.push(emitter(-PROUD, -1));
      // The yoke (turns with the swivel only): two arms beside the head from the pivot to a crossbar above the swept sphere.
      const armX = head.radius + YOKE.clearance + YOKE.strip / 2;
      const armBottom = head.pivot - 0.02;
      for (const s of [-1, 1]) {
        parts.push(boxPart([YOKE.strip, head.crossbar - armBottom, YOKE.depth], 'housing', 'swivel', [s * armX, (armBottom + head.crossbar) / 2, 0]));
        // The pivot boss on the arm's outer side: a short cylinder along x.
        parts.push(partFrom(new THREE.CylinderGeometry(0.012, 0.012, 0.008, 16), 'housing', 'swivel', { at: [s * (armX + YOKE.strip / 2 + 0.004), head.pivot, 0], rotate: [0, 0, Math.PI / 2] }));
      }
      parts.push(boxPart([2 * armX + YOKE.strip, YOKE.strip, YOKE.depth], 'housing', 'swivel', [0, head.crossbar + YOKE.strip / 2, 0]));
      parts.push(...hanging(input.mount, head.crossbar + YOKE.strip, 'swivel'));
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
