import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import type { RenderSummary } from '../../../src/hosts/node/renderSummary';

/**
 * `luxbox render` batches and absolute exposure (docs/viewer.md, "Shop images"):
 * several scene files × several cameras in one process with the programs
 * linked once, per-file failures that do not stop the batch, and --ev: a
 * fixed EV100 shows a dimmed configuration darker by exactly its dimming.
 */
const ROOT = join(__dirname, '../../..');
const OUT = mkdtempSync(join(tmpdir(), 'luxbox-batch-'));
const CONFIG = 'tests/fixtures/configurations/corner-l.luxbox.json';
const CHEAP = ['--width', '96', '--height', '64', '--samples', '4', '--bounces', '1'];

function render(args: string[]): { status: number | null; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, [join(ROOT, 'bin/luxbox.js'), 'render', ...args], { cwd: ROOT, encoding: 'utf8', timeout: 240_000 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

/** corner-l with every module at `dimming` (0..1), written next to the outputs. */
function dimmedConfig(dimming: number, name: string): string {
  const data = JSON.parse(readFileSync(join(ROOT, CONFIG), 'utf8'));
  for (const system of data.configuration.systems) for (const rail of system.rails) for (const m of rail.modules) m.dimming = dimming;
  const file = join(OUT, name);
  writeFileSync(file, JSON.stringify(data));
  return file;
}

const read = (file: string) => PNG.sync.read(readFileSync(file));

function mean(img: PNG): number {
  let s = 0;
  for (let i = 0; i < img.data.length; i += 4) s += img.data[i] + img.data[i + 1] + img.data[i + 2];
  return s / (3 * img.width * img.height);
}

describe('luxbox render batch', () => {
  it('scenes × cameras in one process: one PNG each, summary.json, programs linked for the first scene only, a bad file reported without stopping the batch', () => {
    const dir = join(OUT, 'batch');
    const cams = join(OUT, 'cameras.json');
    writeFileSync(cams, JSON.stringify({ detail: { position: [1, 1.5, 3.5], target: [2.5, 0.5, 1.5], fov: 50 } }));
    const missing = join(OUT, 'missing.luxbox.json');
    const r = render([CONFIG, missing, dimmedConfig(0.5, 'half.luxbox.json'), 'tests/fixtures/scenes/small-room.json', '--camera', 'eye', '--camera', 'top', '--cameras', cams, '--ev', '6', '--out', dir + '/', ...CHEAP]);
    expect(r.status).toBe(1);
    expect(r.stderr.trim().split('\n')).toEqual([expect.stringMatching(/missing\.luxbox\.json: .*cannot read .*no such file/)]);
    const summary = JSON.parse(readFileSync(join(dir, 'summary.json'), 'utf8')) as RenderSummary;
    expect(summary.failed).toEqual([{ file: missing, error: expect.stringMatching(/no such file/) }]);
    expect(summary.exposure).toEqual({ mode: 'fixed', ev100: 6 });
    expect(summary.cameras.map((c) => c.name)).toEqual(['eye', 'top', 'detail']);
    const expected = ['corner-l', 'half', 'small-room'].flatMap((s) => ['eye', 'top', 'detail'].map((c) => `${s}-${c}.png`));
    expect(summary.images.map((i) => i.image)).toEqual(expected);
    expect(readdirSync(dir).sort()).toEqual([...expected, 'summary.json'].sort());
    for (const name of expected) expect([read(join(dir, name)).width, read(join(dir, name)).height]).toEqual([96, 64]);
    // Every image at the fixed EV100.
    for (const image of summary.images) expect(image.ev100).toBeCloseTo(6, 9);
    // The view's (three.js) programs: linked for the first scene only, also for the lighting scene of another kind.
    const after = summary.programs_linked_after_scene;
    expect(after).toHaveLength(3);
    expect(after[0].view).toBeGreaterThanOrEqual(2);
    expect(after.map((a) => a.view)).toEqual([after[0].view, after[0].view, after[0].view]);
    // The baker's: the dimmed configuration (same lamps) links none; the small room's other lamps link their own variants.
    expect(after[0].baker).toBeGreaterThan(5);
    expect(after[1].baker).toBe(after[0].baker);
    expect(summary.programs_linked).toEqual(after[2]);
    // Half the light on the floor: the relight is linear in the dimming (same bake noise, same bases).
    const floorOf = (scene: string) => summary.images.find((i) => i.scene === scene)!.floor.avg;
    expect(floorOf('half') / floorOf('corner-l')).toBeCloseTo(0.5, 3);
  });

  it('a fixed EV100 shows dimming: 50 % dimmed at EV e equals full light at EV e + 1 (pixel for pixel), and is darker than full light at EV e; auto exposure hides it', () => {
    const dir = join(OUT, 'ev');
    mkdirSync(dir);
    const full = CONFIG;
    const half = dimmedConfig(0.5, 'half.luxbox.json');
    // Luminance × exposure is what the display curve sees: L/2 · 1/(1.2·2^e) = L · 1/(1.2·2^(e+1)).
    // Without colour adaptation: under `eye` the degree of adaptation D follows the scene's own L_A,
    // which halves with the light, and the glowing emitters (full chroma at the top of the curve) show
    // that as 2 levels of blue (docs/viewer.md, "Luminaires").
    const none = ['--adapt', 'none'];
    expect(render([full, '--ev', '7', '--camera', 'eye', ...none, '--out', join(dir, 'full-ev7.png'), ...CHEAP]).status).toBe(0);
    expect(render([full, '--ev', '6', '--camera', 'eye', ...none, '--out', join(dir, 'full-ev6.png'), ...CHEAP]).status).toBe(0);
    expect(render([half, '--ev', '6', '--camera', 'eye', ...none, '--out', join(dir, 'half-ev6.png'), ...CHEAP]).status).toBe(0);
    expect(render([full, '--camera', 'eye', '--out', join(dir, 'full-auto.png'), ...CHEAP]).status).toBe(0);
    expect(render([half, '--camera', 'eye', '--out', join(dir, 'half-auto.png'), ...CHEAP]).status).toBe(0);
    const a = read(join(dir, 'full-ev7.png'));
    const b = read(join(dir, 'half-ev6.png'));
    let worst = 0;
    for (let i = 0; i < a.data.length; i++) worst = Math.max(worst, Math.abs(a.data[i] - b.data[i]));
    // Same value into the same curve: equal up to float rounding (1 level of 255).
    expect(worst).toBeLessThanOrEqual(1);
    const fullEv6 = mean(read(join(dir, 'full-ev6.png')));
    expect(mean(b)).toBeLessThan(fullEv6 - 10);
    expect(mean(b)).toBeGreaterThan(10); // not black
    // Auto exposure maps both to the same key: the dimmed one looks the same (what a shop must not get).
    expect(Math.abs(mean(read(join(dir, 'half-auto.png'))) - mean(read(join(dir, 'full-auto.png'))))).toBeLessThanOrEqual(1);
  });

  it('bad exposure and camera arguments: one line, exit 1, no image', () => {
    const out = join(OUT, 'never.png');
    const cams = join(OUT, 'bad-cameras.json');
    writeFileSync(cams, JSON.stringify({ 'bad name': 'eye' }));
    const bad: [string[], RegExp][] = [
      [[CONFIG, '--out', out, '--ev', '99'], /--ev must be an EV100 in -6\.\.20/],
      [[CONFIG, '--out', out, '--ev', '5', '--exposure', '1'], /either --ev .* or --exposure/],
      [[CONFIG, '--out', out, '--cameras', cams], /camera name "bad name"/],
      [[CONFIG, '--out', out, '--camera', 'eye', '--camera', 'eye,top', '--cameras', join(OUT, 'nope.json')], /--cameras .*nope\.json: cannot read/],
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
