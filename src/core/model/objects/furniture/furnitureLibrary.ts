/**
 * The furniture library: real-size items built from closed convex parts (meshParts.ts): boxes,
 * frusta, and ringed solids for what is upholstered or alive (cushions with rounded edges, limbs,
 * heads, leaf clusters), so each piece reads as what it is.
 * Frame of every item: metres, y up, front toward +z. Floor items: origin at the centre of the
 * footprint on the floor (x ∈ ±width/2, z ∈ ±depth/2, y ∈ [0, height]). Wall items: origin at
 * the centre of the back (x ∈ ±width/2, y ∈ ±height/2, z ∈ [0, depth], back on z = 0).
 * Dimensions and their sources: docs/furniture.md.
 */
import type { TriangleMesh } from '../../../mesh/triangleMesh';
import { boxPart, composeParts, ellipsoidRings, frustumPart, ringedPart, slabRings, type MeshPart } from './meshParts';
import { objectFinishRgb } from './objectFinishes';
import { standingPersonParts } from './standingPerson';

export interface FurnitureItem {
  readonly id: string;
  readonly name: string;
  /** Where it stands: on the floor, or hung on a wall. */
  readonly mount: 'floor' | 'wall';
  /** Overall size at scale 1, metres: x (width), z (depth), y (height). */
  readonly width: number;
  readonly depth: number;
  readonly height: number;
  /** Wall items: the default height of the origin (back centre) above the floor, metres. */
  readonly hangHeight?: number;
  /** Default finish (src/core/model/objects/furniture/objectFinishes.ts) per material. */
  readonly finishes: Readonly<Record<string, string>>;
  /** The closed solids it is made of. */
  readonly parts: () => MeshPart[];
}

type P3 = [number, number, number];

/** Four legs of square section `s` under a rectangle w × d, inset `inset` from its edges, from y 0 to h. */
function fourLegs(material: string, w: number, d: number, s: number, inset: number, h: number): MeshPart[] {
  const xs = [-w / 2 + inset, w / 2 - inset - s];
  const zs = [-d / 2 + inset, d / 2 - inset - s];
  return xs.flatMap((x) => zs.map((z) => boxPart(material, [x, 0, z], [x + s, h, z + s])));
}

/** Round feet of radius r under a rectangle w × d, inset from its edges, from y 0 to h. */
function roundFeet(material: string, w: number, d: number, r: number, inset: number, h: number): MeshPart[] {
  const xs = [-w / 2 + inset + r, w / 2 - inset - r];
  const zs = [-d / 2 + inset + r, d / 2 - inset - r];
  return xs.flatMap((x) => zs.map((z) => frustumPart(material, x, z, 0, h, r, r, 8)));
}

const box = (material: string, min: P3, max: P3) => boxPart(material, min, max);

/** A table: a top of thickness t on four legs; light reaches the floor under it. */
function table(w: number, d: number, h: number, t: number, leg: number, inset: number): MeshPart[] {
  return [box('top', [-w / 2, h - t, -d / 2], [w / 2, h, d / 2]), ...fourLegs('legs', w, d, leg, inset, h - t)];
}

/**
 * An upholstered or eased block over x0…x1, y0…y1, z0…z1 (exactly these bounds), its plan corners
 * and top edge bevelled (eTop), its bottom edge too where it shows (eBottom), leaning by dz from
 * bottom to top. Flat facets only: few light-map charts (meshParts.ts, slabRings).
 */
function cushion(material: string, x0: number, x1: number, y0: number, y1: number, z0: number, z1: number, eTop: number, eBottom = 0, dz = 0): MeshPart {
  const hx = (x1 - x0) / 2;
  const hz = (z1 - z0) / 2;
  const rc = Math.min(hx, hz, Math.max(eTop, eBottom) + 0.02);
  return ringedPart(material, (x0 + x1) / 2, (z0 + z1) / 2, slabRings(y0, y1, hx, hz, rc, eTop, eBottom, dz), 1);
}

/** An ellipsoid centred at (x, yc, z) with semi-axes hx, ay, hz, 2k − 1 rings (a head, a cluster of leaves). */
function blob(material: string, x: number, yc: number, z: number, hx: number, ay: number, hz: number, k = 2): MeshPart {
  return ringedPart(material, x, z, ellipsoidRings(yc, ay, hx, hz, k), 2, yc - ay, yc + ay);
}

/** Both sides: the parts for x and for −x. */
const mirrored = (make: (side: number) => MeshPart): MeshPart[] => [make(-1), make(1)];

/** A sofa or armchair: a base on round feet, a back, arms, seat cushions and back cushions leaning back. */
function seating(w: number, d: number, h: number, seats: number): MeshPart[] {
  const feet = 0.1;
  const arm = 0.16;
  const back = 0.2;
  const parts: MeshPart[] = [
    ...roundFeet('legs', w, d, 0.025, 0.05, feet + 0.02),
    cushion('frame', -w / 2, w / 2, feet, 0.34, -d / 2, d / 2, 0.02),
    cushion('frame', -w / 2, w / 2, 0.3, h, -d / 2, -d / 2 + back, 0.06),
    ...mirrored((s) => cushion('frame', s < 0 ? -w / 2 : w / 2 - arm, s < 0 ? -w / 2 + arm : w / 2, 0.3, 0.62, -d / 2 + 0.1, d / 2, 0.05)),
  ];
  const inner = w - 2 * arm;
  for (let i = 0; i < seats; i++) {
    const x0 = -w / 2 + arm + (inner * i) / seats + 0.006;
    const x1 = -w / 2 + arm + (inner * (i + 1)) / seats - 0.006;
    parts.push(cushion('cushions', x0, x1, 0.32, 0.47, -d / 2 + back, d / 2 - 0.01, 0.04));
    parts.push(cushion('cushions', x0, x1, 0.44, h - 0.05, -d / 2 + back - 0.02, -d / 2 + back + 0.16, 0.05, 0.03, -0.08));
  }
  return parts;
}

/** Books standing on a board from y0, filling x0…x1 with a repeating pattern of widths and heights. */
function bookRow(x0: number, x1: number, y0: number, z0: number, z1: number, maxHeight: number, seed: number): MeshPart[] {
  const widths = [0.042, 0.06, 0.035, 0.07, 0.048, 0.055, 0.04];
  const heights = [0.24, 0.21, 0.28, 0.19, 0.3, 0.23, 0.26];
  const parts: MeshPart[] = [];
  let x = x0 + 0.01;
  for (let i = seed; ; i++) {
    const w = widths[i % widths.length];
    if (x + w > x1 - 0.01) break;
    const h = Math.min(heights[(i * 3) % heights.length], maxHeight);
    parts.push(box('books', [x, y0, z0], [x + w, y0 + h, z1]));
    x += w + 0.002;
  }
  return parts;
}

export const FURNITURE_LIBRARY: readonly FurnitureItem[] = [
  {
    id: 'dining-table',
    name: 'Dining table',
    mount: 'floor',
    width: 1.8,
    depth: 0.9,
    height: 0.75,
    finishes: { top: 'oak-veneer', legs: 'oak-veneer' },
    // Dimensions: Neufert (table height 72-76 cm; 60 cm of table edge per person: 180 × 90 cm seats six)
    parts: () => table(1.8, 0.9, 0.75, 0.04, 0.06, 0.05),
  },
  {
    id: 'coffee-table',
    name: 'Coffee table',
    mount: 'floor',
    width: 1.2,
    depth: 0.6,
    height: 0.45,
    finishes: { top: 'walnut-veneer', legs: 'black-metal' },
    // Dimensions: common sizes 100-130 × 50-70 cm, 40-45 cm high (about sofa seat height)
    parts: () => [cushion('top', -0.6, 0.6, 0.42, 0.45, -0.3, 0.3, 0.01), ...roundFeet('legs', 1.2, 0.6, 0.018, 0.05, 0.43)],
  },
  {
    id: 'chair',
    name: 'Chair',
    mount: 'floor',
    width: 0.45,
    depth: 0.52,
    height: 0.9,
    finishes: { seat: 'oak-veneer', back: 'oak-veneer', legs: 'oak-veneer' },
    // Dimensions: Neufert / EN 1729 adult chair: seat height 45 cm, seat 40-45 cm wide and deep, backrest to 85-90 cm
    parts: () => [
      cushion('seat', -0.225, 0.225, 0.42, 0.46, -0.24, 0.26, 0.012),
      ...mirrored((s) => frustumPart('legs', s * 0.19, 0.215, 0, 0.44, 0.015, 0.019, 8)),
      // back posts run from the floor to the top rail, leaning back 2 cm
      ...mirrored((s) =>
        ringedPart('back', s * 0.195, -0.22, [
          [0, 0.02, 0.02, 0.02],
          [0.9, 0.02, 0.02, 0.02, -0.02],
        ]),
      ),
      cushion('back', -0.2, 0.2, 0.74, 0.88, -0.248, -0.222, 0.01, 0.01, -0.006),
      cushion('back', -0.2, 0.2, 0.56, 0.62, -0.244, -0.222, 0.008, 0.008, -0.002),
    ],
  },
  {
    id: 'sofa',
    name: 'Sofa (three seats)',
    mount: 'floor',
    width: 2.1,
    depth: 0.9,
    height: 0.85,
    finishes: { frame: 'grey-fabric', cushions: 'grey-fabric', legs: 'walnut-veneer' },
    // Dimensions: common three-seat sofas 200-230 × 85-100 cm, 80-90 cm high, seat 42-45 cm (Neufert: 60-70 cm per seat)
    parts: () => seating(2.1, 0.9, 0.85, 3),
  },
  {
    id: 'armchair',
    name: 'Armchair',
    mount: 'floor',
    width: 0.85,
    depth: 0.85,
    height: 0.9,
    finishes: { frame: 'beige-linen', cushions: 'beige-linen', legs: 'walnut-veneer' },
    // Dimensions: common armchairs 75-90 cm wide and deep, 85-100 cm high, seat about 44 cm
    parts: () => seating(0.85, 0.85, 0.9, 1),
  },
  {
    id: 'sideboard',
    name: 'Sideboard',
    mount: 'floor',
    width: 1.8,
    depth: 0.45,
    height: 0.8,
    finishes: { body: 'white-lacquer', fronts: 'white-lacquer', top: 'oak-veneer', legs: 'black-metal' },
    // Dimensions: common sideboards 160-200 × 40-50 cm, 75-85 cm high
    parts: () => [
      ...fourLegs('legs', 1.8, 0.45, 0.03, 0.04, 0.12),
      box('body', [-0.9, 0.12, -0.225], [0.9, 0.78, 0.205]),
      box('top', [-0.9, 0.78, -0.225], [0.9, 0.8, 0.225]),
      ...[0, 1, 2].map((i) => box('fronts', [-0.895 + i * 0.6, 0.125, 0.205], [-0.305 + i * 0.6, 0.775, 0.225])),
    ],
  },
  {
    id: 'open-shelf',
    name: 'Open shelf with books',
    mount: 'floor',
    width: 1,
    depth: 0.35,
    height: 2,
    finishes: { frame: 'white-lacquer', books: 'book-spines' },
    // Dimensions: common bookcases 80-100 cm wide, 30-40 cm deep, 180-220 cm high; Neufert: 30-35 cm shelf spacing for books
    parts: () => {
      const boards = [0.04, 0.5, 0.86, 1.22, 1.58, 1.98];
      return [
        box('frame', [-0.5, 0, -0.175], [-0.48, 2, 0.175]),
        box('frame', [0.48, 0, -0.175], [0.5, 2, 0.175]),
        ...boards.map((y) => box('frame', [-0.48, y - (y === 0.04 ? 0.04 : 0.02), -0.175], [0.48, y, 0.175])),
        ...boards.slice(0, 5).flatMap((y, k) => bookRow(-0.48, k % 2 === 0 ? 0.48 : 0.2, y, -0.15, 0.07, boards[k + 1] - y - 0.06, k * 2)),
      ];
    },
  },
  {
    id: 'bed',
    name: 'Double bed',
    mount: 'floor',
    width: 1.7,
    depth: 2.15,
    height: 1,
    finishes: { frame: 'oak-veneer', legs: 'oak-veneer', mattress: 'white-linen', bedding: 'white-linen' },
    // Dimensions: DIN 68880 / Neufert: mattress 160 × 200 cm, about 45-55 cm top height; frame adds 5 cm each side; headboard about 1 m
    parts: () => [
      cushion('frame', -0.85, 0.85, 0.12, 1, -1.075, -0.995, 0.03),
      ...[-0.96, 1.02].flatMap((z) => mirrored((s) => frustumPart('legs', s * 0.79, z, 0, 0.14, 0.03, 0.03, 8))),
      cushion('frame', -0.85, 0.85, 0.12, 0.32, -1, 1.075, 0.015),
      cushion('mattress', -0.8, 0.8, 0.3, 0.52, -0.95, 1.055, 0.05),
      cushion('bedding', -0.83, 0.83, 0.47, 0.6, -0.35, 1.07, 0.05),
      cushion('bedding', -0.83, 0.83, 0.5, 0.64, -0.42, -0.2, 0.05, 0.03),
      ...mirrored((s) => cushion('bedding', s < 0 ? -0.76 : 0.05, s < 0 ? -0.05 : 0.76, 0.5, 0.67, -0.94, -0.56, 0.06, 0.04)),
    ],
  },
  {
    id: 'desk',
    name: 'Desk',
    mount: 'floor',
    width: 1.4,
    depth: 0.7,
    height: 0.75,
    finishes: { top: 'white-lacquer', frame: 'black-metal' },
    // Dimensions: EN 527-1 work desks: 72-75 cm high; Neufert: at least 120-160 × 70-80 cm
    parts: () => [box('top', [-0.7, 0.725, -0.35], [0.7, 0.75, 0.35]), box('frame', [-0.68, 0, -0.32], [-0.64, 0.725, 0.32]), box('frame', [0.64, 0, -0.32], [0.68, 0.725, 0.32]), box('frame', [-0.64, 0.35, -0.32], [0.64, 0.7, -0.3])],
  },
  {
    id: 'kitchen-island',
    name: 'Kitchen island',
    mount: 'floor',
    width: 1.8,
    depth: 0.9,
    height: 0.91,
    finishes: { worktop: 'stone-worktop', cabinet: 'white-lacquer', fronts: 'white-lacquer', plinth: 'black-metal' },
    // Dimensions: DIN EN 1116 / Neufert: worktop 85-95 cm high (91 cm here), cabinets 60 cm deep (two rows back to back: 90 cm with overhang), plinth 10 cm
    parts: () => [
      box('plinth', [-0.85, 0, -0.38], [0.85, 0.1, 0.38]),
      box('cabinet', [-0.88, 0.1, -0.42], [0.88, 0.87, 0.4]),
      ...[0, 1, 2].map((i) => box('fronts', [-0.875 + i * (1.75 / 3), 0.105, 0.4], [-0.875 + (i + 1) * (1.75 / 3) - 0.005, 0.865, 0.42])),
      box('worktop', [-0.9, 0.87, -0.45], [0.9, 0.91, 0.45]),
    ],
  },
  {
    id: 'picture',
    name: 'Framed picture',
    mount: 'wall',
    width: 0.8,
    depth: 0.03,
    height: 0.6,
    hangHeight: 1.55,
    finishes: { frame: 'black-metal', canvas: 'canvas-print' },
    // Dimensions: common frame size 80 × 60 cm; hung with its centre at eye height, about 1.5-1.6 m
    parts: () => [
      box('frame', [-0.4, -0.3, 0], [0.4, -0.255, 0.03]),
      box('frame', [-0.4, 0.255, 0], [0.4, 0.3, 0.03]),
      box('frame', [-0.4, -0.255, 0], [-0.355, 0.255, 0.03]),
      box('frame', [0.355, -0.255, 0], [0.4, 0.255, 0.03]),
      box('canvas', [-0.355, -0.255, 0.005], [0.355, 0.255, 0.02]),
    ],
  },
  {
    id: 'floor-plant',
    name: 'Floor plant',
    mount: 'floor',
    width: 0.6,
    depth: 0.6,
    height: 1.5,
    finishes: { pot: 'terracotta', stem: 'walnut-veneer', leaves: 'leaf-green' },
    // Dimensions: a large indoor plant (e.g. Ficus) 1.2-1.8 m high in a 30-40 cm pot
    parts: () => [
      frustumPart('pot', 0, 0, 0, 0.38, 0.14, 0.18, 12),
      frustumPart('stem', 0, 0, 0.36, 0.95, 0.022, 0.014, 8),
      blob('leaves', 0, 0.92, 0, 0.3, 0.22, 0.3),
      blob('leaves', 0.1, 1.1, -0.1, 0.16, 0.17, 0.16),
      blob('leaves', -0.11, 1.08, 0.1, 0.15, 0.16, 0.15),
      blob('leaves', 0.02, 1.29, 0, 0.16, 0.21, 0.16),
    ],
  },
  {
    id: 'person',
    name: 'Standing person',
    mount: 'floor',
    width: 0.5,
    depth: 0.3,
    height: 1.75,
    finishes: { shoes: 'black-metal', trousers: 'denim', shirt: 'mid-grey-paint', skin: 'skin', hair: 'walnut-veneer' },
    // Dimensions: DIN 33402-2 and Tilley, The Measure of Man and Woman: stature 1.75 m (men 50th percentile), head 1/7.5 of it, shoulders 50 cm over the deltoids (standingPerson.ts)
    parts: standingPersonParts,
  },
];

const byId = new Map(FURNITURE_LIBRARY.map((item) => [item.id, item]));

/** The library item with this id, or undefined. */
export function findFurnitureItem(id: string): FurnitureItem | undefined {
  return byId.get(id);
}

const meshes = new Map<string, TriangleMesh>();

/**
 * The item's mesh with its default finishes (built once per item and shared: meshes are
 * immutable by convention, like the configuration). Throws for an unknown id.
 */
export function furnitureMesh(id: string): TriangleMesh {
  let mesh = meshes.get(id);
  if (!mesh) {
    const item = byId.get(id);
    if (!item) throw new Error(`unknown furniture item '${id}'`);
    mesh = composeParts(item.parts(), (material) => objectFinishRgb(item.finishes[material]));
    meshes.set(id, mesh);
  }
  return mesh;
}
