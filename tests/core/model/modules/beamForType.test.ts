/** Issue #27, "choices that stick": a module's beam survives a type change, or the nearest beam angle is taken. */
import { describe, expect, it } from 'vitest';
import { beamForType } from '../../../../src/core/model/modules/beamForType';
import { findModuleType } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { catalog, only, powered, run, withPreset } from '../helpers';

const type = (id: string) => findModuleType(catalog, id);

describe('beamForType', () => {
  it('keeps the beam the new type offers under the same id (Spot 30° → warm-dim 30°)', () => {
    expect(beamForType(type('spot'), 'medium', type('spot-warmdim'))).toBe('medium');
    expect(beamForType(type('spot-warmdim'), 'narrow', type('spot'))).toBe('narrow');
  });
  it('takes the nearest beam angle otherwise (30° → 48° flood, 12° → 48°), the narrower on a tie', () => {
    expect(beamForType(type('spot'), 'medium', type('flood'))).toBe('flood48');
    expect(beamForType(type('flood'), 'flood55', type('spot'))).toBe('medium');
    const twin = {
      ...type('flood'),
      beams: [
        { ...type('flood').beams[0], id: 'a', beamAngle: 20 },
        { ...type('flood').beams[0], id: 'b', beamAngle: 40 },
      ],
    };
    expect(beamForType(type('spot'), 'medium', twin)).toBe('a');
  });
  it('falls back to the default where angles cannot be compared (diffuser, washer)', () => {
    expect(beamForType(type('linear'), 'diffuse', type('spot'))).toBe('narrow');
    expect(beamForType(type('spot'), 'medium', type('washer'))).toBe('left');
    expect(beamForType(undefined, 'medium', type('flood'))).toBe('flood48');
  });
});

describe('setModuleType keeps the beam', () => {
  it('a 30° spot switched to the warm-dim spot stays 30°; switched to a flood it becomes the 48° flood', () => {
    const s = powered(withPreset('single', 1, 1));
    const rail = only(s).rails[0];
    const m = rail.modules[0].id;
    const medium = run(s, 'setModuleBeam', { moduleId: m, beam: 'medium' });
    expect(only(run(medium, 'setModuleType', { moduleId: m, type: 'spot-warmdim' })).rails[0].modules[0].beam).toBe('medium');
    expect(only(run(medium, 'setModuleType', { moduleId: m, type: 'flood' })).rails[0].modules[0].beam).toBe('flood48');
  });
});
