/**
 * L3D structure (readL3dStructure.ts): a hand-made track spot — a mount, a swivel joint about
 * the vertical, a tilt joint, a head with a round light-emitting object and the OBJ faces that
 * glow — read into the tree it declares. The structure.xml validates against the official
 * schema (vendor/l3d/l3d.xsd); hostile variants are refused in one line naming file and entry.
 */
import { readFileSync } from 'node:fs';
import { zipSync, type Zippable } from 'fflate';
import { describe, expect, it } from 'vitest';
import { validateXML } from 'xmllint-wasm';
import { GldfError } from '../../../src/core/gldf/GldfError';
import { l3dJoints, readL3dStructure, type L3dGeometryNode } from '../../../src/core/gldf/readL3dStructure';

const encode = (s: string): Uint8Array => new TextEncoder().encode(s);
/** A 2 cm cube in millimetres: 8 vertices, 12 triangles (the OBJ content is not read by the structure reader). */
const CUBE = encode(['v 0 0 0', 'v 20 0 0', 'v 20 20 0', 'v 0 20 0', 'v 0 0 20', 'v 20 0 20', 'v 20 20 20', 'v 0 20 20', 'f 1 2 3', 'f 1 3 4', 'f 5 6 7', 'f 5 7 8', 'f 1 2 6', 'f 1 6 5', 'f 2 3 7', 'f 2 7 6', 'f 3 4 8', 'f 3 8 7', 'f 4 1 5', 'f 4 5 8'].join('\n'));

const STRUCTURE = `<?xml version="1.0" encoding="UTF-8"?>
<Luminaire>
  <Header><Name>Track spot</Name><CreatedWithApplication>luxbox tests</CreatedWithApplication><CreationTimeCode>2026-11-27T08:00:00</CreationTimeCode><FormatVersion major="0" minor="11"/></Header>
  <GeometryDefinitions>
    <GeometryFileDefinition id="adapter" filename="adapter.obj" units="mm"/>
    <GeometryFileDefinition id="yoke" filename="yoke.obj" units="mm"/>
    <GeometryFileDefinition id="head" filename="head.obj" units="cm"/>
  </GeometryDefinitions>
  <Structure>
    <Geometry partName="adapter">
      <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
      <GeometryReference geometryId="adapter"/>
      <Joints>
        <Joint partName="swivel">
          <Position x="0" y="0" z="-0.03"/><Rotation x="0" y="0" z="0"/>
          <ZAxis min="-170" max="170" step="1"/>
          <Geometries>
            <Geometry partName="yoke">
              <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
              <GeometryReference geometryId="yoke"/>
              <Joints>
                <Joint partName="tilt">
                  <Position x="0" y="0" z="-0.06"/><Rotation x="0" y="0" z="0"/>
                  <XAxis min="0" max="90" step="5"/>
                  <DefaultRotation x="30" y="0" z="0"/>
                  <Geometries>
                    <Geometry partName="head" includedInMeasurement="true">
                      <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
                      <GeometryReference geometryId="head"/>
                      <LightEmittingObjects>
                        <LightEmittingObject partName="lens">
                          <Position x="0" y="0" z="-0.045"/><Rotation x="0" y="0" z="0"/>
                          <Circle diameter="0.05"/>
                        </LightEmittingObject>
                      </LightEmittingObjects>
                      <LightEmittingSurfaces>
                        <LightEmittingSurface partName="lens-faces">
                          <LightEmittingObjectReference lightEmittingPartName="lens"/>
                          <FaceAssignments><FaceAssignment faceIndex="0"/><FaceRangeAssignment faceIndexBegin="2" faceIndexEnd="3"/></FaceAssignments>
                        </LightEmittingSurface>
                      </LightEmittingSurfaces>
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

const files = (): Zippable => ({ 'adapter/adapter.obj': CUBE, 'yoke/yoke.obj': CUBE, 'head/head.obj': CUBE });
const l3d = (xml = STRUCTURE, extra: Zippable = {}): Uint8Array => zipSync({ 'structure.xml': encode(xml), ...files(), ...extra });

function refusal(bytes: Uint8Array): string {
  try {
    readL3dStructure(bytes, 'spot.l3d');
  } catch (error) {
    expect(error).toBeInstanceOf(GldfError);
    expect((error as Error).message.split('\n')).toHaveLength(1);
    return (error as Error).message;
  }
  throw new Error('accepted');
}

describe('L3D structure', () => {
  it('the hand-made structure.xml validates against the official L3D schema; a twin without Rotation does not', async () => {
    const schema = { fileName: 'l3d.xsd', contents: readFileSync('vendor/l3d/l3d.xsd', 'utf8') };
    const ok = await validateXML({ xml: [{ fileName: 'structure.xml', contents: STRUCTURE }], schema: [schema] });
    expect(ok.errors.map((e) => e.rawMessage)).toEqual([]);
    const broken = await validateXML({ xml: [{ fileName: 'structure.xml', contents: STRUCTURE.replace('<Position x="0" y="0" z="-0.045"/><Rotation x="0" y="0" z="0"/>', '<Position x="0" y="0" z="-0.045"/>') }], schema: [schema] });
    expect(broken.valid).toBe(false);
  });

  it('reads parts, joints with their axes and limits, and the light-emitting object and faces, as declared', () => {
    const { luminaire } = readL3dStructure(l3d(), 'spot.l3d');
    expect(luminaire.header).toEqual({ name: 'Track spot', createdWithApplication: 'luxbox tests', formatVersion: '0.11' });
    expect([...luminaire.geometryFiles.values()]).toEqual([
      { id: 'adapter', path: 'adapter/adapter.obj', scale: 0.001 },
      { id: 'yoke', path: 'yoke/yoke.obj', scale: 0.001 },
      { id: 'head', path: 'head/head.obj', scale: 0.01 },
    ]);
    const node = (partName: string, geometryId: string, rest: Partial<L3dGeometryNode> = {}): L3dGeometryNode => ({
      partName,
      position: [0, 0, 0],
      rotation: [0, 0, 0],
      geometryId,
      includedInMeasurement: true,
      joints: [],
      lightEmittingObjects: [],
      lightEmittingSurfaces: [],
      ...rest,
    });
    const head = node('head', 'head', {
      lightEmittingObjects: [{ partName: 'lens', position: [0, 0, -0.045], rotation: [0, 0, 0], shape: { kind: 'circle', diameter: 0.05 } }],
      lightEmittingSurfaces: [{ partName: 'lens-faces', objects: [{ partName: 'lens' }], faces: [{ begin: 0, end: 0 }, { begin: 2, end: 3 }] }],
    });
    const tilt = { partName: 'tilt', position: [0, 0, -0.06], rotation: [0, 0, 0], axes: [{ axis: 'x', min: 0, max: 90, step: 5 }], defaultRotation: [30, 0, 0], geometries: [head] };
    const yoke = node('yoke', 'yoke', { joints: [tilt as never] });
    const swivel = { partName: 'swivel', position: [0, 0, -0.03], rotation: [0, 0, 0], axes: [{ axis: 'z', min: -170, max: 170, step: 1 }], geometries: [yoke] };
    expect(luminaire.structure).toEqual([node('adapter', 'adapter', { joints: [swivel as never] })]);
    // The aiming a module type could take from it (docs/gldf.md, "L3D"): rotation about the vertical ±170°, tilt 0–90° in 5° steps.
    expect(l3dJoints(luminaire.structure).map((j) => [j.partName, j.axes])).toEqual([
      ['swivel', [{ axis: 'z', min: -170, max: 170, step: 1 }]],
      ['tilt', [{ axis: 'x', min: 0, max: 90, step: 5 }]],
    ]);
  });

  it('refuses hostile or broken structures in one line naming file, entry and part', () => {
    expect(refusal(l3d(STRUCTURE.replace('partName="yoke"', 'partName="adapter"')))).toBe("spot.l3d: entry 'structure.xml': Geometry 'adapter': duplicate partName");
    expect(refusal(l3d(STRUCTURE.replace('<GeometryReference geometryId="yoke"/>', '<GeometryReference geometryId="arm"/>')))).toBe("spot.l3d: entry 'structure.xml': Geometry 'yoke': geometryId 'arm' names no GeometryFileDefinition");
    expect(refusal(l3d(STRUCTURE.replace('lightEmittingPartName="lens"', 'lightEmittingPartName="bulb"')))).toBe("spot.l3d: entry 'structure.xml': LightEmittingSurface 'lens-faces': lightEmittingPartName 'bulb' names no LightEmittingObject");
    expect(refusal(l3d(STRUCTURE.replace('<XAxis min="0" max="90"', '<XAxis min="95" max="90"')))).toBe("spot.l3d: entry 'structure.xml': Joint 'tilt' XAxis: min 95 exceeds max 90");
    expect(refusal(l3d(STRUCTURE.replace('filename="head.obj"', 'filename="../head.obj"')))).toBe("spot.l3d: entry 'structure.xml': GeometryFileDefinition 'head': filename '../head.obj' climbs out of the container ('..')");
    expect(refusal(l3d(STRUCTURE.replace('units="cm"', 'units="furlong"')))).toMatch(/^spot\.l3d: entry 'structure\.xml': GeometryFileDefinition 'head': units 'furlong' is not one of m, dm/);
    expect(refusal(l3d(STRUCTURE.replace('<Luminaire>', '<!DOCTYPE Luminaire [<!ENTITY a "b">]><Luminaire>')))).toBe("spot.l3d: entry 'structure.xml': has a DTD (<!DOCTYPE); DTDs and entity declarations are refused");
    expect(refusal(l3d(STRUCTURE.replace('<Circle diameter="0.05"/>', '<Circle diameter="1e400"/>')))).toBe("spot.l3d: entry 'structure.xml': LightEmittingObject 'lens' diameter: Infinity is out of range (0 to 1000)");
    const missing = zipSync({ 'structure.xml': encode(STRUCTURE), 'adapter/adapter.obj': CUBE, 'yoke/yoke.obj': CUBE });
    expect(refusal(missing)).toBe("spot.l3d: entry 'structure.xml': GeometryFileDefinition 'head': 'head/head.obj' is not in the container");
  });
});
