/**
 * Headless GL back ends (issue 17, docs/gpu-server.md): ANGLE's Vulkan back
 * end needs no X display and must give the same light maps as GLX; batches
 * bake on one context with each shader compiled once and give exactly the
 * maps of single bakes; report.json states the read-backs a bake made. CI
 * has no GPU: both back ends run on Mesa's software drivers here (lavapipe,
 * llvmpipe), which setup.sh installs.
 */
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import { batchFolderNames } from '../../../src/hosts/node/batchFolderNames';
import { ensureVulkanLoader, parseGlChoice, selectGlBackend, vulkanDrivers } from '../../../src/hosts/node/glBackend';
import { decodePfm } from '../../../src/hosts/node/writePfm';

const root = join(__dirname, '../../..');
const scene = join(root, 'tests/fixtures/scenes/small-room.json');
const quick = ['--texel', '0.1', '--samples', '16', '--bounces', '2'];
const out = mkdtempSync(join(tmpdir(), 'luxbox-gl-'));

/** A PATH with nothing on it but node (no xvfb-run, whatever folder node lives in). */
const bareBin = mkdtempSync(join(tmpdir(), 'luxbox-bin-'));
symlinkSync(process.execPath, join(bareBin, 'node'));

/** The CLI with no DISPLAY at all and no xvfb-run reachable. */
function luxboxNoX(args: string[]) {
  const env: NodeJS.ProcessEnv = { ...process.env, PATH: bareBin };
  delete env.DISPLAY;
  delete env.LUXBOX_GL;
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, env, encoding: 'utf8', timeout: 180_000 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

function luxbox(args: string[]) {
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, encoding: 'utf8', timeout: 180_000 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

function maps(dir: string) {
  return Object.fromEntries(SURFACE_NAMES.flatMap((n) => ['direct', 'indirect', 'total'].map((k) => [`${n}.${k}`, decodePfm(readFileSync(join(dir, `${n}.${k}.pfm`))).rgb])));
}

describe('GL back ends', () => {
  it('Vulkan with no X display and no xvfb-run equals GLX within 1e-4 relative, every texel of every map', () => {
    const vk = luxboxNoX(['bake', scene, '--out', join(out, 'vk'), '--gl', 'vulkan', ...quick]);
    expect(vk.stderr).toBe('');
    expect(vk.status).toBe(0);
    expect(vk.stdout).toContain('gl vulkan');
    const glx = luxbox(['bake', scene, '--out', join(out, 'glx'), '--gl', 'glx', ...quick]);
    expect(glx.status).toBe(0);
    expect(glx.stdout).toContain('gl glx');
    const a = maps(join(out, 'vk'));
    const b = maps(join(out, 'glx'));
    let worst = 0;
    for (const key of Object.keys(b)) {
      const peak = Math.max(...b[key]);
      expect(a[key].length).toBe(b[key].length);
      for (let i = 0; i < b[key].length; i++) {
        // Relative to the texel, with a floor of 1e-6 of the map's peak for texels near zero.
        worst = Math.max(worst, Math.abs(a[key][i] - b[key][i]) / Math.max(Math.abs(b[key][i]), 1e-6 * peak, 1e-12));
      }
    }
    expect(worst).toBeLessThan(1e-4);
    const report = JSON.parse(readFileSync(join(out, 'vk', 'report.json'), 'utf8'));
    expect(report.gl).toBe('vulkan');
  });

  it('auto without hardware Vulkan: GLX with a display or xvfb-run, software Vulkan only when neither is there', () => {
    const saved = { DISPLAY: process.env.DISPLAY, PATH: process.env.PATH };
    const hardware = vulkanDrivers().hardwareManifests.length > 0 && vulkanDrivers().deviceNode;
    try {
      process.env.DISPLAY = ':99';
      if (!hardware) expect(selectGlBackend('auto').backend).toBe('glx');
      delete process.env.DISPLAY;
      process.env.PATH = bareBin;
      if (!hardware && vulkanDrivers().manifests.length > 0 && ensureVulkanLoader()) expect(selectGlBackend('auto').backend).toBe('vulkan');
    } finally {
      for (const [k, v] of Object.entries(saved)) {
        if (v === undefined) delete process.env[k];
        else process.env[k] = v;
      }
    }
  });

  it('a hardware ICD manifest counts only with a device node; lavapipe never counts', () => {
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-icd-'));
    writeFileSync(join(dir, 'nvidia_icd.json'), JSON.stringify({ ICD: { library_path: 'libGLX_nvidia.so.0' } }));
    writeFileSync(join(dir, 'lvp_icd.x86_64.json'), JSON.stringify({ ICD: { library_path: '/usr/lib/x86_64-linux-gnu/libvulkan_lvp.so' } }));
    const saved = process.env.VK_DRIVER_FILES;
    try {
      process.env.VK_DRIVER_FILES = dir;
      const d = vulkanDrivers();
      expect(d.manifests).toHaveLength(2);
      expect(d.hardwareManifests).toEqual([join(dir, 'nvidia_icd.json')]);
    } finally {
      if (saved === undefined) delete process.env.VK_DRIVER_FILES;
      else process.env.VK_DRIVER_FILES = saved;
    }
  });

  it('the loader link is made where ANGLE looks, and a real file there is left alone', () => {
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-release-'));
    const linked = ensureVulkanLoader(dir);
    if (linked) expect(readFileSync(linked).length).toBeGreaterThan(0);
    const packed = mkdtempSync(join(tmpdir(), 'luxbox-packed-'));
    writeFileSync(join(packed, 'libvulkan.so.1'), 'shipped');
    expect(ensureVulkanLoader(packed)).toBe(join(packed, 'libvulkan.so.1'));
    expect(readFileSync(join(packed, 'libvulkan.so.1'), 'utf8')).toBe('shipped');
  });

  it('--gl and $LUXBOX_GL accept vulkan, glx, auto; anything else is one clear line', () => {
    expect(parseGlChoice('Vulkan', '--gl')).toBe('vulkan');
    expect(parseGlChoice(undefined, '$LUXBOX_GL')).toBe('auto');
    expect(() => parseGlChoice('metal', '--gl')).toThrow('--gl must be vulkan, glx or auto, got "metal"');
    const r = luxbox(['bake', scene, '--out', join(out, 'bad'), '--gl', 'metal']);
    expect(r.status).toBe(1);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain('--gl must be vulkan, glx or auto');
  });
});

describe('batches', () => {
  it('bake a.json b.json: one folder each, exactly the maps of single bakes, each shader compiled once', () => {
    // Two scenes: the small room, and the same file under another folder name (same shaders: 0 new compiles).
    const other = join(out, 'copy');
    mkdirSync(other, { recursive: true });
    const text = JSON.parse(readFileSync(scene, 'utf8'));
    text.luminaires = text.luminaires.map((l: { photometry: string }) => ({ ...l, photometry: join(root, 'tests/fixtures/scenes', l.photometry) }));
    text.room.reflectance.floor = 0.35;
    writeFileSync(join(other, 'small-room.json'), JSON.stringify(text));
    const batch = luxboxNoX(['bake', scene, join(other, 'small-room.json'), '--out', join(out, 'batch'), ...quick]);
    expect(batch.stderr).toBe('');
    expect(batch.status).toBe(0);
    expect(batchFolderNames([scene, join(other, 'small-room.json')])).toEqual(['small-room', 'small-room-2']);
    const single = luxboxNoX(['bake', join(other, 'small-room.json'), '--out', join(out, 'single'), ...quick]);
    expect(single.status).toBe(0);
    const a = maps(join(out, 'batch', 'small-room-2'));
    const b = maps(join(out, 'single'));
    for (const key of Object.keys(b)) expect(Buffer.from(a[key].buffer).equals(Buffer.from(b[key].buffer))).toBe(true);
    const first = JSON.parse(readFileSync(join(out, 'batch', 'small-room', 'report.json'), 'utf8'));
    const second = JSON.parse(readFileSync(join(out, 'batch', 'small-room-2', 'report.json'), 'utf8'));
    expect(first.batch.programsCompiled).toBeGreaterThan(0);
    // Only the gather shaders differ (they encode the reflectances); direct and fixed passes are reused.
    expect(second.batch.programsCompiled).toBeLessThan(first.batch.programsCompiled);
    // 18 map read-backs (6 surfaces × direct, indirect, total) + the stats row + the bright-patch
    // summary texel (the report's; the patches are chosen on the GPU), nothing during the bake.
    expect(first.bake.readbacks.count).toBe(20);
  });

  it('render over scenes × cameras in one process gives the images of single renders', () => {
    const corner = join(root, 'tests/fixtures/configurations/corner-l.luxbox.json');
    const size = ['--width', '160', '--height', '100', '--samples', '16', '--bounces', '1', '--texel', '0.2'];
    const batch = luxboxNoX(['render', corner, '--camera', 'eye,top', '--out', join(out, 'renders'), ...size]);
    expect(batch.stderr).toBe('');
    expect(batch.status).toBe(0);
    const single = luxboxNoX(['render', corner, '--camera', 'top', '--out', join(out, 'top.png'), ...size]);
    expect(single.status).toBe(0);
    const a = PNG.sync.read(readFileSync(join(out, 'renders', 'corner-l-top.png')));
    const b = PNG.sync.read(readFileSync(join(out, 'top.png')));
    expect(a.data.equals(b.data)).toBe(true);
    const eye = PNG.sync.read(readFileSync(join(out, 'renders', 'corner-l-eye.png')));
    expect(eye.data.equals(a.data)).toBe(false);
  });
});
