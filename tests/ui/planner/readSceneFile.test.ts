import { describe, expect, it } from 'vitest';
import { serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../../src/core/model/files/sceneFileError';
import { MAX_SCENE_FILE_BYTES, readSceneFile } from '../../../src/ui/planner/readSceneFile';
import { sceneFileName } from '../../../src/ui/planner/sceneFileName';
import { catalog, withPreset } from '../../core/model/helpers';

const named = (name: string, text: string) => new File([text], name, { type: 'application/json' });

describe('readSceneFile', () => {
  const config = withPreset('snake', 1, 4);

  it('reads back exactly what was saved', async () => {
    await expect(readSceneFile(named('a.luxbox.json', serializeConfiguration(config, catalog)), catalog)).resolves.toEqual(config);
  });

  it('names the file and the problem for corrupt and foreign files', async () => {
    const text = serializeConfiguration(config, catalog);
    await expect(readSceneFile(named('cut.json', text.slice(0, text.length / 2)), catalog)).rejects.toThrow(/^“cut\.json” is not valid JSON/);
    await expect(readSceneFile(named('pkg.json', '{"name":"x","version":"1.0.0"}'), catalog)).rejects.toThrow(/^“pkg\.json” is not a luxbox configuration \(format must be 'luxbox-configuration'\)/);
    await expect(readSceneFile(named('x.json', '[]'), catalog)).rejects.toBeInstanceOf(SceneFileError);
  });

  it('refuses files over the size limit before reading them', async () => {
    let read = false;
    const big = { name: 'film.mp4', size: MAX_SCENE_FILE_BYTES + 1, text: async () => ((read = true), '') };
    await expect(readSceneFile(big, catalog)).rejects.toThrow(/^“film\.mp4” is too large .*\(1\.0 MB; at most 1 MB\)/);
    expect(read).toBe(false);
    // Exactly at the limit is still read (and then judged on its content).
    const edge = { name: 'edge.json', size: MAX_SCENE_FILE_BYTES, text: async () => serializeConfiguration(config, catalog) };
    await expect(readSceneFile(edge, catalog)).resolves.toEqual(config);
  });

  it('reports a failed read as a SceneFileError naming the file', async () => {
    const broken = { name: 'gone.json', size: 10, text: () => Promise.reject(new Error('NotReadableError')) };
    await expect(readSceneFile(broken, catalog)).rejects.toThrow(/^“gone\.json” could not be read \(NotReadableError\)$/);
  });
});

describe('sceneFileName', () => {
  it('carries the room size in metres', () => {
    expect(sceneFileName(withPreset('snake', 1, 4))).toBe('luxbox-8x6x3.luxbox.json');
    expect(sceneFileName(withPreset('single', 1, 1, 0, { width: 5, depth: 4, height: 2.8 }))).toBe('luxbox-5x4x2.8.luxbox.json');
  });
});
