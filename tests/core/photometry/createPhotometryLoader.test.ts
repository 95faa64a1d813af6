import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { createPhotometryLoader } from '../../../src/core/photometry/createPhotometryLoader';
import { PhotometryParseError } from '../../../src/core/photometry/PhotometryParseError';
import { PhotometryReadError } from '../../../src/core/photometry/PhotometryReadError';

const fixtures = join(__dirname, '../../fixtures/photometry');
const bytes = (name: string) => new Uint8Array(readFileSync(join(fixtures, name)));
const GOOD = 'c_rotational_isotropic.ies';
const WARNED = 'lumens_mismatch_60x.ies';
const NOT_PHOTOMETRY = new TextEncoder().encode('IESNA:LM-63-2002\nno tilt line here\n');

/** A reader over named byte arrays that counts its reads; async unless told otherwise. */
function countingReader(files: Record<string, Uint8Array>) {
  const reads: string[] = [];
  const read = (path: string): Uint8Array => {
    reads.push(path);
    const data = files[path];
    if (!data) throw new PhotometryReadError(path, 'no such file');
    return data;
  };
  return { reads, sync: read, async: async (path: string) => read(path) };
}

describe('createPhotometryLoader', () => {
  it('reads and parses each path once; the parser names the file and keeps its warnings', async () => {
    const r = countingReader({ [GOOD]: bytes(GOOD), [WARNED]: bytes(WARNED) });
    const load = createPhotometryLoader(r.async);
    const a = await load(GOOD);
    expect(await load(GOOD)).toBe(a);
    const w = await load(WARNED);
    expect(w.warnings.length).toBeGreaterThan(0);
    expect(r.reads).toEqual([GOOD, WARNED]);
  });

  it('concurrent loads of one path share one read', async () => {
    const r = countingReader({ [GOOD]: bytes(GOOD) });
    const load = createPhotometryLoader(r.async);
    const [a, b, c] = await Promise.all([load(GOOD), load(GOOD), load(GOOD)]);
    expect(a).toBe(b);
    expect(b).toBe(c);
    expect(r.reads).toEqual([GOOD]);
  });

  it('a synchronous reader gives synchronous answers, cached the same way', () => {
    const r = countingReader({ [GOOD]: bytes(GOOD) });
    const load = createPhotometryLoader(r.sync);
    const a = load(GOOD);
    expect(a.candela.length).toBeGreaterThan(0);
    expect(load(GOOD)).toBe(a);
    expect(r.reads).toEqual([GOOD]);
  });

  it('a file that does not parse: the same error naming the file every time, read once', async () => {
    const r = countingReader({ 'bad.ies': NOT_PHOTOMETRY });
    const load = createPhotometryLoader(r.async);
    const first = await load('bad.ies').catch((e: unknown) => e);
    expect(first).toBeInstanceOf(PhotometryParseError);
    expect((first as Error).message).toMatch(/^bad\.ies( line \d+)?: /);
    expect(await load('bad.ies').catch((e: unknown) => e)).toBe(first);
    expect(r.reads).toEqual(['bad.ies']);

    const s = countingReader({ 'bad.ies': NOT_PHOTOMETRY });
    const loadSync = createPhotometryLoader(s.sync);
    const thrown = (() => {
      try {
        loadSync('bad.ies');
      } catch (e) {
        return e;
      }
    })();
    expect(thrown).toBeInstanceOf(PhotometryParseError);
    expect(() => loadSync('bad.ies')).toThrow((thrown as Error).message);
    expect(s.reads).toEqual(['bad.ies']);
  });

  it('a file that cannot be read: an error naming it, and the next load reads again', async () => {
    const files: Record<string, Uint8Array> = {};
    const r = countingReader(files);
    const load = createPhotometryLoader(r.async);
    await expect(load('ies/late.ies')).rejects.toThrow('ies/late.ies: no such file');
    files['ies/late.ies'] = bytes(GOOD);
    await expect(load('ies/late.ies')).resolves.toHaveProperty('format', 'IES');
    expect(r.reads).toEqual(['ies/late.ies', 'ies/late.ies']);
  });

  it('a reader failure that is not a PhotometryReadError (fetch TypeError, fs error) is turned into one naming the path', async () => {
    const load = createPhotometryLoader(async (): Promise<Uint8Array> => {
      throw new TypeError('Failed to fetch');
    });
    const error = await load('ies/x.ies').catch((e: unknown) => e);
    expect(error).toBeInstanceOf(PhotometryReadError);
    expect(error).toMatchObject({ message: 'ies/x.ies: Failed to fetch', path: 'ies/x.ies', reason: 'Failed to fetch' });
    const loadSync = createPhotometryLoader((): Uint8Array => {
      throw new Error('EACCES');
    });
    expect(() => loadSync('a.ies')).toThrow(new PhotometryReadError('a.ies', 'EACCES'));
  });

  it("two hosts' loaders have independent caches", async () => {
    const r1 = countingReader({ [GOOD]: bytes(GOOD) });
    const r2 = countingReader({ [GOOD]: bytes(GOOD) });
    const one = createPhotometryLoader(r1.async);
    const two = createPhotometryLoader(r2.async);
    const [a, b] = [await one(GOOD), await two(GOOD)];
    expect(a).not.toBe(b);
    expect(a).toEqual(b);
    await one(GOOD);
    await two(GOOD);
    expect(r1.reads).toEqual([GOOD]);
    expect(r2.reads).toEqual([GOOD]);
  });
});
