/** The command line's lines about what orienting a model did (issue #35): one per kind of change, none for a clean model. */
import { describe, expect, it } from 'vitest';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import { orientationNotes } from '../../../src/engines/meshImport/orientationNotes';
import { insideOut, mobiusMesh, objText, quadMesh, wedgeMesh } from '../../core/mesh/orientFixtures';
import { modelFile, textFile } from './modelFixtures';

describe('orientationNotes', () => {
  it('an inside-out wedge: one line naming the file, the part and the triangles reversed', async () => {
    const r = await importMesh([textFile('attic.obj', objText(insideOut(wedgeMesh())))]);
    expect(orientationNotes(r.name, r.orientation)).toEqual(['attic.obj: 1 closed part faced inward and was turned outward (8 triangles reversed)']);
  });

  it('an open quad: its back side is named with the triangles added', async () => {
    const r = await importMesh([textFile('sheet.obj', objText(quadMesh()))]);
    expect(orientationNotes(r.name, r.orientation)).toEqual(['sheet.obj: 1 open surface lit and reflecting on both sides (2 back-side triangles added)']);
  });

  it('a Möbius strip (no consistent winding): lit on both sides, said in one line', async () => {
    const r = await importMesh([textFile('strip.obj', objText(mobiusMesh()))]);
    expect(r.orientation).toMatchObject({ parts: 1, undecided: 1, backTriangles: 12 });
    expect(orientationNotes(r.name, r.orientation)).toEqual(['strip.obj: 1 part with no clear inside (faces that cannot be wound alike) lit on both sides']);
  });

  it('the fixture table (five closed boxes wound outward): nothing to say', async () => {
    const r = await importMesh([modelFile('table.obj'), modelFile('table.mtl')]);
    expect(r.orientation).toMatchObject({ parts: 5, closed: 5, turnedOutward: 0 });
    expect(orientationNotes(r.name, r.orientation)).toEqual([]);
  });
});
