/**
 * LightEmittingSurfaces (docs/gldf.md "Light-emitting surfaces"): the OBJ faces an L3D marks as
 * emitting glow instead of their object's Rectangle, their area is the emitting area the glow
 * divides the flux by, and they are the near field's opening. The hand-made panel
 * (buildL3dPanel.ts): its object is 0.6 × 0.3 m, its emitting faces the housing's 0.62 × 0.32 m
 * bottom (two triangles), worked out by hand from the OBJ; faces on top emit upward and make the
 * opening as tall as the housing (40 mm).
 */
import { zipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { readL3dStructure } from '../../../src/core/gldf/readL3dStructure';
import { readL3dEmittingFaces } from '../../../src/engines/meshImport/readL3dEmittingFaces';
import { l3dLuminaireModel } from '../../../src/engines/view/luminaires/l3dLuminaireModel';
import { l3dOpening } from '../../../src/engines/view/luminaires/l3dOpening';
import { PROUD } from '../../../src/engines/view/luminaires/luminaireDimensions';
import { partArea } from '../../../src/engines/view/luminaires/luminaireModel';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { encode } from '../../core/gldf/buildL3d';
import { panelL3d, panelStructure, type PanelOptions } from '../../core/gldf/buildL3dPanel';

const BOTTOM = 0.62 * 0.32;
const body = (o: PanelOptions) => readL3dBody(panelL3d(o), 'panel.l3d');
const placement = { heading: 0, orientation: { yaw: 0, pitch: 0, roll: 0 }, mount: 0 };

describe('LightEmittingSurfaces', () => {
  it('reads the assigned faces in metres, y up, with their area', () => {
    const { luminaire, zip } = readL3dStructure(panelL3d({ surfaces: true }), 'panel.l3d');
    const [s, ...rest] = readL3dEmittingFaces(luminaire, zip);
    expect(rest).toHaveLength(0);
    expect(s.surface).toBe('diffuser');
    expect(s.part).toBe('housing');
    expect(s.objects).toEqual(['panel']);
    expect(s.positions.length).toBe(2 * 9);
    expect(s.area).toBeCloseTo(BOTTOM, 9);
    for (let i = 0; i < s.positions.length; i += 3) {
      expect(Math.abs(s.positions[i])).toBeCloseTo(0.31, 6);
      expect(s.positions[i + 1]).toBeCloseTo(0, 9);
      expect(Math.abs(s.positions[i + 2])).toBeCloseTo(0.16, 6);
    }
  });

  it('glow instead of the object: one downward emitter of the faces, 0.5 mm proud, with their area', () => {
    const b = body({ surfaces: true });
    expect(b.emitterArea).toEqual({ down: expect.closeTo(BOTTOM, 6), up: 0 });
    const { model } = l3dLuminaireModel(b, placement);
    expect(model.emitterArea).toBeCloseTo(BOTTOM, 6);
    const emitters = model.parts.filter((p) => p.role === 'emitter');
    expect(emitters).toHaveLength(1);
    expect(emitters[0].side).toBe(-1);
    expect(emitters[0].indices.length).toBe(6);
    expect(partArea(model, 'emitter', -1)).toBeCloseTo(BOTTOM, 6);
    for (let i = 1; i < emitters[0].positions.length; i += 3) expect(emitters[0].positions[i]).toBeCloseTo(-PROUD, 6);
    for (let i = 0; i < emitters[0].normals.length; i += 3) expect([emitters[0].normals[i], emitters[0].normals[i + 1], emitters[0].normals[i + 2]]).toEqual([0, -1, 0].map((v) => expect.closeTo(v, 6)));
    // Without surfaces the object's Rectangle glows, with its own area.
    expect(body({}).emitterArea.down).toBeCloseTo(0.18, 12);
  });

  it('are the opening: the faces’ extent in the photometry’s frame, turned with the beam', () => {
    expect(l3dOpening(body({ surfaces: true }), 0)).toEqual({ width: 0.62, length: 0.32, height: 0, shape: 'rectangular' });
    expect(l3dOpening(body({ surfaces: true }), 90)).toEqual({ width: 0.32, length: 0.62, height: 0, shape: 'rectangular' });
    // Bottom and top: both hemispheres glow, and the opening is as tall as the housing.
    const both = body({ surfaces: true, faces: '<FaceRangeAssignment faceIndexBegin="0" faceIndexEnd="3"/>' });
    expect(both.emitterArea).toEqual({ down: expect.closeTo(BOTTOM, 6), up: expect.closeTo(BOTTOM, 6) });
    expect(l3dOpening(both, 0)).toEqual({ width: 0.62, length: 0.32, height: 0.04, shape: 'rectangular' });
    const sides = l3dLuminaireModel(both, placement)
      .model.parts.filter((p) => p.role === 'emitter')
      .map((p) => p.side);
    expect(sides.sort()).toEqual([-1, 1]);
  });

  it('groupIndex counts within the OBJ’s g groups; a face past the file’s is refused in one line', () => {
    const grouped = encode(['v 0 0 0', 'v 100 0 0', 'v 100 100 0', 'v 0 100 0', 'v 0 0 50', 'v 100 0 50', 'v 100 100 50', 'g top', 'f 5 6 7', 'g bottom', 'f 1 4 3', 'f 1 3 2'].join('\n'));
    const xml = panelStructure({ surfaces: true, faces: '<FaceAssignment groupIndex="1" faceIndex="1"/>' });
    const { luminaire, zip } = readL3dStructure(zipSync({ 'structure.xml': encode(xml), 'housing/housing.obj': grouped }), 'g.l3d');
    const [s] = readL3dEmittingFaces(luminaire, zip);
    // Group 1 ('bottom'), its face 1: 'f 1 3 2', the file's third face, half of the 0.1 m square at z = 0.
    expect(s.area).toBeCloseTo(0.005, 9);
    expect([...s.positions].filter((_, i) => i % 3 === 1).every((y) => Math.abs(y) < 1e-9)).toBe(true);
    expect(() => readL3dBody(panelL3d({ surfaces: true, faces: '<FaceRangeAssignment faceIndexBegin="10" faceIndexEnd="12"/>' }), 'panel.l3d')).toThrow(
      "panel.l3d: LightEmittingSurface 'diffuser' (entry 'housing/housing.obj'): face 12 does not exist (12 faces)",
    );
    expect(() => readL3dBody(zipSync({ 'structure.xml': encode(xml), 'housing/housing.obj': grouped }), 'g.l3d')).not.toThrow();
    expect(() => readL3dBody(zipSync({ 'structure.xml': encode(panelStructure({ surfaces: true, faces: '<FaceAssignment groupIndex="2" faceIndex="0"/>' })), 'housing/housing.obj': grouped }), 'g.l3d')).toThrow(
      'face 0 of group 2 does not exist (0 faces of group 2)',
    );
  });
});
