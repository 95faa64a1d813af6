/**
 * A hand-made L3D (structure.xml + OBJ parts) for the tests and the fuzz target: a track spot with
 * a mount, a swivel joint about the vertical, a tilt joint and a head with a round light-emitting
 * object (readL3dStructure.test.ts checks it against vendor/l3d/l3d.xsd).
 */
import { zipSync, type Zippable } from 'fflate';

export const encode = (s: string): Uint8Array => new TextEncoder().encode(s);
/** A 2 cm cube in millimetres: 8 vertices, 12 triangles (the OBJ content is not read by the structure reader). */
export const CUBE = encode(
  ['v 0 0 0', 'v 20 0 0', 'v 20 20 0', 'v 0 20 0', 'v 0 0 20', 'v 20 0 20', 'v 20 20 20', 'v 0 20 20', 'f 1 2 3', 'f 1 3 4', 'f 5 6 7', 'f 5 7 8', 'f 1 2 6', 'f 1 6 5', 'f 2 3 7', 'f 2 7 6', 'f 3 4 8', 'f 3 8 7', 'f 4 1 5', 'f 4 5 8'].join(
    '\n',
  ),
);

export const STRUCTURE = `<?xml version="1.0" encoding="UTF-8"?>
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

export const files = (): Zippable => ({ 'adapter/adapter.obj': CUBE, 'yoke/yoke.obj': CUBE, 'head/head.obj': CUBE });
export const l3d = (xml = STRUCTURE, extra: Zippable = {}): Uint8Array => zipSync({ 'structure.xml': encode(xml), ...files(), ...extra });
