import type { Rgb, SurfaceName, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { toRgb, type BakeScene } from '../bake/bakeScene';
import { num, toRadiance, vecText } from './radianceFrame';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { roomSurfaces, type Point3 } from '../../core/room/roomSurfaces';
import { wallQuads } from '../../core/room/roomTriangles';

/** The six surfaces in luxbox's world: four corners and the normal pointing into the room. */
function surfaceQuads(room: { width: number; height: number; depth: number }): { name: SurfaceName; corners: Vec3[]; inward: Vec3 }[] {
  const { width: W, height: H, depth: D } = room;
  return [
    {
      name: 'floor',
      corners: [
        [0, 0, 0],
        [W, 0, 0],
        [W, 0, D],
        [0, 0, D],
      ],
      inward: [0, 1, 0],
    },
    {
      name: 'ceiling',
      corners: [
        [0, H, 0],
        [W, H, 0],
        [W, H, D],
        [0, H, D],
      ],
      inward: [0, -1, 0],
    },
    {
      name: 'north',
      corners: [
        [0, 0, 0],
        [W, 0, 0],
        [W, H, 0],
        [0, H, 0],
      ],
      inward: [0, 0, 1],
    },
    {
      name: 'south',
      corners: [
        [0, 0, D],
        [W, 0, D],
        [W, H, D],
        [0, H, D],
      ],
      inward: [0, 0, -1],
    },
    {
      name: 'west',
      corners: [
        [0, 0, 0],
        [0, 0, D],
        [0, H, D],
        [0, H, 0],
      ],
      inward: [1, 0, 0],
    },
    {
      name: 'east',
      corners: [
        [W, 0, 0],
        [W, 0, D],
        [W, H, D],
        [W, H, 0],
      ],
      inward: [-1, 0, 0],
    },
  ];
}

/**
 * Radiance orders a polygon's vertices counterclockwise seen from the side its normal points to
 * (right-hand rule). Each surface faces into the room, so a ray from inside sees its front.
 */
function inwardOrder(corners: Vec3[], inward: Vec3): Vec3[] {
  const [a, b, c] = corners;
  const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const e2 = [c[0] - b[0], c[1] - b[1], c[2] - b[2]];
  const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
  const facing = n[0] * inward[0] + n[1] * inward[1] + n[2] * inward[2];
  return facing > 0 ? corners : [...corners].reverse();
}

/**
 * The room as six Lambertian polygons: Radiance `plastic` with no specular part reflects
 * ρ·E/π, the grey (or RGB) Lambertian surface luxbox bakes.
 */
export function roomRad(scene: BakeScene): string {
  // A room of any shape (lighting scene version 3) travels on the lighting scene's room object.
  const shape = (scene.room as { shape?: ShapedRoom }).shape;
  if (shape) return shapedRoomRad(shape);
  const out: string[] = ['# Room: six Lambertian surfaces, normals into the room'];
  for (const { name, corners, inward } of surfaceQuads(scene.room)) {
    const rho: Rgb = toRgb(scene.room.reflectance[name]);
    const vertices = inwardOrder(corners, inward).map(toRadiance);
    out.push('', `void plastic ${name}_material`, '0', '0', `5 ${rho.map(num).join(' ')} 0 0`, '', `${name}_material polygon ${name}`, '0', '0', `12`, ...vertices.map((v) => `\t${vecText(v)}`));
  }
  return out.join('\n') + '\n';
}

/** Twice a planar polygon's area vector (Newell): its length is twice the area, its direction the right-hand normal. */
function areaVector(poly: readonly Point3[]): Vec3 {
  const n: Vec3 = [0, 0, 0];
  for (let i = 0; i < poly.length; i++) {
    const a = poly[i];
    const b = poly[(i + 1) % poly.length];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

/**
 * A room of any shape (issue 29) as Radiance polygons, one material per surface of roomSurfaces
 * (floor, ceiling, slope_i, wall_i; i as the author numbered them) with its own reflectance. The
 * floor, ceiling and slope parts are their polygons as they are (Radiance polygons may be
 * concave); a wall with openings is its pieces around them (wallQuads: strips between the
 * openings' sides), so an opening is a hole in the file too, through which light leaves the
 * room as it does in luxbox until daylight exists. Every polygon wound so its right-hand normal
 * points into the room.
 */
function shapedRoomRad(room: ShapedRoom): string {
  const out: string[] = ['# Room of any shape: Lambertian polygons per surface, normals into the room; openings left as holes'];
  for (const s of roomSurfaces(room)) {
    const name = s.id.replace('-', '_');
    const pieces: Point3[][] = s.kind === 'wall' && s.openings.length > 0 ? wallQuads(room, s) : s.polygons;
    out.push('', `void plastic ${name}_material`, '0', '0', `5 ${s.reflectance.map(num).join(' ')} 0 0`);
    pieces.forEach((piece, k) => {
      const n = areaVector(piece);
      if (Math.hypot(...n) < 1e-12) return; // an opening's head at the wall's top leaves no piece above it
      const inward = n[0] * s.inward[0] + n[1] * s.inward[1] + n[2] * s.inward[2] > 0 ? piece : [...piece].reverse();
      out.push('', `${name}_material polygon ${name}_${k}`, '0', '0', `${3 * inward.length}`, ...inward.map((v) => `\t${vecText(toRadiance(v))}`));
    });
  }
  return out.join('\n') + '\n';
}
