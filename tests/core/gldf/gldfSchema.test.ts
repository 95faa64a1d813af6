/**
 * The GLDF files the tests build are valid GLDF: each product.xml against the official schema
 * (vendor/gldf/gldf.xsd, globallightingdata/gldf, MIT) through xmllint (libxml2 compiled to
 * WebAssembly, xmllint-wasm). A twin with an element out of the schema's order is refused, so
 * the check can fail.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { validateXML } from 'xmllint-wasm';
import { changeablePendantXml, linearSpec, pendantSpec, productXml, trackSpotSpec } from './buildGldf';

const schema = { fileName: 'gldf.xsd', contents: readFileSync('vendor/gldf/gldf.xsd', 'utf8') };

async function validate(xml: string): Promise<{ valid: boolean; errors: string[] }> {
  const r = await validateXML({ xml: [{ fileName: 'product.xml', contents: xml }], schema: [schema] });
  return { valid: r.valid, errors: r.errors.map((e) => e.rawMessage) };
}

describe('GLDF test files against the official XSD', () => {
  for (const [name, spec] of [
    ['track spot', trackSpotSpec],
    ['pendant', pendantSpec],
    ['linear module', linearSpec],
  ] as const) {
    it(`${name}: product.xml validates`, async () => {
      expect(await validate(productXml(spec()))).toEqual({ valid: true, errors: [] });
    });
  }

  it('pendant with changeable lamps (ChangeableLightSource, Equipment, ChangeableLightEmitter): product.xml validates', async () => {
    expect(await validate(changeablePendantXml())).toEqual({ valid: true, errors: [] });
  });

  it('a product.xml with GTIN before the variant Name is refused by the schema', async () => {
    const xml = productXml(trackSpotSpec()).replace(/(<ProductNumber><Locale language="en">LTL-TS-NARROW-30<\/Locale><\/ProductNumber>)(<Name>.*?<\/Name>)(<GTIN>\d+<\/GTIN>)/, '$1$3$2');
    const r = await validate(xml);
    expect(r.valid).toBe(false);
    expect(r.errors.join(' ')).toMatch(/GTIN/);
  });
});
