import { readFileSync, readdirSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { findHardCodedText, hasWord } from './findHardCodedText';

const ROOT = join(import.meta.dirname, '../../..');

function tsxFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((d) => (d.isDirectory() ? tsxFiles(join(dir, d.name)) : d.name.endsWith('.tsx') ? [join(dir, d.name)] : []));
}

const scan = (path: string) => findHardCodedText(relative(ROOT, path), readFileSync(path, 'utf8'));

describe('no hard-coded user-visible text (docs/i18n.md)', () => {
  it('finds none in any component under src/ui and the hosts that render UI', () => {
    const files = [...tsxFiles(join(ROOT, 'src/ui')), ...tsxFiles(join(ROOT, 'src/hosts'))];
    expect(files.length).toBeGreaterThan(40);
    const found = files.flatMap(scan).map((f) => `${f.file}:${f.line} ${f.where}: ${JSON.stringify(f.text)}`);
    expect(found).toEqual([]);
  });

  it('reports every kind of literal in a fixture component (the check can fail)', () => {
    const found = scan(join(ROOT, 'tests/fixtures/i18n/HardCodedFixture.tsx'));
    expect(found.map((f) => `${f.where}: ${f.text}`)).toEqual([
      'key label: Width',
      'key hint: floor to ceiling',
      'prop aria-label: Close the panel',
      'prop title: Zoom in',
      'jsx-text: Your room',
      'prop placeholder: Search',
      'prop alt: Room preview',
      'jsx-child: Open',
      'jsx-child: Shut',
      'jsx-child: Rooms:',
      'prop emptyLabel: Nothing here',
      'call confirm: Delete everything?',
    ]);
    // Units, symbols and translated text pass: "2.5 m", "×", "{t('…')}", "ρ 0.50", "EV", "luxbox".
    expect(found.some((f) => /^(2\.5 m|×|ρ|EV|luxbox)/.test(f.text))).toBe(false);
  });

  it('tells words from units and symbols', () => {
    expect(hasWord('2.50 m')).toBe(false);
    expect(hasWord('300 lx · 12 W · 3000 K')).toBe(false);
    expect(hasWord('⤢ − + ✕')).toBe(false);
    expect(hasWord('Width (m)')).toBe(true);
    expect(hasWord('Größe')).toBe(true);
  });
});
