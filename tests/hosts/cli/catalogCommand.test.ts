/**
 * `luxbox catalog import` end to end (docs/gldf.md): GLDF files built from the repo's
 * photometry, the demo catalog as the base, the manufacturer's mapping; the folder written must
 * hold a catalog that validates, every photometry it names, and the report. A refused file
 * writes nothing.
 */
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { validateXML } from 'xmllint-wasm';
import { unzipSync } from 'fflate';
import { parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { parsePhotometry } from '../../../src/core/photometry';
import { gldfBytes, linearSpec, MAPPING_TEXT, pendantSpec, productXml, trackSpotSpec } from '../../core/gldf/buildGldf';

const dir = mkdtempSync(join(tmpdir(), 'luxbox-catalog-import-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

function luxbox(...args: string[]): { status: number | null; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, ['bin/luxbox.js', ...args], { encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

const write = (name: string, bytes: Uint8Array | string): string => {
  const path = join(dir, name);
  writeFileSync(path, bytes);
  return path;
};

describe('luxbox catalog import', () => {
  const spot = write('track-spot.gldf', gldfBytes(trackSpotSpec()));
  const pendant = write('pendant.gldf', gldfBytes(pendantSpec()));
  const linear = write('linear.gldf', gldfBytes(linearSpec()));
  const mapping = write('mapping.json', MAPPING_TEXT);

  it('writes a complete catalog folder: catalog.json, every photometry it names (imported and the base’s), the picture, the report', () => {
    const out = join(dir, 'shop');
    const r = luxbox('catalog', 'import', spot, pendant, linear, '--into', 'src/core/catalog/default-catalog.json', '--assets', 'public', '--mapping', mapping, '--out', out);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(r.stdout.split('\n')[0]).toBe("track-spot.gldf: module type 'track-spot', 9 variants imported, 0 skipped, 3 values assumed, 3 flux differences");
    const catalog = parseCatalogText(readFileSync(join(out, 'catalog.json'), 'utf8'), 'catalog.json');
    expect(catalog.moduleTypes.map((t) => t.id)).toEqual(['spot', 'spot-warmdim', 'flood', 'linear', 'washer', 'updown', 'track-spot', 'ltl-pendant', 'linear-600']);
    // Every photometry the catalog names is in the folder and parses: the folder is served as the app's assetBase.
    for (const b of catalog.moduleTypes.flatMap((t) => t.beams)) {
      const bytes = new Uint8Array(readFileSync(join(out, b.photometry)));
      expect(parsePhotometry(bytes, b.photometry).candela.length).toBeGreaterThan(0);
    }
    expect(readdirSync(join(out, 'images'))).toEqual(['track-spot.png']);
    const report = JSON.parse(readFileSync(join(out, 'import-report.json'), 'utf8'));
    expect(report.products.map((p: { typeId: string }) => p.typeId)).toEqual(['track-spot', 'ltl-pendant', 'linear-600']);
    expect(readFileSync(join(out, 'import-report.txt'), 'utf8')).toContain('skipped pd-wall-3000: mounting wall-surface does not fit the rail (ceiling-surface, ceiling-pendant)');
  });

  it('a refused file writes nothing, in one line naming the file and entry, exit 1', () => {
    const spec = trackSpotSpec();
    const bad = write('bad.gldf', gldfBytes(spec, {}, productXml(spec).replace('<Root>', '<!DOCTYPE Root [<!ENTITY x "y">]><Root>')));
    const out = join(dir, 'never');
    const r = luxbox('catalog', 'import', pendant, bad, '--into', 'src/core/catalog/default-catalog.json', '--out', out);
    expect(r.status).toBe(1);
    expect(r.stderr).toBe("luxbox catalog: bad.gldf: entry 'product.xml': has a DTD (<!DOCTYPE); DTDs and entity declarations are refused\n");
    expect(existsSync(out)).toBe(false);
  });

  it('usage errors in one line', () => {
    for (const [args, message] of [
      [['import', spot, '--out', join(dir, 'x')], /--into <catalog\.json> is required/],
      [['import', '--into', 'src/core/catalog/default-catalog.json', '--out', join(dir, 'x')], /no GLDF file given/],
      [['export'], /export: give one catalog\.json/],
      [['export', 'src/core/catalog/default-catalog.json'], /export: --out <dir> is required/],
      [['publish'], /unknown subcommand "publish"/],
      [['import', spot, '--into', 'src/core/catalog/default-catalog.json', '--out', join(dir, 'x'), '--mapping', spot], /^luxbox catalog: track-spot\.gldf/],
    ] as const) {
      const r = luxbox('catalog', ...args);
      expect(r.status).toBe(1);
      expect(r.stderr.trim().split('\n')).toHaveLength(1);
      expect(r.stderr).toMatch(message);
    }
  });
});

describe('luxbox catalog export', () => {
  const spot = write('export-track-spot.gldf', gldfBytes(trackSpotSpec()));
  const linear = write('export-linear.gldf', gldfBytes(linearSpec()));
  const mapping = write('export-mapping.json', MAPPING_TEXT);
  const schema = { fileName: 'gldf.xsd', contents: readFileSync('vendor/gldf/gldf.xsd', 'utf8') };

  it('round trip: import, export the imported types, import the exports with the exported mapping: the same module types (all but the beams’ source)', async () => {
    const shop = join(dir, 'export-shop');
    expect(luxbox('catalog', 'import', spot, linear, '--into', 'src/core/catalog/default-catalog.json', '--assets', 'public', '--mapping', mapping, '--out', shop).status).toBe(0);
    const gldf = join(dir, 'gldf-out');
    const r = luxbox('catalog', 'export', join(shop, 'catalog.json'), '--type', 'track-spot', '--type', 'linear-600', '--out', gldf);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(r.stdout.split('\n')[0]).toBe('track-spot.gldf: 9 variants; each beam’s source text is provenance: the import writes its own, naming the GLDF file and variant');
    expect(readdirSync(gldf).sort()).toEqual(['linear-600.gldf', 'mapping.json', 'track-spot.gldf']);
    const entries = unzipSync(new Uint8Array(readFileSync(join(gldf, 'track-spot.gldf'))));
    const v = await validateXML({ xml: [{ fileName: 'product.xml', contents: new TextDecoder().decode(entries['product.xml']) }], schema: [schema] });
    expect(v.errors.map((e) => e.rawMessage)).toEqual([]);
    expect(entries['image/track-spot.png']).toEqual(new Uint8Array(readFileSync(join(shop, 'images', 'track-spot.png'))));

    const again = join(dir, 'export-again');
    const r2 = luxbox('catalog', 'import', join(gldf, 'track-spot.gldf'), join(gldf, 'linear-600.gldf'), '--into', 'src/core/catalog/default-catalog.json', '--assets', 'public', '--mapping', join(gldf, 'mapping.json'), '--out', again);
    expect(r2.stderr).toBe('');
    const before = parseCatalogText(readFileSync(join(shop, 'catalog.json'), 'utf8'), 'catalog.json');
    const after = parseCatalogText(readFileSync(join(again, 'catalog.json'), 'utf8'), 'catalog.json');
    const strip = (c: typeof before): unknown => c.moduleTypes.map((t) => ({ ...t, beams: t.beams.map(({ source: _s, ...b }) => b) }));
    expect(strip(after)).toEqual(strip(before));
    for (const b of after.moduleTypes.flatMap((t) => t.beams)) expect(readFileSync(join(again, b.photometry))).toEqual(readFileSync(join(shop, b.photometry)));
  });

  it('exports every type of the demo catalog (its photometry under public/): each validates, the dimming curve is noted as not exported', async () => {
    const out = join(dir, 'demo-gldf');
    const r = luxbox('catalog', 'export', 'src/core/catalog/default-catalog.json', '--assets', 'public', '--out', out);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const demo = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');
    expect(readdirSync(out).sort()).toEqual([...demo.moduleTypes.map((t) => `${t.id}.gldf`), 'mapping.json'].sort());
    for (const t of demo.moduleTypes) {
      const xml = new TextDecoder().decode(unzipSync(new Uint8Array(readFileSync(join(out, `${t.id}.gldf`))))['product.xml']);
      const v = await validateXML({ xml: [{ fileName: 'product.xml', contents: xml }], schema: [schema] });
      expect({ type: t.id, errors: v.errors.map((e) => e.rawMessage) }).toEqual({ type: t.id, errors: [] });
    }
    expect(r.stdout).toMatch(/spot-warmdim\.gldf: \d+ variants; .*its dimming curve \(dim-to-warm\) has no GLDF element and is not exported/);
  });

  it('an unknown type writes nothing, exit 1', () => {
    const out = join(dir, 'export-never');
    const r = luxbox('catalog', 'export', 'src/core/catalog/default-catalog.json', '--assets', 'public', '--type', 'spot', '--type', 'nope', '--out', out);
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(/^luxbox catalog: catalog 'luxbox-demo-rail' has no module type 'nope'/);
    expect(existsSync(out)).toBe(false);
  });
});
