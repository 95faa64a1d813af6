/**
 * A hand-made L3D panel luminaire for the near-field and glow tests (docs/gldf.md "The L3D's
 * opening in the near field"). L3D frame: Z up, metres.
 * - housing (mm): a box x ±310, y ±160, z 0..40 (the insert point on its bottom's centre); its OBJ
 *   faces 0 and 1 are the two triangles of the bottom (z = 0), faces 2 and 3 the top;
 * - light-emitting object `panel` on the bottom, z = 0: a Rectangle sizeX × sizeY (default 0.6 ×
 *   0.3 m), turned about z by `turn` degrees;
 * - with `surfaces`, a LightEmittingSurface `diffuser` assigning the bottom's faces 0–1 to `panel`
 *   (or the `faces` given), so the glowing area is the housing's bottom, 0.62 × 0.32 m, not the
 *   object's 0.6 × 0.3 m.
 */
import { zipSync } from 'fflate';
import { encode } from './buildL3d';

export interface PanelOptions {
  sizeX?: number;
  sizeY?: number;
  /** Rotation of the object about its z (degrees). */
  turn?: number;
  /** Give the housing's bottom faces as a LightEmittingSurface. */
  surfaces?: boolean;
  /** The surface's FaceAssignments content instead of the bottom's range 0–1. */
  faces?: string;
  /** The housing OBJ instead of the box. */
  housing?: Uint8Array;
  /** The object's name. */
  name?: string;
}

export const HOUSING = encode(
  [
    'v -310 -160 0',
    'v 310 -160 0',
    'v 310 160 0',
    'v -310 160 0',
    'v -310 -160 40',
    'v 310 -160 40',
    'v 310 160 40',
    'v -310 160 40',
    // Bottom (seen from below counterclockwise), top, then the four sides.
    'f 1 4 3',
    'f 1 3 2',
    'f 5 6 7',
    'f 5 7 8',
    'f 1 2 6',
    'f 1 6 5',
    'f 2 3 7',
    'f 2 7 6',
    'f 3 4 8',
    'f 3 8 7',
    'f 4 1 5',
    'f 4 5 8',
  ].join('\n'),
);

export function panelStructure(o: PanelOptions = {}): string {
  const name = o.name ?? 'panel';
  const surfaces = o.surfaces
    ? `
      <LightEmittingSurfaces>
        <LightEmittingSurface partName="diffuser">
          <LightEmittingObjectReference lightEmittingPartName="${name}"/>
          <FaceAssignments>${o.faces ?? '<FaceRangeAssignment faceIndexBegin="0" faceIndexEnd="1"/>'}</FaceAssignments>
        </LightEmittingSurface>
      </LightEmittingSurfaces>`
    : '';
  return `<?xml version="1.0" encoding="UTF-8"?>
<Luminaire>
  <Header><Name>Panel</Name><CreatedWithApplication>luxbox tests</CreatedWithApplication><CreationTimeCode>2026-11-27T08:00:00</CreationTimeCode><FormatVersion major="0" minor="11"/></Header>
  <GeometryDefinitions>
    <GeometryFileDefinition id="housing" filename="housing.obj" units="mm"/>
  </GeometryDefinitions>
  <Structure>
    <Geometry partName="housing">
      <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>
      <GeometryReference geometryId="housing"/>
      <LightEmittingObjects>
        <LightEmittingObject partName="${name}">
          <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="${o.turn ?? 0}"/>
          <Rectangle sizeX="${o.sizeX ?? 0.6}" sizeY="${o.sizeY ?? 0.3}"/>
        </LightEmittingObject>
      </LightEmittingObjects>${surfaces}
    </Geometry>
  </Structure>
</Luminaire>
`;
}

export function panelL3d(o: PanelOptions = {}): Uint8Array {
  return zipSync({ 'structure.xml': encode(panelStructure(o)), 'housing/housing.obj': o.housing ?? HOUSING }, { mtime: new Date('2026-11-27T08:00:00Z') });
}
