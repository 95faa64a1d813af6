import type { FixtureModule } from '../view/fixtures';
import { aimJoints, mountFrameAxis, poseL3dBody } from '../view/luminaires/l3dBody';
import { num, toRadiance } from './radianceFrame';

/**
 * The luminaires' L3D bodies (catalog `model`, docs/gldf.md "L3D in the 3D view") as Radiance
 * polygons, posed as the 3D view poses them (the joints turned with the aim) and placed at each
 * module (T(centre)·Ry(heading)), one triangle a polygon, in one grey `plastic` with the view's
 * housing reflectance (ρ 0.06, a dark matte powder coat; assumed, no specular part). The body's
 * light-emitting objects are not drawn: the point sources of luminairesRad stand there. A housing
 * face that lies in a light-emitting object's plane and faces with it (the face the lens is set
 * in: |distance| ≤ 1.5 mm, normals within 8°) is left out, so the 1 mm source spheres at the
 * photometric centre are not half buried in it; that is the opening, plus any rim of that face.
 */
export const BODY_REFLECTANCE = 0.06;
const PLANE_TOLERANCE = 0.0015;

export function bodiesRad(modules: readonly FixtureModule[]): string {
  const out: string[] = [];
  let polygons = 0;
  for (const m of modules) {
    if (!m.body) continue;
    const parts = poseL3dBody(m.body, aimJoints(m.body, mountFrameAxis(m), m.orientation.yaw - m.heading)).parts;
    const planes = parts
      .filter((p) => p.role === 'emitter')
      .map((p) => {
        const n = p.positions.length / 3;
        const c = [0, 1, 2].map((a) => {
          let s = 0;
          for (let i = 0; i < n; i++) s += p.positions[i * 3 + a];
          return s / n;
        });
        return { centre: c, normal: [p.normals[0], p.normals[1], p.normals[2]] };
      });
    const h = (m.heading * Math.PI) / 180;
    const [cos, sin] = [Math.cos(h), Math.sin(h)];
    // Mount frame to world (luxbox): Ry(heading), then the centre.
    const world = (x: number, y: number, z: number): [number, number, number] => [m.centre[0] + cos * x + sin * z, m.centre[1] + y, m.centre[2] - sin * x + cos * z];
    let index = 0;
    for (const p of parts) {
      if (p.role !== 'housing') continue;
      const v = p.positions;
      for (let t = 0; t < p.indices.length; t += 3) {
        const tri = [0, 1, 2].map((k) => p.indices[t + k] * 3).map((i) => [v[i], v[i + 1], v[i + 2]]);
        const normal = [p.normals[p.indices[t] * 3], p.normals[p.indices[t] * 3 + 1], p.normals[p.indices[t] * 3 + 2]];
        const inOpening = planes.some(
          (pl) =>
            normal[0] * pl.normal[0] + normal[1] * pl.normal[1] + normal[2] * pl.normal[2] > 0.99 &&
            tri.every((q) => Math.abs((q[0] - pl.centre[0]) * pl.normal[0] + (q[1] - pl.centre[1]) * pl.normal[1] + (q[2] - pl.centre[2]) * pl.normal[2]) <= PLANE_TOLERANCE),
        );
        if (inOpening) continue;
        const name = `${m.id.replace(/[^\w-]/g, '_')}_body_${index++}`;
        out.push(
          `luminaire_body polygon ${name}`,
          '0',
          '0',
          '9',
          ...tri.map(
            (q) =>
              `\t${toRadiance(world(q[0], q[1], q[2]))
                .map(num)
                .join(' ')}`,
          ),
        );
        polygons++;
      }
    }
  }
  if (polygons === 0) return '';
  return [`# Luminaire bodies from L3D: ${polygons} polygons`, '', 'void plastic luminaire_body', '0', '0', `5 ${BODY_REFLECTANCE} ${BODY_REFLECTANCE} ${BODY_REFLECTANCE} 0 0`, '', ...out, ''].join('\n');
}
