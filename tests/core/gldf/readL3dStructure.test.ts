/**
 * L3D structure (readL3dStructure.ts): a hand-made track spot — a mount, a swivel joint about
 * the vertical, a tilt joint, a head with a round light-emitting object and the OBJ faces that
 * glow — read into the tree it declares. The structure.xml validates against the official
 * schema (vendor/l3d/l3d.xsd); hostile variants are refused in one line naming file and entry.
 */
import { readFileSync } from 'node:fs';
import { zipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { validateXML } from 'xmllint-wasm';
import { GldfError } from '../../../src/core/gldf/GldfError';
import { l3dJoints, readL3dStructure, type L3dGeometryNode } from '../../../src/core/gldf/readL3dStructure';
import { CUBE, encode, l3d, STRUCTURE } from './buildL3d';

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
      lightEmittingSurfaces: [
        {
          partName: 'lens-faces',
          objects: [{ partName: 'lens' }],
          faces: [
            { begin: 0, end: 0 },
            { begin: 2, end: 3 },
          ],
        },
      ],
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
    expect(refusal(l3d(STRUCTURE.replace('lightEmittingPartName="lens"', 'lightEmittingPartName="bulb"')))).toBe(
      "spot.l3d: entry 'structure.xml': LightEmittingSurface 'lens-faces': lightEmittingPartName 'bulb' names no LightEmittingObject",
    );
    expect(refusal(l3d(STRUCTURE.replace('<XAxis min="0" max="90"', '<XAxis min="95" max="90"')))).toBe("spot.l3d: entry 'structure.xml': Joint 'tilt' XAxis: min 95 exceeds max 90");
    expect(refusal(l3d(STRUCTURE.replace('filename="head.obj"', 'filename="../head.obj"')))).toBe("spot.l3d: entry 'structure.xml': GeometryFileDefinition 'head': filename '../head.obj' climbs out of the container ('..')");
    expect(refusal(l3d(STRUCTURE.replace('units="cm"', 'units="furlong"')))).toMatch(/^spot\.l3d: entry 'structure\.xml': GeometryFileDefinition 'head': units 'furlong' is not one of m, dm/);
    expect(refusal(l3d(STRUCTURE.replace('<Luminaire>', '<!DOCTYPE Luminaire [<!ENTITY a "b">]><Luminaire>')))).toBe("spot.l3d: entry 'structure.xml': has a DTD (<!DOCTYPE); DTDs and entity declarations are refused");
    expect(refusal(l3d(STRUCTURE.replace('<Circle diameter="0.05"/>', '<Circle diameter="1e400"/>')))).toBe("spot.l3d: entry 'structure.xml': LightEmittingObject 'lens' diameter: Infinity is out of range (0 to 1000)");
    const missing = zipSync({ 'structure.xml': encode(STRUCTURE), 'adapter/adapter.obj': CUBE, 'yoke/yoke.obj': CUBE });
    expect(refusal(missing)).toBe("spot.l3d: entry 'structure.xml': GeometryFileDefinition 'head': 'head/head.obj' is not in the container");
  });
});
