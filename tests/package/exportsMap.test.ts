// The package's shape without building it (scripts/checkPackage.mjs builds, packs, installs and
// opens the real thing; it takes minutes): every door of the exports map has an ES module and
// declarations under lib/, built from an entry of vite.lib.config.ts and checked by an API report;
// what the builds leave as imports is exactly what package.json declares; nothing runs at a shop's
// install. docs/package.md.
import { existsSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { UserConfig } from 'vite';
import libConfig, { DEPENDENCIES } from '../../vite.lib.config';
// @ts-expect-error: a plain .mjs script without declarations
import { DOORS } from '../../scripts/packageApi.mjs';

interface PackageJson {
  exports: Record<string, string | { types: string; import: string }>;
  files: string[];
  sideEffects: string[];
  scripts: Record<string, string>;
  bin: Record<string, string>;
  dependencies: Record<string, string>;
  optionalDependencies: Record<string, string>;
  peerDependencies: Record<string, string>;
  peerDependenciesMeta: Record<string, { optional: boolean }>;
  devDependencies: Record<string, string>;
  license: string;
  private?: boolean;
}
const pkg: PackageJson = JSON.parse(readFileSync('package.json', 'utf8'));
const doors = DOORS as Record<string, string>;

function libEntries(mode: string): Record<string, string> {
  const saved = process.env.LUXBOX_LIB;
  process.env.LUXBOX_LIB = mode;
  try {
    const config = (libConfig as () => UserConfig)();
    const lib = config.build!.lib as { entry: Record<string, string> };
    return lib.entry;
  } finally {
    if (saved === undefined) delete process.env.LUXBOX_LIB;
    else process.env.LUXBOX_LIB = saved;
  }
}

describe('package.json exports map', () => {
  const conditional = Object.entries(pkg.exports).filter((e): e is [string, { types: string; import: string }] => typeof e[1] === 'object');

  it('has the four doors the issue names, each an ES module with its own declarations in lib/', () => {
    expect(conditional.map(([path]) => path).sort()).toEqual(['.', './element', './engine', './react']);
    for (const [path, target] of conditional) {
      const door = path === '.' ? 'luxbox' : path.slice(2);
      expect(target).toEqual({ types: `./lib/${door}.d.ts`, import: `./lib/${door}.js` });
    }
    expect(pkg.exports['./standalone/*']).toBe('./lib/standalone/*');
  });

  it('builds each door from an entry of vite.lib.config.ts whose source exists, and reports its API', () => {
    const entries = { ...libEntries('preact'), ...libEntries('react') };
    expect(Object.keys(entries).sort()).toEqual(Object.keys(doors).sort());
    for (const [door, source] of Object.entries(entries)) {
      expect(existsSync(source), source).toBe(true);
      expect(source.endsWith(`src/hosts/package/${doors[door]}.${door === 'react' ? 'tsx' : 'ts'}`)).toBe(true);
      expect(existsSync(`docs/api/${door}.api.md`), `docs/api/${door}.api.md`).toBe(true);
    }
    expect(Object.keys(libEntries('script'))).toEqual(['luxbox-element']);
  });

  it('ships lib/, the bin and the licence texts, and is publishable', () => {
    expect(pkg.private).toBeUndefined();
    expect(pkg.license).toBe('MIT');
    expect(pkg.files).toEqual(expect.arrayContaining(['lib', 'bin/luxbox.js', 'LICENSE', 'THIRD-PARTY-NOTICES.md', 'CHANGELOG.md']));
    for (const file of ['LICENSE', 'THIRD-PARTY-NOTICES.md', 'CHANGELOG.md', pkg.bin.luxbox]) expect(existsSync(file), file).toBe(true);
  });

  it('marks the element (it registers <luxbox-configurator>) and the chunks (they inject styles, register texts) as side effects, not the main door or the engine', () => {
    expect(pkg.sideEffects).toEqual(expect.arrayContaining(['./lib/element.js', './lib/chunks/*.js', './lib/standalone/**']));
    expect(pkg.sideEffects).not.toContain('./lib/luxbox.js');
    expect(pkg.sideEffects).not.toContain('./lib/engine.js');
  });

  it("keeps the repository's own sources side-effectful: bundlers apply sideEffects to this package's files too, and the app's and the library's builds import modules for their effects (registrations, styles, customElements.define)", () => {
    expect(pkg.sideEffects).toContain('./src/**');
  });
});

describe('package.json dependencies', () => {
  const packageOf = (specifier: string) => (specifier.startsWith('@') ? specifier.split('/').slice(0, 2).join('/') : specifier.split('/')[0]);

  it('declares exactly what the library builds leave as imports; React is an optional peer', () => {
    expect(Object.keys(pkg.dependencies).sort()).toEqual([...new Set(DEPENDENCIES.map(packageOf))].sort());
    expect(Object.keys(pkg.peerDependencies).sort()).toEqual(['react', 'react-dom']);
    expect(pkg.peerDependenciesMeta).toEqual({ react: { optional: true }, 'react-dom': { optional: true } });
    // The React build's externals are the same plus the peers (vite.lib.config.ts); React is never a dependency.
    expect(pkg.dependencies.react).toBeUndefined();
    expect(pkg.dependencies['react-dom']).toBeUndefined();
  });

  it('pins dependencies to the versions the repository tests (devDependencies hold the same React)', () => {
    for (const [name, version] of Object.entries(pkg.dependencies)) expect(version, name).toMatch(/^\d+\.\d+\.\d+/);
    expect(pkg.devDependencies.react).toBeDefined();
  });

  it('keeps headless-gl (a native build for the CLI only) optional', () => {
    expect(Object.keys(pkg.optionalDependencies)).toEqual(['gl']);
  });

  it('runs nothing when a shop installs it (no preinstall, install or postinstall)', () => {
    for (const hook of ['preinstall', 'install', 'postinstall']) expect(pkg.scripts[hook], hook).toBeUndefined();
  });
});
