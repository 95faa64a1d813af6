import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { readImportGraph } from './importGraph';
import { directParses, zodImportViolations } from './zodRules';

function sources(dir: string, out: string[] = []): string[] {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) sources(path, out);
    else if (/\.(ts|tsx)$/.test(name)) out.push(path.split('\\').join('/'));
  }
  return out;
}

describe('zod: the schemas run the API they are typed against', () => {
  it('no file under src imports zod other than zod/mini', () => {
    const edges = readImportGraph('.');
    expect(edges.some((e) => e.spec === 'zod/mini')).toBe(true);
    expect(zodImportViolations(edges)).toEqual([]);
  });

  it('the rule catches classic zod however it is imported', () => {
    const from = 'src/core/room/roomShapeSchema.ts';
    const found = zodImportViolations([
      { from, to: 'zod', isPackage: true, spec: 'zod' },
      { from, to: 'zod', isPackage: true, spec: 'zod/v4' },
      { from, to: 'zod', isPackage: true, spec: 'zod/mini' },
      { from, to: 'zod-to-anything', isPackage: true, spec: 'zod-to-anything' },
    ]);
    expect(found).toEqual([`${from} imports 'zod': write the schema against 'zod/mini' (z.optional(x), x.check(z.gte(0)), …)`, `${from} imports 'zod/v4': write the schema against 'zod/mini' (z.optional(x), x.check(z.gte(0)), …)`]);
  });

  it('every parse with a schema goes through safeParseInEnglish', () => {
    const found = sources('src').flatMap((file) => directParses(file, readFileSync(file, 'utf8')));
    expect(found).toEqual([]);
  });

  it('the parse rule catches a direct safeParse, and parse in a schema file, not an XML parser', () => {
    expect(directParses('src/core/a.ts', 'const r = definition(name).params.safeParse(params);')).toHaveLength(1);
    expect(directParses('src/core/b.ts', "import { z } from 'zod/mini';\nconst v = schema.parse(data);")).toHaveLength(1);
    expect(directParses('src/core/c.ts', 'doc = parser.parse(text);')).toEqual([]);
    expect(directParses('src/core/zodEnglish.ts', 'return safeParse(schema, data); schema.safeParse(x);')).toEqual([]);
  });
});
