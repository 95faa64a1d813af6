/**
 * Live control end to end (docs/live-control.md): the real DMX bridge
 * (`node bin/luxbox.js dmx`, docs/dmx.md) started from the spec, a test console
 * sending sACN (E1.31) packets built by hand on the loopback interface, and the
 * 3D view relighting from them without a bake, the configuration and its undo
 * history untouched.
 */
import { spawn, type ChildProcess } from 'node:child_process';
import { createSocket } from 'node:dgram';
import { createServer } from 'node:net';
import { expect, test, type Page } from '@playwright/test';
import { viewerStatus as status } from './helpers';

test.use({ reducedMotion: 'reduce', viewport: { width: 1280, height: 800 } });

const getConfig = (page: Page): Promise<string> => page.evaluate(() => window.luxbox!.getConfig());

/** A TCP port nothing listens on (bound, then released). */
function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const s = createServer();
    s.once('error', reject);
    s.listen(0, '127.0.0.1', () => {
      const { port } = s.address() as { port: number };
      s.close(() => resolve(port));
    });
  });
}

interface Bridge {
  process: ChildProcess;
  wsPort: number;
  sacnPort: number;
}

/** `luxbox dmx` with sACN only, on loopback, free ports; resolves once it prints where it listens. */
function startBridge(): Promise<Bridge> {
  return new Promise((resolve, reject) => {
    const child = spawn(process.execPath, ['bin/luxbox.js', 'dmx', '--sacn', '--sacn-port', '0', '--port', '0', '--bind', '127.0.0.1'], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    let err = '';
    const timer = setTimeout(() => reject(new Error(`luxbox dmx did not start: ${err}`)), 30_000);
    child.stderr!.on('data', (d: Buffer) => (err += d.toString()));
    child.stdout!.on('data', (d: Buffer) => {
      out += d.toString();
      const ws = /WebSocket ws:\/\/127\.0\.0\.1:(\d+)/.exec(out);
      const sacn = /sACN\s+udp 127\.0\.0\.1:(\d+)/.exec(out);
      if (ws && sacn) {
        clearTimeout(timer);
        resolve({ process: child, wsPort: Number(ws[1]), sacnPort: Number(sacn[1]) });
      }
    });
    child.once('exit', (code) => reject(new Error(`luxbox dmx exited (${code}): ${err}`)));
  });
}

/**
 * An E1.31-2018 data packet with 512 slots (638 bytes), laid out by hand from the
 * standard: root layer (§5), framing layer (§6), DMP layer (§7).
 */
function e131Packet(universe: number, sequence: number, slots: Uint8Array): Buffer {
  const b = Buffer.alloc(638);
  b.writeUInt16BE(0x0010, 0); // preamble size
  b.writeUInt16BE(0x0000, 2); // post-amble size
  Buffer.from('ASC-E1.17\0\0\0', 'latin1').copy(b, 4); // ACN packet identifier
  b.writeUInt16BE(0x7000 | (638 - 16), 16); // flags and length
  b.writeUInt32BE(0x00000004, 18); // VECTOR_ROOT_E131_DATA
  Buffer.alloc(16, 0x5a).copy(b, 22); // CID
  b.writeUInt16BE(0x7000 | (638 - 38), 38);
  b.writeUInt32BE(0x00000002, 40); // VECTOR_E131_DATA_PACKET
  Buffer.from('luxbox e2e console', 'utf8').copy(b, 44); // source name, 64 bytes, NUL padded
  b[108] = 100; // priority
  b.writeUInt16BE(0, 109); // synchronization address
  b[111] = sequence & 0xff;
  b[112] = 0; // options
  b.writeUInt16BE(universe, 113);
  b.writeUInt16BE(0x7000 | (638 - 115), 115);
  b[117] = 0x02; // VECTOR_DMP_SET_PROPERTY
  b[118] = 0xa1; // address type and data type
  b.writeUInt16BE(0x0000, 119); // first property address
  b.writeUInt16BE(0x0001, 121); // address increment
  b.writeUInt16BE(513, 123); // property value count: start code + 512 slots
  b[125] = 0x00; // DMX start code
  Buffer.from(slots).copy(b, 126);
  return b;
}

/** A console on universe 1: resends its current look every 100 ms, as consoles refresh (and sACN sources must, E1.31 §6.7.1). */
function startConsole(sacnPort: number) {
  const socket = createSocket('udp4');
  const slots = new Uint8Array(512);
  let sequence = 0;
  const send = () => socket.send(e131Packet(1, ++sequence, slots), sacnPort, '127.0.0.1');
  const timer = setInterval(send, 100);
  return {
    set(values: Record<number, number>) {
      for (const [channel, v] of Object.entries(values)) slots[Number(channel) - 1] = v;
      send();
    },
    stop() {
      clearInterval(timer);
      socket.close();
    },
  };
}

let bridge: Bridge | null = null;
let console_: ReturnType<typeof startConsole> | null = null;

test.afterEach(() => {
  console_?.stop();
  console_ = null;
  bridge?.process.kill('SIGTERM');
  bridge = null;
});

test('a console dims a module through the real bridge: the 3D view relights live, no bake, configuration and undo history untouched', async ({ page }) => {
  bridge = await startBridge();
  console_ = startConsole(bridge.sacnPort);

  // Lux values at a fixed bake quality (docs/viewer.md, "Quality levels"): `fast`, since every check compares the
  // floor with the same bake's own numbers; live control is an expert tool.
  await page.goto('/?quality=fast&expert=1');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-corner-l').click();
  await expect.poll(async () => JSON.parse(await getConfig(page)).configuration.systems.length).toBe(1);
  const placed = await getConfig(page);
  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
  const baked = await status(page);
  expect(baked.groupBakes).toBe(6);
  expect(baked.live).toBeNull();

  // Off by default; on, with a port nothing listens on: "no bridge", and the view says so.
  await expect(page.getByTestId('live-on')).not.toBeChecked();
  await page.getByTestId('live-on').check();
  const nobody = await freePort();
  await page.getByTestId('live-port').fill(String(nobody));
  await page.getByTestId('live-port').press('Enter');
  await expect(page.getByTestId('live-state')).toHaveAttribute('data-state', 'no-bridge', { timeout: 15_000 });
  await expect(page.getByTestId('live-state')).toContainText(`ws://127.0.0.1:${nobody}`);

  // Auto-patch: 8-bit with a CCT channel, from 1/1 (corner-l: six tunable modules, two channels each).
  await page.getByTestId('autopatch').click();
  const patchedText = await getConfig(page);
  const patched = JSON.parse(patchedText);
  const modules = patched.configuration.systems[0].rails.flatMap((r: { modules: { id: string; dmx: unknown }[] }) => r.modules);
  expect(modules.map((m: { dmx: unknown }) => m.dmx)).toEqual([1, 3, 5, 7, 9, 11].map((address) => ({ universe: 1, address, resolution: 8, cct: true })));
  expect(patched.version).toBe(10); // scene file version 10 (daylight) still carries the DMX patch of version 2
  // The patch is part of the configuration, but only a relight (nothing about the light changed).
  await expect.poll(async () => (await status(page)).relightsOnly).toBeGreaterThan(baked.relightsOnly);
  expect((await status(page)).groupBakes).toBe(6);

  // Every module full, at its own CCT's channel value: the console's look.
  const full: Record<number, number> = {};
  for (let k = 0; k < 6; k++) {
    full[2 * k + 1] = 255;
    full[2 * k + 2] = 59; // ≈ 3000 K on the 2700–4000 K range
  }
  console_.set(full);
  await page.getByTestId('live-port').fill(String(bridge.wsPort));
  await page.getByTestId('live-port').press('Enter');
  await expect(page.getByTestId('live-state')).toHaveAttribute('data-state', 'connected', { timeout: 15_000 });
  await expect(page.getByTestId('live-state')).toContainText(/sACN · universe 1 · 1 source/, { timeout: 10_000 });
  await expect.poll(async () => (await status(page)).live?.applied ?? 0).toBeGreaterThan(0);
  await expect(page.getByTestId(`live-${modules[0].id}`)).toHaveText(/^100% · 30\d\d K$/);
  const atFull = await status(page);
  // Grey finishes: a CCT at unit luminance leaves the floor's illuminance (photometric Y) as it was.
  expect(atFull.floor!.avg).toBeCloseTo(baked.floor!.avg, 0);

  // The console dims the first module to 20 %: the floor darkens at once, without any bake.
  console_.set({ 1: 51 });
  await expect(page.getByTestId(`live-${modules[0].id}`)).toHaveText(/^20% · /);
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 10_000 }).toBeLessThan(atFull.floor!.avg * 0.97);
  const dimmed = await status(page);
  expect(dimmed.groupBakes).toBe(6);
  expect(dimmed.lastRelightMs).not.toBeNull();
  // Relit, not rebaked: the engine's relight counter is published with the next progress report,
  // which may come after the floor's statistics (from the view's GPU), so it is awaited.
  await expect.poll(async () => (await status(page)).relightsOnly, { timeout: 10_000 }).toBeGreaterThan(atFull.relightsOnly);
  // A fader move faster than the view: 40 levels in a burst. Only the latest frame counts, applied
  // at most once per animation frame, so the view ends at the last level with no backlog.
  for (let v = 60; v < 100; v++) console_.set({ 3: v });
  await expect(page.getByTestId(`live-${modules[1].id}`)).toHaveText(/^39% · /); // 99/255
  const burst = await status(page);
  expect(burst.live!.received - dimmed.live!.received).toBeGreaterThanOrEqual(2);
  expect(burst.live!.applied - dimmed.live!.applied).toBeLessThan(burst.live!.received - dimmed.live!.received);
  expect(burst.groupBakes).toBe(6);
  // The stream is relit on the view's GPU (docs/viewer.md, "Relighting on the GPU"): no map read back.
  expect(burst.gpu!.gpuRelights).toBeGreaterThan(atFull.gpu!.gpuRelights);
  expect(burst.gpu!.mapReadbacks).toBe(0);
  // The configuration is not touched by live levels (dimming stays 1).
  expect(await getConfig(page)).toBe(patchedText);

  // The bridge goes away: the view keeps the last look and says so, retrying.
  bridge.process.kill('SIGTERM');
  await expect(page.getByTestId('live-state')).toHaveAttribute('data-state', 'lost', { timeout: 15_000 });
  await expect(page.getByTestId('live-note')).toContainText('bridge lost');
  // Levels changed: the direct light was exact at once, the indirect light is re-solved in the
  // background (docs/viewer.md, "Relighting without rebaking"); once that is done the look is final.
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
  const lastLook = await status(page);
  await page.waitForTimeout(500);
  expect((await status(page)).floor!.avg).toBe(lastLook.floor!.avg);

  // Live control off: the configuration's own dimming again, still without a bake.
  await page.getByTestId('live-on').uncheck();
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 90_000, intervals: [250] }).toBeCloseTo(baked.floor!.avg, 0);
  const off = await status(page);
  expect(off.live).toBeNull();
  expect(off.groupBakes).toBe(6);
  await expect(page.getByTestId('live-note')).toHaveCount(0);
  expect(await getConfig(page)).toBe(patchedText);
  // One undo step takes back the auto-patch: live control added nothing to the history.
  expect(await page.evaluate(() => window.luxbox!.undo())).toBe(true);
  expect(await getConfig(page)).toBe(placed);
});
