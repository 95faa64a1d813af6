// lib/THIRD-PARTY-NOTICES.md: the licence of every npm package the package's builds bundle
// (recorded by vite.lib.config.ts in build/bundled-*.json and by esbuild's metafile for the CLI),
// with the licence text from the installed package. Run by scripts/buildPackage.mjs; the
// repository's own third-party files are listed in THIRD-PARTY-NOTICES.md at the root.
import { existsSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const LICENCE_FILE = /^(licen[cs]e|copying)(\.(md|txt|markdown))?$/i;

/** Package names from esbuild's metafile inputs (paths under node_modules/). */
export function packagesInMetafile(metafile) {
  const names = new Set();
  for (const input of Object.keys(JSON.parse(readFileSync(metafile, 'utf8')).inputs)) {
    const m = /(?:^|\/)node_modules\/((?:@[^/]+\/)?[^/]+)/.exec(input);
    if (m) names.add(m[1]);
  }
  return names;
}

export function writeThirdPartyNotices(root, bundledBy, out) {
  const where = new Map();
  for (const [build, names] of Object.entries(bundledBy)) for (const name of names) where.set(name, [...(where.get(name) ?? []), build]);
  const sections = [...where.keys()].sort().map((name) => {
    const dir = join(root, 'node_modules', name);
    const pkg = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
    const file = readdirSync(dir).find((f) => LICENCE_FILE.test(f));
    const title = `## ${name} ${pkg.version} (${pkg.license}) — in ${where.get(name).join(', ')}\n\n`;
    if (file) return `${title}\`\`\`text\n${readFileSync(join(dir, file), 'utf8').trim()}\n\`\`\`\n`;
    // A few small packages declare their licence only in package.json: say so, with who made it and where it lives.
    if (typeof pkg.license !== 'string') throw new Error(`${name}: neither a licence file nor a licence in package.json`);
    const author = typeof pkg.author === 'string' ? pkg.author : (pkg.author?.name ?? 'not stated');
    const repository = typeof pkg.repository === 'string' ? pkg.repository : (pkg.repository?.url ?? 'not stated');
    return `${title}Licensed ${pkg.license} (its package.json; the package ships no licence text). Author: ${author}. Repository: ${repository}.\n`;
  });
  const header = [
    '# Third-party software in this package',
    '',
    'luxbox itself is MIT-licensed (LICENSE). Its builds bundle the npm packages below; each is listed with',
    'its version, licence, the builds that contain it, and the licence text it ships. The packages the',
    'ES modules import instead of bundling are ordinary dependencies with their own licences (package.json).',
    'The photometric files in lib/standalone/ies are described, with their sources, in',
    'lib/standalone/ies/SOURCES.md.',
    '',
  ];
  writeFileSync(out, `${header.join('\n')}\n${sections.join('\n')}`);
  return [...where.keys()];
}

/** The demo catalog's photometry (only the files it names) and the part of SOURCES.md that describes them. */
export function copyCatalogPhotometry(root, catalogFile, sourcesFile, outDir, copy) {
  const catalog = readFileSync(catalogFile, 'utf8');
  const names = [...new Set([...catalog.matchAll(/"ies\/([^"]+)"/g)].map((m) => m[1]))].sort();
  for (const name of names) {
    const from = join(root, 'public/ies', name);
    if (!existsSync(from)) throw new Error(`the demo catalog names ies/${name}, which public/ies lacks`);
    copy(from, join(outDir, name));
  }
  // The table rows of files not shipped are left out; the sources' licences above them stay.
  const kept = readFileSync(sourcesFile, 'utf8')
    .split('\n')
    .filter((line) => {
      const m = /^\| ([^ |]+\.(?:ies|ldt)) \|/i.exec(line);
      return !m || names.includes(m[1]);
    });
  writeFileSync(join(outDir, 'SOURCES.md'), kept.join('\n'));
  return names;
}
