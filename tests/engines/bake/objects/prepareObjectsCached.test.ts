import { describe, expect, it } from 'vitest';
import { prepareObjectsCached } from '../../../../src/engines/bake/objects/prepareObjectsCached';
import { prepareObjects } from '../../../../src/engines/bake/objects/prepareObjects';
import type { BakeObject } from '../../../../src/engines/bake/bakeScene';
import { boxMesh } from './objectFixtures';

describe('prepareObjectsCached', () => {
  const objects: BakeObject[] = [{ id: 'a', mesh: boxMesh(0.5, 0.4, 0.3), position: [1, 0, 1], yaw: 20, scale: 1 }];

  it('returns the same preparation for the same list and options, equal to a fresh one', () => {
    const first = prepareObjectsCached(objects, { texelSize: 0.1 });
    expect(prepareObjectsCached(objects, { texelSize: 0.1 })).toBe(first);
    const fresh = prepareObjects(objects, { texelSize: 0.1 });
    expect(Array.from(first.atlas.position)).toEqual(Array.from(fresh.atlas.position));
    expect(Array.from(first.bvh.triangles)).toEqual(Array.from(fresh.bvh.triangles));
  });

  it('prepares again for other options or another list', () => {
    const first = prepareObjectsCached(objects, { texelSize: 0.1 });
    expect(prepareObjectsCached(objects, { texelSize: 0.05 })).not.toBe(first);
    expect(prepareObjectsCached([...objects], { texelSize: 0.1 })).not.toBe(first);
  });
});
