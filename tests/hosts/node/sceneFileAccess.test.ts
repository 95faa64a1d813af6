/**
 * Issue 32, "Files": the CLI read `/dev/zero` forever when a scene named it as photometry, as a
 * glTF buffer URI or as an OBJ `mtllib` (a character device reports size 0, so size checks from
 * stat passed). Now only regular files are read, the size cap holds while reading, and a scene
 * given on the command line may name files only in its own folder, luxbox's public folder or a folder given with --allow
 * (docs/scene-format.md, "Which files a scene may name"). Each refusal is one line naming the
 * file and the reason, and comes at once.
 */
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, truncateSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { delimiter, join, resolve } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { MAX_PHOTOMETRY_BYTES } from '../../../src/core/photometry/limits';
import { cliReadableFolders } from '../../../src/hosts/node/cliReadableFolders';
import { MAX_MODEL_FILE_BYTES } from '../../../src/hosts/node/createNodeMeshLoader';
import { loadLightingSceneFile, loadLightingSceneFileAsync } from '../../../src/hosts/node/loadLightingSceneFile';
import { readRegularFile } from '../../../src/hosts/node/readRegularFile';

const IES = resolve('public/ies/bega_50975_downlight_lm1995_crlf.ies');
const MODELS = resolve('tests/fixtures/models');

let root = '';
let folder = '';

beforeAll(() => {
  root = mkdtempSync(join(tmpdir(), 'luxbox-files-'));
  folder = join(root, 'scene');
  mkdirSync(folder);
  copyFileSync(IES, join(folder, 'lamp.ies'));
  symlinkSync('/dev/zero', join(folder, 'zero-link'));
  execFileSync('mkfifo', [join(folder, 'pipe')]);
  mkdirSync(join(folder, 'folder'));
  // Sparse files: their size is what counts, no disk is used.
  writeFileSync(join(folder, 'huge.ies'), '');
  truncateSync(join(folder, 'huge.ies'), MAX_PHOTOMETRY_BYTES + 1);
  writeFileSync(join(folder, 'huge.bin'), '');
  truncateSync(join(folder, 'huge.bin'), MAX_MODEL_FILE_BYTES + 1);
  copyFileSync(IES, join(root, 'outside.ies'));
});

afterAll(() => rmSync(root, { recursive: true, force: true }));

/** What each special name is, and the reason its refusal must give. */
const SPECIALS: [name: string, reason: RegExp][] = [
  ['/dev/zero', /\/dev\/zero is outside the scene's folder \(give more with --allow\)/],
  ['zero-link', /\/dev\/zero is outside the scene's folder \(give more with --allow\)/],
  ['pipe', /a named pipe, not a regular file/],
  ['folder', /a directory, not a regular file/],
  ['../outside.ies', /luxbox-files-\w+\/outside\.ies is outside the scene's folder \(give more with --allow\)\)$/],
];

function writeScene(name: string, extra: object): string {
  const path = join(folder, `${name}.json`);
  const luminaires = [{ photometry: 'lamp.ies', position: [1, 2.4, 1] }];
  writeFileSync(path, JSON.stringify({ version: 2, room: { width: 3, height: 2.5, depth: 3, reflectance: { floor: 0.3, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } }, luminaires, ...extra }));
  return path;
}

/** The one-line refusal of loading a scene as the CLI does, and how long it took. */
async function refusal(scene: string): Promise<{ message: string; ms: number }> {
  const start = performance.now();
  try {
    await loadLightingSceneFileAsync(scene, { within: cliReadableFolders(scene) });
  } catch (error) {
    return { message: (error as Error).message, ms: performance.now() - start };
  }
  throw new Error(`${scene} was accepted`);
}

function expectOneLine(message: string, names: string, reason: RegExp) {
  expect(message).not.toMatch(/[\r\n]/);
  expect(message.length).toBeLessThan(200); // oneLine cuts at 200: the whole reason must fit
  expect(message).toContain(names);
  expect(message).toMatch(reason);
}

describe('a scene names a file that is not a regular file, too large, or outside its folder', () => {
  it.each([...SPECIALS, ['huge.ies', /file is too large/] as [string, RegExp]])(
    'photometry %s: refused at once, naming it',
    async (name, reason) => {
      const scene = writeScene('photometry', { luminaires: [{ photometry: name, position: [1, 2.4, 1] }] });
      const { message, ms } = await refusal(scene);
      expectOneLine(message, `photometry.json: luminaires[0].photometry: cannot read "${name}"`, reason);
      expect(ms).toBeLessThan(2000);
    },
    10_000,
  );

  it.each([...SPECIALS, ['huge.bin', /file is too large/] as [string, RegExp]])(
    'OBJ mtllib %s: refused at once, naming it',
    async (name, reason) => {
      writeFileSync(join(folder, 'box.obj'), readFileSync(join(MODELS, 'table.obj'), 'utf8').replace('mtllib table.mtl', `mtllib ${name}`));
      const scene = writeScene('obj', { objects: [{ mesh: 'box.obj', position: [1.5, 0, 1.5] }] });
      const { message, ms } = await refusal(scene);
      expectOneLine(message, `obj.json: objects[0].mesh: box.obj: cannot read ${name}`, reason);
      expect(ms).toBeLessThan(2000);
      // The synchronous loader (OBJ only) refuses the same way.
      expect(() => loadLightingSceneFile(scene, { within: cliReadableFolders(scene) })).toThrow(`cannot read ${name}`);
    },
    10_000,
  );

  it.each([...SPECIALS, ['huge.bin', /file is too large/] as [string, RegExp]])(
    'glTF buffer uri %s: refused at once, naming it',
    async (name, reason) => {
      const gltf = JSON.parse(readFileSync(join(MODELS, 'table-external.gltf'), 'utf8')) as { buffers: { uri: string }[] };
      gltf.buffers[0].uri = name;
      writeFileSync(join(folder, 'box.gltf'), JSON.stringify(gltf));
      const scene = writeScene('gltf', { objects: [{ mesh: 'box.gltf', position: [1.5, 0, 1.5] }] });
      const { message, ms } = await refusal(scene);
      expectOneLine(message, `gltf.json: objects[0].mesh: box.gltf: cannot read ${name}`, reason);
      expect(ms).toBeLessThan(2000);
    },
    10_000,
  );

  it('the model file itself: a link to /dev/zero, a pipe or a folder named as the mesh is refused the same way', async () => {
    symlinkSync('/dev/zero', join(folder, 'zero.obj'));
    execFileSync('mkfifo', [join(folder, 'pipe.obj')]);
    mkdirSync(join(folder, 'folder.obj'));
    for (const [mesh, reason] of [
      ['zero.obj', /outside the scene's folder/],
      ['pipe.obj', /a named pipe, not a regular file/],
      ['folder.obj', /a directory, not a regular file/],
    ] as const) {
      const { message } = await refusal(writeScene('model', { objects: [{ mesh, position: [1.5, 0, 1.5] }] }));
      expectOneLine(message, `model.json: objects[0].mesh: cannot read ${mesh} (`, reason);
    }
  }, 10_000);

  it('a scene and its files in its own folder load; so do the fixtures that reach into luxbox’s public/ folder', async () => {
    copyFileSync(join(MODELS, 'table.obj'), join(folder, 'table.obj'));
    copyFileSync(join(MODELS, 'table.mtl'), join(folder, 'table.mtl'));
    const scene = writeScene('good', { objects: [{ mesh: 'table.obj', position: [1.5, 0, 1.5] }] });
    const loaded = await loadLightingSceneFileAsync(scene, { within: cliReadableFolders(scene) });
    expect(loaded.bakeScene.objects).toHaveLength(1);
    expect(loaded.meshes.get('table.obj')!.warnings).toEqual([]);
    const fixture = 'tests/fixtures/models/furnished-room.json';
    expect((await loadLightingSceneFileAsync(fixture, { within: cliReadableFolders(fixture) })).bakeScene.objects).toHaveLength(2);
  });

  it('a long absolute path keeps the reason inside the one-line message (the resolved path is cut from its start)', async () => {
    const deep = mkdtempSync(join(tmpdir(), 'luxbox-deep-'));
    const folder = join(deep, 'a-folder-with-a-long-name-'.repeat(4), 'and-another-one-below-it');
    mkdirSync(folder, { recursive: true });
    const far = join(folder, 'lamp.ies');
    writeFileSync(far, readFileSync('tests/fixtures/photometry/lumens_mismatch_60x.ies'));
    const scene = writeScene('deep', { luminaires: [{ photometry: far, position: [1, 2.4, 1] }] });
    const { message } = await refusal(scene);
    expect(far.length).toBeGreaterThan(150);
    expect(message).toMatch(/…[^ ]*lamp\.ies is outside the scene's folder \(give more with --allow\)\)$/);
  });

  it('a file in the current folder but outside the scene’s is refused (a scene run from a home folder cannot name ../.ssh/…); --allow opens more folders', async () => {
    // The current folder is the repository: the fixture lies in it, not in the scene's folder or public/.
    const elsewhere = resolve('tests/fixtures/photometry/lumens_mismatch_60x.ies');
    const scene = writeScene('cwd', { luminaires: [{ photometry: elsewhere, position: [1, 2.4, 1] }] });
    const { message } = await refusal(scene);
    expect(message).toMatch(/^cwd\.json: luminaires\[0\]\.photometry: cannot read ".* \(.*lumens_mismatch_60x\.ies is outside the scene's folder/);
    expect(() => readRegularFile(elsewhere, { maxBytes: MAX_PHOTOMETRY_BYTES, within: cliReadableFolders(scene) })).toThrow(/lumens_mismatch_60x\.ies is outside the scene's folder \(give more with --allow\)$/);
    // Given on the command line (--allow, several joined like PATH), the folder is read.
    for (const allow of ['tests/fixtures/photometry', `${root}${delimiter}tests/fixtures`]) {
      const loaded = await loadLightingSceneFileAsync(scene, { within: cliReadableFolders(scene, allow) });
      expect(loaded.bakeScene.luminaires).toHaveLength(1);
    }
    expect(cliReadableFolders(scene, `${root}${delimiter}`)).toHaveLength(3); // the scene's folder, public/, root
  });

  it('a missing MTL library stays a warning (grey materials), as before', async () => {
    writeFileSync(join(folder, 'box.obj'), readFileSync(join(MODELS, 'table.obj'), 'utf8').replace('mtllib table.mtl', 'mtllib gone.mtl'));
    const scene = writeScene('missing', { objects: [{ mesh: 'box.obj', position: [1.5, 0, 1.5] }] });
    const loaded = await loadLightingSceneFileAsync(scene, { within: cliReadableFolders(scene) });
    expect(loaded.meshes.get('box.obj')!.warnings.join(' ')).toContain('gone.mtl not found');
  });

  it('a scene file given on the command line is read wherever it is, but only if it is a regular file', async () => {
    for (const [path, reason] of [
      ['/dev/zero', /^zero: cannot read \/dev\/zero \(a character device, not a regular file\)$/],
      [join(folder, 'pipe'), /a named pipe, not a regular file/],
      [folder, /a directory, not a regular file/],
    ] as const) {
      await expect(loadLightingSceneFileAsync(path)).rejects.toThrow(reason);
    }
  });
});

describe('readRegularFile', () => {
  it('refuses devices, pipes and folders by fstat on the open file, symbolic links followed', () => {
    expect(() => readRegularFile('/dev/zero', { maxBytes: 1000 })).toThrow('a character device, not a regular file');
    expect(() => readRegularFile(join(folder, 'zero-link'), { maxBytes: 1000 })).toThrow('a character device, not a regular file');
    expect(() => readRegularFile(join(folder, 'pipe'), { maxBytes: 1000 })).toThrow('a named pipe, not a regular file');
    expect(() => readRegularFile(folder, { maxBytes: 1000 })).toThrow('a directory, not a regular file');
    expect(() => readRegularFile(join(folder, 'gone'), { maxBytes: 1000 })).toThrow('no such file');
  });

  it('holds the size cap while reading: a regular file whose stat says 0 bytes (procfs) stops one past the cap', () => {
    expect(readFileSync('/proc/self/maps').length).toBeGreaterThan(200);
    expect(() => readRegularFile('/proc/self/maps', { maxBytes: 100 })).toThrow('file is too large (more than 100 bytes)');
    expect(readRegularFile(join(folder, 'lamp.ies'), { maxBytes: MAX_PHOTOMETRY_BYTES })).toEqual(new Uint8Array(readFileSync(IES)));
  });

  it('refuses a file outside the given folders once links are resolved', () => {
    const within = cliReadableFolders(join(folder, 'x.json'));
    expect(() => readRegularFile(join(root, 'outside.ies'), { maxBytes: MAX_PHOTOMETRY_BYTES, within })).toThrow(/outside the scene's folder/);
    expect(() => readRegularFile(join(folder, 'zero-link'), { maxBytes: 1000, within })).toThrow(/^\/dev\/zero is outside the scene's folder \(give more with --allow\)$/);
    expect(readRegularFile(join(folder, 'lamp.ies'), { maxBytes: MAX_PHOTOMETRY_BYTES, within }).length).toBeGreaterThan(0);
  });
});
