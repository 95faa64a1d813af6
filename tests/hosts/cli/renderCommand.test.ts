import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import pixelmatch from 'pixelmatch';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';

/**
 * Golden images through the command line (`luxbox render`, three.js on
 * headless-gl). Tolerance: pixelmatch threshold 0.1 per pixel (YIQ distance),
 * at most 0.5 % of the pixels may differ. On failure the actual image and a
 * diff image are written to test-results/goldens/. LUXBOX_UPDATE_GOLDENS=1
 * rewrites the goldens (review them before committing).
 */
const ROOT = join(__dirname, '../../..');
const GOLDENS = join(ROOT, 'tests/goldens');
const OUT = mkdtempSync(join(tmpdir(), 'luxbox-render-'));
const MAX_DIFF_RATIO = 0.005;
const update = process.env.LUXBOX_UPDATE_GOLDENS === '1';

function render(args: string[]): { status: number | null; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, [join(ROOT, 'bin/luxbox.js'), 'render', ...args], { cwd: ROOT, encoding: 'utf8', timeout: 120_000 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

function compareGolden(name: string, file: string): void {
  const golden = join(GOLDENS, name);
  if (update || !existsSync(golden)) {
    if (!update) throw new Error(`golden ${name} is missing: run with LUXBOX_UPDATE_GOLDENS=1 and review it`);
    writeFileSync(golden, readFileSync(file));
    return;
  }
  const actual = PNG.sync.read(readFileSync(file));
  const expected = PNG.sync.read(readFileSync(golden));
  expect([actual.width, actual.height]).toEqual([expected.width, expected.height]);
  const diff = new PNG({ width: actual.width, height: actual.height });
  const differing = pixelmatch(actual.data, expected.data, diff.data, actual.width, actual.height, { threshold: 0.1 });
  const ratio = differing / (actual.width * actual.height);
  if (ratio > MAX_DIFF_RATIO) {
    const dir = join(ROOT, 'test-results/goldens');
    mkdirSync(dir, { recursive: true });
    writeFileSync(join(dir, name.replace('.png', '.actual.png')), readFileSync(file));
    writeFileSync(join(dir, name.replace('.png', '.diff.png')), PNG.sync.write(diff));
  }
  expect(ratio, `${name}: ${differing} pixels differ (diff in test-results/goldens/)`).toBeLessThanOrEqual(MAX_DIFF_RATIO);
}

function meanLevel(file: string): number {
  const img = PNG.sync.read(readFileSync(file));
  let s = 0;
  for (let i = 0; i < img.data.length; i += 4) s += (img.data[i] + img.data[i + 1] + img.data[i + 2]) / 3;
  return s / (img.width * img.height);
}

const cases: { name: string; args: string[] }[] = [
  { name: 'render-corner-l-corner.png', args: ['tests/fixtures/configurations/corner-l.luxbox.json', '--camera', 'corner'] },
  { name: 'render-corner-l-eye.png', args: ['tests/fixtures/configurations/corner-l.luxbox.json', '--camera', 'eye', '--exposure', '0.5'] },
  { name: 'render-small-room-top-lux.png', args: ['tests/fixtures/scenes/small-room.json', '--camera', 'top', '--mode', 'lux'] },
];

describe('luxbox render (golden images)', () => {
  for (const c of cases) {
    it(`${c.name} matches its golden`, () => {
      const file = join(OUT, c.name);
      const r = render([...c.args, '--out', file, '--width', '320', '--height', '200']);
      expect(r.stderr).toBe('');
      expect(r.status).toBe(0);
      expect(r.stdout).toMatch(/floor Ē [\d.]+ lx/);
      expect(meanLevel(file)).toBeGreaterThan(20); // not black
      compareGolden(c.name, file);
    });
  }

  it('exposure compensation brightens the image (one stop up is brighter than auto)', () => {
    const a = join(OUT, 'ev0.png');
    const b = join(OUT, 'ev1.png');
    const common = ['tests/fixtures/configurations/corner-l.luxbox.json', '--camera', 'eye', '--width', '96', '--height', '64', '--samples', '4', '--bounces', '1'];
    expect(render([...common, '--out', a]).status).toBe(0);
    expect(render([...common, '--out', b, '--exposure', '1']).status).toBe(0);
    expect(meanLevel(b)).toBeGreaterThan(meanLevel(a) + 5);
  });

  it('--adapt: the warm room is most orange with none, neutral with camera white balance at its CCT, in between with eye (default)', () => {
    const common = ['tests/fixtures/configurations/corner-l.luxbox.json', '--camera', 'eye', '--width', '96', '--height', '64', '--samples', '4', '--bounces', '1'];
    const warmth = (args: string[]) => {
      const file = join(OUT, `adapt-${args.join('-').replace(/[^a-z0-9]/gi, '')}.png`);
      const r = render([...common, '--out', file, ...args]);
      expect(r.stderr).toBe('');
      expect(r.status).toBe(0);
      const img = PNG.sync.read(readFileSync(file));
      let s = 0;
      for (let i = 0; i < img.data.length; i += 4) s += img.data[i] - img.data[i + 2];
      return s / (img.width * img.height);
    };
    const none = warmth(['--adapt', 'none']);
    const eye = warmth([]);
    const camera = warmth(['--adapt', 'camera:3000']);
    // corner-l's modules are 3000 K: the physical colour is strongly orange (R − B ≈ 100 of 255 on lit walls).
    expect(none).toBeGreaterThan(40);
    expect(eye).toBeLessThan(none - 20);
    expect(eye).toBeGreaterThan(camera);
    expect(Math.abs(camera)).toBeLessThan(6);
  });

  it('bad input: one line on stderr naming the problem, exit 1, no image', () => {
    const out = join(OUT, 'never.png');
    const bad: [string[], RegExp][] = [
      [['tests/fixtures/configurations/corner-l.luxbox.json', '--out', out, '--camera', '{"position":[1,2]}'], /--camera: position must be three/],
      [['tests/fixtures/configurations/corner-l.luxbox.json', '--out', out, '--width', '0'], /--width must be an integer/],
      [['tests/fixtures/configurations/corner-l.luxbox.json', '--out', out, '--mode', 'xray'], /--mode must be light or lux/],
      [['tests/fixtures/configurations/corner-l.luxbox.json', '--out', out, '--adapt', 'camera:500'], /--adapt must be eye, none or camera:<K> with K in 1000..20000, got "camera:500"/],
      [['tests/fixtures/configurations/corner-l.luxbox.json'], /--out <image.png> is required/],
      [['tests/fixtures/configurations/missing.json', '--out', out], /cannot read .*no such file/],
    ];
    for (const [args, message] of bad) {
      const r = render(args);
      expect(r.status).toBe(1);
      expect(r.stderr).toMatch(message);
      expect(r.stderr.trim().split('\n')).toHaveLength(1);
    }
    expect(existsSync(out)).toBe(false);
  });
});
