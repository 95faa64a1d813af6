/**
 * A GLDF is an upload (docs/gldf.md, "Limits"): each hostile container below is refused with
 * one line naming the file and the entry, and nothing of it lands in a catalog. The bombs'
 * sizes are written into the central directory where making the real bytes would take a test
 * seconds; the reader must refuse them from the directory alone, before inflating.
 */
import { readFileSync } from 'node:fs';
import { zipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { GldfError } from '../../../src/core/gldf/GldfError';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { readGldfProduct } from '../../../src/core/gldf/readGldfProduct';
import { crc32, readUploadZip, unsafeEntryName } from '../../../src/core/gldf/readUploadZip';
import { UPLOAD_LIMITS } from '../../../src/core/gldf/uploadLimits';
import { parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { gldfBytes, linearSpec, pendantSpec, productXml, trackSpotSpec } from './buildGldf';

const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'));

/** The message a container is refused with (fails the test when it is accepted or throws anything else). */
function refusal(bytes: Uint8Array, name = 'bad.gldf'): string {
  try {
    importGldfCatalog(base, [{ name, bytes }], null);
  } catch (error) {
    expect(error).toBeInstanceOf(GldfError);
    const message = (error as Error).message;
    expect(message.split('\n')).toHaveLength(1);
    expect(message.length).toBeLessThanOrEqual(200);
    return message;
  }
  throw new Error('accepted');
}

/** Rewrites fields of an entry's central directory header (APPNOTE §4.3.12). */
function patchCentral(zip: Uint8Array, name: string, fields: { size?: number; compressedSize?: number; method?: number }): Uint8Array {
  const out = zip.slice();
  const view = new DataView(out.buffer);
  const encoded = new TextEncoder().encode(name);
  for (let at = 0; at + 46 < out.length; at++) {
    if (view.getUint32(at, true) !== 0x02014b50) continue;
    const n = view.getUint16(at + 28, true);
    if (n !== encoded.length || !encoded.every((b, i) => out[at + 46 + i] === b)) continue;
    if (fields.method !== undefined) view.setUint16(at + 10, fields.method, true);
    if (fields.compressedSize !== undefined) view.setUint32(at + 20, fields.compressedSize, true);
    if (fields.size !== undefined) view.setUint32(at + 24, fields.size, true);
    return out;
  }
  throw new Error(`no central entry ${name}`);
}

const xmlWith = (edit: (xml: string) => string, spec = trackSpotSpec()): Uint8Array => gldfBytes(spec, {}, edit(productXml(spec)));

describe('hostile GLDF containers are refused in one line naming file and entry', () => {
  it('a zip bomb entry: 24 MB of zeros compressed over 1000:1, refused from the central directory', () => {
    const zeros = new Uint8Array(24 * 1024 * 1024);
    const zip = gldfBytes(trackSpotSpec(), { 'other/padding.bin': [zeros, { level: 9 }] });
    expect(refusal(zip)).toMatch(/^bad\.gldf: entry 'other\/padding\.bin' compresses \d+:1, over the 200:1 limit \(a zip bomb\?\)$/);
  });

  it('an entry that claims more than the per-entry cap, and entries that add up to more than the total cap', () => {
    const zip = gldfBytes(trackSpotSpec());
    expect(refusal(patchCentral(zip, 'ldc/bega_84693_narrow_spot.ies', { size: 40 * 1024 * 1024 }))).toBe("bad.gldf: entry 'ldc/bega_84693_narrow_spot.ies' is 40 MB uncompressed, over the 32 MB limit per entry");
    // Five stored (uncompressed) entries of 30 MB each: ratio 1, each under the entry cap, 150 MB in all.
    const stored = zipSync(Object.fromEntries([1, 2, 3, 4, 5].map((i) => [`other/${i}.bin`, [new Uint8Array(16), { level: 0 }]])));
    let patched: Uint8Array = stored;
    for (const i of [1, 2, 3, 4, 5]) patched = patchCentral(patched, `other/${i}.bin`, { size: 30 * 1024 * 1024, compressedSize: 30 * 1024 * 1024 });
    expect(refusal(patched)).toBe("bad.gldf: entry 'other/5.bin': the entries add up to over 128 MB uncompressed");
  });

  it('more entries than the cap', () => {
    const many = Object.fromEntries(Array.from({ length: UPLOAD_LIMITS.maxEntries + 1 }, (_, i) => [`other/${i}.txt`, new Uint8Array(1)]));
    expect(refusal(zipSync(many))).toBe('bad.gldf: 1001 entries, over the limit of 1000');
  });

  it('an entry that inflates to more than its directory entry states is stopped while inflating', () => {
    const zip = patchCentral(gldfBytes(trackSpotSpec()), 'product.xml', { size: 100 });
    expect(refusal(zip)).toBe("bad.gldf: entry 'product.xml' inflates to more than the 100 bytes its directory entry states (a zip bomb?)");
  });

  it('damaged data: a flipped byte fails the checksum; not a zip at all', () => {
    const zip = gldfBytes(trackSpotSpec(), { 'other/note.txt': [new TextEncoder().encode('stored text'), { level: 0 }] });
    const at = indexOf(zip, new TextEncoder().encode('stored text'));
    const broken = zip.slice();
    broken[at] ^= 0x20;
    expect(() => readUploadZip(broken, 'bad.gldf').read('other/note.txt')).toThrow("bad.gldf: entry 'other/note.txt': checksum mismatch (the data is damaged)");
    expect(refusal(new TextEncoder().encode('<Root/>'.repeat(10)))).toBe('bad.gldf: not a zip container (no end of central directory)');
    expect(crc32(new TextEncoder().encode('123456789'))).toBe(0xcbf43926); // the CRC-32 check value (APPNOTE; ISO 3309)
  });

  it('path traversal and other unsafe entry names', () => {
    for (const [name, why] of [
      ['../evil.ies', "climbs out of the container ('..')"],
      ['ldc/../../evil.ies', "climbs out of the container ('..')"],
      ['/etc/evil.ies', 'has an absolute path'],
      ['C:/evil.ies', 'names a drive'],
      ['ldc\\evil.ies', 'uses a backslash in its name (zip names use /)'],
      ['ldc//evil.ies', "has an empty or '.' path segment"],
    ] as const) {
      expect(unsafeEntryName(name)).toBe(why);
      const zip = gldfBytes(trackSpotSpec(), { [name]: new Uint8Array(4) });
      expect(refusal(zip)).toBe(`bad.gldf: entry '${name.replace(/\\/g, '\\\\')}' ${why}`);
    }
    // A File element that names a path instead of a file name.
    expect(refusal(xmlWith((x) => x.replace('>bega_84693_narrow_spot.ies<', '>../bega_84693_narrow_spot.ies<')))).toBe("bad.gldf: entry 'product.xml': File 'f-narrow': '../bega_84693_narrow_spot.ies' climbs out of the container ('..')");
  });

  it('DTDs and entity declarations: entity expansion and external entities never reach the parser', () => {
    const laughs = (x: string): string => x.replace('<Root>', '<!DOCTYPE Root [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">]><Root>').replace('>Luxbox Test Lighting<', '>&lol2;<');
    expect(refusal(xmlWith(laughs))).toBe("bad.gldf: entry 'product.xml': has a DTD (<!DOCTYPE); DTDs and entity declarations are refused");
    const external = (x: string): string => x.replace('<Root>', '<!DOCTYPE Root SYSTEM "file:///etc/passwd"><Root>');
    expect(refusal(xmlWith(external))).toMatch(/has a DTD/);
    const entityOnly = (x: string): string => x.replace('<Root>', '<Root><!ENTITY x SYSTEM "http://example.invalid/">');
    expect(refusal(xmlWith(entityOnly))).toBe("bad.gldf: entry 'product.xml': declares an entity (<!ENTITY); DTDs and entity declarations are refused");
  });

  it('XML nested deeper than 40 levels, and more than 5000 siblings of one name', () => {
    expect(refusal(xmlWith((x) => x.replace('<Header>', `<Header>${'<A>'.repeat(60)}${'</A>'.repeat(60)}`)))).toBe("bad.gldf: entry 'product.xml': Maximum nested tags exceeded");
    const files = Array.from({ length: 5001 }, (_, i) => `<File id="x${i}" contentType="other" type="url">u</File>`).join('');
    expect(refusal(xmlWith((x) => x.replace('<Files>', `<Files>${files}`)))).toBe("bad.gldf: entry 'product.xml': 5006 <File> elements, over the limit of 5000"); // 5001 + the spot's 5 (three photometries, the picture, the L3D)
  });

  it('malformed XML is refused with its line', () => {
    expect(refusal(xmlWith((x) => x.replace('</Header>', '</Headr>')))).toMatch(/^bad\.gldf: entry 'product\.xml' line 2: .*Header/);
  });

  it('references to missing ids and duplicate ids', () => {
    expect(refusal(xmlWith((x) => x.replace('photometryId="ph-wide"', 'photometryId="ph-missing"')))).toBe("bad.gldf: entry 'product.xml': Emitter 'em-wide-3000': photometryId 'ph-missing' names no Photometry");
    expect(refusal(xmlWith((x) => x.replace('<EmitterReference emitterId="em-medium-2700">', '<EmitterReference emitterId="em-gone">')))).toBe(
      "bad.gldf: entry 'product.xml': Variant 'v-medium-2700'/Geometry: emitterId 'em-gone' names no Emitter",
    );
    expect(refusal(xmlWith((x) => x.replace('fixedLightSourceId="ls-narrow-4000"', 'fixedLightSourceId="nowhere"')))).toBe("bad.gldf: entry 'product.xml': Emitter 'em-narrow-4000': fixedLightSourceId 'nowhere' names no light source");
    expect(refusal(xmlWith((x) => x.replace('<Variant id="v-medium-3000"', '<Variant id="v-narrow-3000"')))).toBe("bad.gldf: entry 'product.xml': Variant: duplicate id 'v-narrow-3000'");
    // xs:ID is unique across the document: a Photometry may not share a File's id.
    expect(refusal(xmlWith((x) => x.replace('<Photometry id="ph-wide">', '<Photometry id="f-wide">').replace(/photometryId="ph-wide"/g, 'photometryId="f-wide"')))).toBe("bad.gldf: entry 'product.xml': Photometry: duplicate id 'f-wide'");
  });

  it('a File the container lacks, and a container without product.xml', () => {
    const spec = trackSpotSpec();
    const zip = gldfBytes({ ...spec, files: spec.files.filter((f) => f.id !== 'f-wide') }, {}, productXml(spec));
    expect(refusal(zip)).toBe("bad.gldf: entry 'product.xml': File 'f-wide' names 'ldc/bega_50975_downlight_lm1995_crlf.ies', which is not in the container");
    expect(refusal(zipSync({ 'ldc/x.ies': new Uint8Array(3) }))).toBe('bad.gldf: no product.xml in the container');
  });

  it('photometry the IES/EULUMDAT parsers refuse refuses the GLDF, naming the entry', () => {
    const spec = linearSpec();
    spec.files[0].bytes = new TextEncoder().encode('not a EULUMDAT file\n1\n2\n');
    expect(refusal(gldfBytes(spec))).toBe('bad.gldf: entry \'ldc/zumtobel_sloin_linear_isym4.ldt\' line 4: expected the number of C-planes Mc (a number), found ""');
  });

  it('nothing partial: one bad file among good ones refuses the whole import', () => {
    const good = [
      { name: 'pendant.gldf', bytes: gldfBytes(pendantSpec()) },
      { name: 'spot.gldf', bytes: gldfBytes(trackSpotSpec()) },
    ];
    const bad = { name: 'broken.gldf', bytes: xmlWith((x) => x.replace('photometryId="ph-wide"', 'photometryId="ph-missing"')) };
    expect(() => importGldfCatalog(base, [good[0], bad, good[1]], null)).toThrow(/^broken\.gldf: entry 'product\.xml': Emitter 'em-wide-3000'/);
    expect(() => importGldfCatalog(base, [...good, { name: 'again.gldf', bytes: gldfBytes(pendantSpec()) }], null)).toThrow("again.gldf: product 'LTL-PENDANT' was already imported from pendant.gldf");
  });

  it('a product with no variant that fits the rail makes no type; an import of only such products is refused', () => {
    const spec = pendantSpec();
    spec.variants = spec.variants.filter((v) => v.id === 'pd-wall-3000');
    expect(refusal(gldfBytes(spec), 'wall.gldf')).toBe('nothing to import: no variant of wall.gldf fits the rail catalog');
    const { product } = readGldfProduct(gldfBytes(spec), 'wall.gldf');
    expect(product.variants[0].mountings).toEqual(['wall-surface']);
  });
});

function indexOf(hay: Uint8Array, needle: Uint8Array): number {
  outer: for (let i = 0; i + needle.length <= hay.length; i++) {
    for (let j = 0; j < needle.length; j++) if (hay[i + j] !== needle[j]) continue outer;
    return i;
  }
  throw new Error('not found');
}
