/**
 * A hand-made L3D track spot whose parts have real shapes, for the 3D view's tests and the GLDF
 * track spot (docs/gldf.md "L3D in the 3D view"). L3D frame: Z up, metres.
 * - adapter (mm): a box x ±20, y ±17, z −28..0 (the insert point at its top);
 * - joint `swivel` 28 mm below it, about Z, −170..170° in 1° steps;
 * - yoke (mm): a crossbar x ±42, y ±6, z −8..0 and two arms x ±(38..42), z −60..−8;
 * - joint `tilt` 60 mm below the swivel, about X, 0..90° in 5° steps, DefaultRotation 20°
 *   (driven by the aim, so not drawn);
 * - head (cm): a 24-sided cylinder, radius 3.5 cm, z −4..4 cm about the tilt axis; its round
 *   light-emitting object `lens` (Ø 50 mm) on the bottom face, z −40 mm;
 * - joint `flap` on the head's rim (y 35 mm, z −40 mm), about X, 0..90°, DefaultRotation 45°, not
 *   above the lens, so not aimed: a barn door (mm: x ±30, y 0..1, z −40..0) drawn at 45°.
 * So the photometric centre (the lens centre, aimed down) is 128 mm below the insert point.
 */
import { zipSync } from 'fflate';
import { encode } from './buildL3d';

/** An OBJ box from its min and max corners (outward faces counterclockwise), after `first` vertices (OBJ numbers from 1). */
function box(min: number[], max: number[], first: number): { v: string[]; f: string[] } {
  const v: string[] = [];
  for (let i = 0; i < 8; i++) v.push(`v ${i & 1 ? max[0] : min[0]} ${i & 2 ? max[1] : min[1]} ${i & 4 ? max[2] : min[2]}`);
  const q = (a: number, b: number, c: number, d: number): string[] => [`f ${a + first + 1} ${b + first + 1} ${c + first + 1}`, `f ${a + first + 1} ${c + first + 1} ${d + first + 1}`];
  const f = [...q(0, 2, 3, 1), ...q(4, 5, 7, 6), ...q(0, 1, 5, 4), ...q(2, 6, 7, 3), ...q(0, 4, 6, 2), ...q(1, 3, 7, 5)];
  return { v, f };
}

function obj(parts: { v: string[]; f: string[] }[]): Uint8Array {
  return encode([...parts.flatMap((p) => p.v), ...parts.flatMap((p) => p.f)].join('\n'));
}

/** A closed n-sided cylinder about z (radius r, z0..z1), 4n triangles. */
function cylinder(r: number, z0: number, z1: number, n: number): Uint8Array {
  const v: string[] = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n;
    v.push(`v ${r * Math.cos(a)} ${r * Math.sin(a)} ${z0}`, `v ${r * Math.cos(a)} ${r * Math.sin(a)} ${z1}`);
  }
  v.push(`v 0 0 ${z0}`, `v 0 0 ${z1}`);
  const f: string[] = [];
  const bottom = 2 * n + 1;
  const top = 2 * n + 2;
  for (let i = 0; i < n; i++) {
    const a0 = 2 * i + 1;
    const a1 = a0 + 1;
    const b0 = 2 * ((i + 1) % n) + 1;
    const b1 = b0 + 1;
    f.push(`f ${a0} ${b0} ${b1}`, `f ${a0} ${b1} ${a1}`, `f ${bottom} ${b0} ${a0}`, `f ${top} ${a1} ${b1}`);
  }
  return encode([...v, ...f].join('\n'));
}

export const HEAD_SEGMENTS = 24;
/** Metres: where things are in the luxbox frame of the model (origin the lens centre, aimed down). */
export const SPOT = { insert: 0.128, pivot: 0.04, headRadius: 0.035, headHalf: 0.04, lens: 0.05, flapDefault: 45, flapLength: 0.04, flapThickness: 0.001 };

export const SPOT_STRUCTURE = `<?xml version="1.0" encoding="UTF-8"?>
<Luminaire>
  <Header><Name>Track spot</Name><CreatedWithApplication>luxbox tests</CreatedWithApplication><CreationTimeCode>2026-11-27T08:00:00</CreationTimeCode><FormatVersion major="0" minor="11"/></Header>
  <GeometryDefinitions>
    <GeometryFileDefinition id="adapter" filename="adapter.obj" units="mm"/>
    <GeometryFileDefinition id="yoke" filename="yoke.obj" units="mm"/>
    <GeometryFileDefinition id="head" filename="head.obj" units="cm"/>
    <GeometryFileDefinition id="flap" filename="flap.obj" units="mm"/>
  </GeometryDefinitions>
  <Structure>
    <Geometry partName="adapter">
      <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
      <GeometryReference geometryId="adapter"/>
      <Joints>
        <Joint partName="swivel">
          <Position x="0" y="0" z="-0.028"/><Rotation x="0" y="0" z="0"/>
          <ZAxis min="-170" max="170" step="1"/>
          <Geometries>
            <Geometry partName="yoke">
              <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
              <GeometryReference geometryId="yoke"/>
              <Joints>
                <Joint partName="tilt">
                  <Position x="0" y="0" z="-0.06"/><Rotation x="0" y="0" z="0"/>
                  <XAxis min="0" max="90" step="5"/>
                  <DefaultRotation x="20" y="0" z="0"/>
                  <Geometries>
                    <Geometry partName="head" includedInMeasurement="true">
                      <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
                      <GeometryReference geometryId="head"/>
                      <Joints>
                        <Joint partName="flap">
                          <Position x="0" y="0.035" z="-0.04"/><Rotation x="0" y="0" z="0"/>
                          <XAxis min="0" max="90" step="1"/>
                          <DefaultRotation x="45" y="0" z="0"/>
                          <Geometries>
                            <Geometry partName="barn-door">
                              <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
                              <GeometryReference geometryId="flap"/>
                            </Geometry>
                          </Geometries>
                        </Joint>
                      </Joints>
                      <LightEmittingObjects>
                        <LightEmittingObject partName="lens">
                          <Position x="0" y="0" z="-0.04"/><Rotation x="0" y="0" z="0"/>
                          <Circle diameter="0.05"/>
                        </LightEmittingObject>
                      </LightEmittingObjects>
                    </Geometry>
                  </Geometries>
                </Joint>
              </Joints>
            </Geometry>
          </Geometries>
        </Joint>
      </Joints>
    </Geometry>
  </Structure>
</Luminaire>
`;

export function spotL3d(xml = SPOT_STRUCTURE): Uint8Array {
  return zipSync(
    {
      'structure.xml': encode(xml),
      'adapter/adapter.obj': obj([box([-20, -17, -28], [20, 17, 0], 0)]),
      'yoke/yoke.obj': obj([box([-42, -6, -8], [42, 6, 0], 0), box([-42, -6, -60], [-38, 6, -8], 8), box([38, -6, -60], [42, 6, -8], 16)]),
      'head/head.obj': cylinder(3.5, -4, 4, HEAD_SEGMENTS),
      'flap/flap.obj': obj([box([-30, 0, -40], [30, 1, 0], 0)]),
    },
    { mtime: new Date('2026-11-27T08:00:00Z') },
  );
}
