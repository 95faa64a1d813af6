/**
 * The sizes of the view's luminaire models that need no geometry (three-free: fixtures.ts uses them
 * in the bake feed's chunk): the dimensions, the opening drawn, the head and can sizes, how tall a model is.
 */
import type { Photometry } from '../../../core/photometry/types';
import type { LuminaireKind } from './luminaireKind';

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
export const WALL = 0.006;
export const YOKE = { strip: 0.006, depth: 0.02, clearance: 0.008 };
export const ADAPTER: [number, number, number] = [0.04, 0.028, 0.034];
export const STEM_RADIUS = 0.008;
export const WIRE_RADIUS = 0.001;
/** The emitter sits this far proud of the housing face it lies on (no depth fighting; 0.5 mm). */
export const PROUD = 0.0005;
/** The least stem between a spot's yoke and the rail (metres). */
export const MIN_STEM = 0.02;

/** The radius of the n-gon the emitter is drawn as for an ellipse axis of `diameter`: its area equals the ellipse's (partMesh.ts). */
export function emitterRadius(diameter: number, segments = 32): number {
  return (diameter / 2) * Math.sqrt((2 * Math.PI) / (segments * Math.sin((2 * Math.PI) / segments)));
}

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
  /**
   * A luminaire standing on the floor (a lighting scene's, in the lower half of the room): the
   * photometric centre's height above the floor (m); its yoke stands on a stem and a base plate.
   * Absent or 0: it hangs.
   */
  stand?: number;
}

/** The opening drawn: the photometry's (width along local x, length along local z, as the baker's point sources) or one for the kind. */
export function drawnOpening(input: ModelInput): { x: number; z: number; shape: 'round' | 'rectangular'; area: number } {
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

export function spotHead(o: { x: number; z: number; shape: 'round' | 'rectangular' }): { radius: number; length: number; pivot: number; crossbar: number } {
  const inner = o.shape === 'round' ? emitterRadius(Math.max(o.x, o.z)) : Math.hypot(o.x, o.z) / 2;
  const radius = Math.max(0.02, inner + WALL);
  const length = Math.max(0.06, 0.9 * 2 * radius);
  const pivot = length / 2;
  // The farthest point of the head from its pivot sweeps a sphere; the crossbar stays clear of it.
  const crossbar = pivot + Math.hypot(length / 2, radius) + YOKE.clearance;
  return { radius, length, pivot, crossbar };
}

export function downlightCan(o: { x: number; z: number; shape: 'round' | 'rectangular' }): { radius: number; height: number } {
  const inner = o.shape === 'round' ? emitterRadius(Math.max(o.x, o.z)) : Math.hypot(o.x, o.z) / 2;
  const radius = Math.max(0.02, inner + WALL + 0.006);
  return { radius, height: Math.max(0.05, 0.6 * radius) };
}
