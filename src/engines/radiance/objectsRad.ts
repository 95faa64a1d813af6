import { placedPositions } from '../../core/mesh/placeMesh';
import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { toRgb, type BakeObject } from '../bake/bakeScene';
import { num, toRadiance, vecText } from './radianceFrame';

/**
 * The scene's objects (furniture, imported models) as Radiance polygons, one per triangle, each
 * with a Lambertian `plastic` per material (the object's `reflectance` when it overrides them,
 * as the baker does). A triangle keeps its vertex order: a mesh lists it counterclockwise seen
 * from its lit side (core/mesh/triangleMesh.ts), Radiance takes a polygon's front from the same
 * right-hand rule, and the frame change (radianceFrame.ts) is a proper rotation, so the front
 * stays the front, which matters to `rpict -bv-`. Degenerate triangles (zero area) are left out:
 * Radiance refuses them ("degenerate polygon").
 */
export function objectsRad(objects: readonly BakeObject[]): { rad: string; triangles: number } {
  const out: string[] = [`# Objects: ${objects.length}, one Lambertian polygon per triangle`];
  let triangles = 0;
  objects.forEach((object, o) => {
    const { mesh } = object;
    const world = placedPositions(mesh, object);
    const prefix = `object${o}`;
    out.push('', `# object ${o}: ${object.id}`);
    mesh.materials.forEach((material, m) => {
      const rho: Rgb = object.reflectance !== undefined ? toRgb(object.reflectance) : material.reflectance;
      out.push('', `void plastic ${prefix}_m${m}`, '0', '0', `5 ${rho.map(num).join(' ')} 0 0`);
    });
    const vertex = (i: number): Vec3 => toRadiance([world[3 * i], world[3 * i + 1], world[3 * i + 2]]);
    for (let t = 0; t < mesh.indices.length / 3; t++) {
      const corners = [vertex(mesh.indices[3 * t]), vertex(mesh.indices[3 * t + 1]), vertex(mesh.indices[3 * t + 2])];
      if (doubleArea(corners) < 1e-12) continue;
      out.push(`${prefix}_m${mesh.materialOfTriangle[t]} polygon ${prefix}_t${t}`, '0', '0', '9', ...corners.map((v) => `\t${vecText(v)}`));
      triangles++;
    }
  });
  return { rad: out.join('\n') + '\n', triangles };
}

function doubleArea([a, b, c]: Vec3[]): number {
  const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  return Math.hypot(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]);
}
