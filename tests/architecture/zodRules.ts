import type { ImportEdge } from './importGraph';

/**
 * The schemas are written against `zod/mini`, the API that runs in Node, Vitest and the browser
 * alike (docs/architecture.md, "Validation"). Classic zod (`zod`, `zod/v4`, `zod/v3`) type-checks
 * methods mini lacks and costs ~10 KiB gzip of the first screen (docs/benchmarks.md, "First
 * screen"); a schema written in its style must be converted, not merged.
 */
export const ZOD_ENTRY = 'zod/mini';

/** Each import of zod other than `zod/mini`, in one readable line. */
export function zodImportViolations(edges: readonly ImportEdge[]): string[] {
  return edges.filter((e) => e.isPackage && e.to === 'zod' && e.spec !== ZOD_ENTRY).map((e) => `${e.from} imports '${e.spec}': write the schema against '${ZOD_ENTRY}' (z.optional(x), x.check(z.gte(0)), …)`);
}

/** The one file that parses with a schema: it gives every parse zod's English messages (mini loads no locale). */
export const PARSING_FILE = 'src/core/zodEnglish.ts';

/**
 * Each direct parse with a schema outside PARSING_FILE (`.safeParse(`, `.safeParseAsync(`, and
 * `.parse(`/`.parseAsync(` in a file that imports zod): such a parse words its issues "Invalid
 * input" where safeParseInEnglish gives zod's sentences.
 */
export function directParses(file: string, text: string): string[] {
  if (file === PARSING_FILE) return [];
  const importsZod = /from\s+['"]zod[/'"]/.test(text);
  const calls = importsZod ? /\.(safeParse|safeParseAsync|parse|parseAsync)\(/g : /\.(safeParse|safeParseAsync)\(/g;
  return [...text.matchAll(calls)].map((m) => `${file}: .${m[1]}( — use safeParseInEnglish (${PARSING_FILE})`);
}
