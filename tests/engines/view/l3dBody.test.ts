/**
 * L3D bodies in the 3D view (docs/gldf.md "L3D in the 3D view"): the hand-made track spot of
 * buildL3dSpot.ts posed for aims. Checked against values worked out by hand from its
 * structure.xml (1e-6 m: float32 vertices): the photometric centre (the lens, aimed down) is the
 * model's origin, the parts' bounds, the barn door at its DefaultRotation, the emitter's area
 * (π·d²/4) and the glow's luminance Φ/(π·A); for aims the emitting face's normal is the beam's
 * axis (aimAxis, an independent formula) within 10⁻⁴ rad, the joints within their limits, and
 * aims past a limit stop at it.
 */
import { describe, expect, it } from 'vitest';
import { validateXML } from 'xmllint-wasm';
import { readFileSync } from 'node:fs';
import { readL3dStructure } from '../../../src/core/gldf/readL3dStructure';
import { positionBounds } from '../../../src/core/mesh/triangleMesh';
import { aimAxis, aimedOrientation } from '../../../src/core/model/modules/aim';
import type { ModuleAim } from '../../../src/core/model/configuration/configuration';
import { readL3dMeshes } from '../../../src/engines/meshImport/readL3dMeshes';
import { l3dBody, poseL3dBody, type L3dBody } from '../../../src/engines/view/luminaires/l3dBody';
import { l3dLuminaireModel } from '../../../src/engines/view/luminaires/l3dLuminaireModel';
import { PROUD } from '../../../src/engines/view/luminaires/luminaireDimensions';
import { partArea, type LuminairePart } from '../../../src/engines/view/luminaires/luminaireModel';
import { SPOT, SPOT_STRUCTURE, spotL3d } from '../../core/gldf/buildL3dSpot';

function spotBody(xml?: string): L3dBody {
  const { luminaire, zip } = readL3dStructure(spotL3d(xml), 'spot.l3d');
  return l3dBody(luminaire, readL3dMeshes(luminaire, zip).parts);
}

function expectBounds(b: { min: number[]; max: number[] }, min: number[], max: number[]): void {
  for (let a = 0; a < 3; a++) {
    expect(b.min[a]).toBeCloseTo(min[a], 6);
    expect(b.max[a]).toBeCloseTo(max[a], 6);
  }
}

/** Mean of a part's vertices and its first normal. */
function face(p: LuminairePart): { centre: number[]; normal: number[] } {
  const n = p.positions.length / 3;
  const centre = [0, 1, 2].map((a) => {
    let s = 0;
    for (let i = 0; i < n; i++) s += p.positions[i * 3 + a];
    return s / n;
  });
  return { centre, normal: [p.normals[0], p.normals[1], p.normals[2]] };
}

const DEG = Math.PI / 180;
/** A mount-frame vector turned to the world by the rail's heading (Ry). */
const toWorld = (v: number[], heading: number): number[] => [Math.cos(heading * DEG) * v[0] + Math.sin(heading * DEG) * v[2], v[1], -Math.sin(heading * DEG) * v[0] + Math.cos(heading * DEG) * v[2]];
const angleBetween = (a: number[], b: number[]): number => Math.acos(Math.min(1, (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (Math.hypot(...a) * Math.hypot(...b))));

describe('an L3D track spot as the module’s body', () => {
  const body = spotBody();

  it('the test structure.xml validates against the official L3D schema', async () => {
    const schema = { fileName: 'l3d.xsd', contents: readFileSync('vendor/l3d/l3d.xsd', 'utf8') };
    const result = await validateXML({ xml: [{ fileName: 'structure.xml', contents: SPOT_STRUCTURE }], schema: [schema] });
    expect(result.errors).toEqual([]);
  });

  it('finds the swivel and the tilt above the lens as the aim’s joints, not the barn door beside it', () => {
    expect(body.primary).toBe('lens');
    expect(body.dofs).toEqual([
      { joint: 'swivel', axis: 'z', min: -170, max: 170, vertical: true },
      { joint: 'tilt', axis: 'x', min: 0, max: 90, vertical: false },
    ]);
    // Aimed straight down the swivel and tilt are 0 (the tilt's DefaultRotation 20° is overridden by the aim); the flap keeps its 45°.
    expect(body.reference.get('swivel')![2]).toBeCloseTo(0, 6);
    expect(body.reference.get('tilt')![0]).toBeCloseTo(0, 6);
    expect(body.reference.get('flap')).toEqual([45, 0, 0]);
  });

  it('puts the lens centre, aimed down, at the photometric centre, and every part where structure.xml says', () => {
    expect(body.origin[0]).toBeCloseTo(0, 9);
    expect(body.origin[1]).toBeCloseTo(-SPOT.insert, 9);
    expect(body.origin[2]).toBeCloseTo(0, 9);
    expect(body.top).toBeCloseTo(SPOT.insert, 6);
    const parts = poseL3dBody(body, body.reference).parts;
    const [adapter, yoke, head, flap] = parts.filter((p) => p.role === 'housing').map((p) => positionBounds(p.positions));
    // L3D (x, y, z) → luxbox (x, z, −y), then less the origin (0, −0.128, 0).
    expectBounds(adapter, [-0.02, 0.1, -0.017], [0.02, 0.128, 0.017]);
    expectBounds(yoke, [-0.042, 0.04, -0.006], [0.042, 0.1, 0.006]);
    // The 24-gon has vertices at 0°, 90°, 180°, 270°: its extent is the radius both ways.
    expectBounds(head, [-SPOT.headRadius, 0, -SPOT.headRadius], [SPOT.headRadius, 2 * SPOT.headHalf, SPOT.headRadius]);
    // The barn door hinged on the rim (luxbox z −0.035, y 0) at its DefaultRotation of 45° about x: (y, z) → (y cos − z sin, y sin + z cos).
    const c = Math.cos(45 * DEG);
    expectBounds(flap, [-0.03, -SPOT.flapLength * c, -(0.035 + (SPOT.flapThickness + SPOT.flapLength) * c)], [0.03, SPOT.flapThickness * c, -0.035]);
  });

  it('draws the lens as the glowing face at the photometric centre, with the lens’s area, and glows at Φ/(π·A)', () => {
    const { model } = l3dLuminaireModel(body, { heading: 0, orientation: { yaw: 0, pitch: 0, roll: 0 }, mount: 0 });
    const emitters = model.parts.filter((p) => p.role === 'emitter');
    expect(emitters).toHaveLength(1);
    const { centre, normal } = face(emitters[0]);
    // 0.5 mm proud of the lens plane, down its normal.
    expect(centre[0]).toBeCloseTo(0, 6);
    expect(centre[1]).toBeCloseTo(-PROUD, 6);
    expect(centre[2]).toBeCloseTo(0, 6);
    expect(normal).toEqual([0, -1, 0].map((v) => expect.closeTo(v, 6)));
    const area = (Math.PI * SPOT.lens ** 2) / 4;
    expect(body.emitterArea).toEqual({ down: area, up: 0 });
    expect(partArea(model, 'emitter') / area).toBeCloseTo(1, 6);
    expect(model.emitterArea).toBe(area);
  });

  const aims: { heading: number; aim: ModuleAim; swivel: number }[] = [
    // yaw = heading + rotation − 90 (aimedOrientation), so the swivel is rotation − 90 (wrapped into ±180).
    { heading: 30, aim: { rotation: 40, tilt: 30 }, swivel: -50 },
    { heading: 0, aim: { rotation: 200, tilt: 75 }, swivel: 110 },
    { heading: 90, aim: { rotation: 300, tilt: 45 }, swivel: -150 },
    { heading: 0, aim: { rotation: 120, tilt: 90 }, swivel: 30 },
  ];
  for (const { heading, aim, swivel } of aims) {
    it(`turns the head with the beam: rail at ${heading}°, rotation ${aim.rotation}°, tilt ${aim.tilt}°`, () => {
      const { model, angles } = l3dLuminaireModel(body, { heading, orientation: aimedOrientation(heading, 0, aim), mount: 0.2 });
      expect(angles.get('tilt')![0]).toBeCloseTo(aim.tilt, 3);
      expect(angles.get('swivel')![2]).toBeCloseTo(swivel, 3);
      expect(angles.get('flap')).toEqual([45, 0, 0]);
      const lens = face(model.parts.find((p) => p.role === 'emitter')!);
      expect(angleBetween(toWorld(lens.normal, heading), aimAxis(heading, aim))).toBeLessThan(1e-4);
      // The head turns about its pivot (40 mm above the lens): the lens stays 40.5 mm from it.
      expect(Math.hypot(lens.centre[0], lens.centre[1] - SPOT.pivot, lens.centre[2])).toBeCloseTo(SPOT.pivot + PROUD, 6);
      // The adapter and a stem up to the rail 0.2 m above the photometric centre.
      expect(Math.max(...model.parts.map((p) => positionBounds(p.positions).max[1]))).toBeCloseTo(0.2 + 0.028, 6);
    });
  }

  it('stops at a joint’s limit: a tilt of 120° at 90°, a swivel wanting 175° at 170°', () => {
    const steep = l3dLuminaireModel(body, { heading: 0, orientation: { yaw: 0, pitch: 120, roll: 0 }, mount: 0 }).angles;
    expect(steep.get('tilt')![0]).toBeCloseTo(90, 6);
    const past = l3dLuminaireModel(body, { heading: 0, orientation: aimedOrientation(0, 0, { rotation: 265, tilt: 30 }), mount: 0 }).angles;
    expect(past.get('swivel')![2]).toBeCloseTo(170, 6);
    expect(past.get('tilt')![0]).toBeGreaterThanOrEqual(0);
    expect(past.get('tilt')![0]).toBeLessThanOrEqual(90);
  });

  it('a second light-emitting object facing up (an uplight on the adapter) emits the upper hemisphere with its own area', () => {
    const uplight = '<LightEmittingObjects><LightEmittingObject partName="uplight"><Position x="0" y="0" z="0"/><Rotation x="180" y="0" z="0"/><Rectangle sizeX="0.03" sizeY="0.02"/></LightEmittingObject></LightEmittingObjects>';
    const xml = SPOT_STRUCTURE.replace('      </Joints>\n    </Geometry>\n  </Structure>', `      </Joints>\n      ${uplight}\n    </Geometry>\n  </Structure>`);
    expect(xml).not.toBe(SPOT_STRUCTURE);
    const both = spotBody(xml);
    const lens = (Math.PI * SPOT.lens ** 2) / 4;
    // The lens is still the photometric centre: the uplight comes first (depth first) but faces up.
    expect(both.primary).toBe('lens');
    expect(both.origin[1]).toBeCloseTo(-SPOT.insert, 9);
    expect(both.emitterArea.down).toBeCloseTo(lens, 12);
    expect(both.emitterArea.up).toBeCloseTo(0.03 * 0.02, 12);
    const { model } = l3dLuminaireModel(both, { heading: 0, orientation: { yaw: 0, pitch: 0, roll: 0 }, mount: 0 });
    expect(model.emitterArea).toBeCloseTo(lens, 12);
    expect(model.emitterAreaUp).toBeCloseTo(0.0006, 12);
    const up = model.parts.filter((p) => p.role === 'emitter' && p.side === 1);
    expect(up).toHaveLength(1);
    expect(face(up[0]).normal).toEqual([0, 1, 0].map((v) => expect.closeTo(v, 6)));
    expect(partArea(model, 'emitter', 1)).toBeCloseTo(0.0006, 9);
  });
});
