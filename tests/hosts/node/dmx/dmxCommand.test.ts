/** `luxbox dmx` as a user runs it: a child process, its addresses on stdout, SIGTERM, and bad flags. */
import { spawn, spawnSync } from 'node:child_process';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { parseDmxArgs, parseUniverseList } from '../../../../src/hosts/cli/dmxCommand';
import { buildArtDmx, buildE131, CID_A, connect, levels, openConsole } from './testConsole';

const root = join(__dirname, '../../../..');
const bin = join(root, 'bin/luxbox.js');

describe('luxbox dmx', () => {
  it('starts, prints its addresses, serves frames and exits 0 on SIGTERM', async () => {
    const child = spawn(process.execPath, [bin, 'dmx', '--port', '0', '--artnet-port', '0', '--sacn-port', '0', '--bind', '127.0.0.1', '--universes', '1-2'], { cwd: root });
    let stdout = '';
    let stderr = '';
    child.stderr.on('data', (d) => (stderr += d));
    const exited = new Promise<number | null>((resolve) => child.on('exit', (code) => resolve(code)));
    try {
      await new Promise<void>((resolve, reject) => {
        const timer = setTimeout(() => reject(new Error(`no addresses within 60 s; stderr: ${stderr}`)), 60_000);
        child.stdout.on('data', (d) => {
          stdout += d;
          if (/WebSocket ws:\/\/127\.0\.0\.1:\d+/.test(stdout)) {
            clearTimeout(timer);
            resolve();
          }
        });
      });
      const artnetPort = Number(/Art-Net\s+udp 127\.0\.0\.1:(\d+)/.exec(stdout)![1]);
      const sacnPort = Number(/sACN\s+udp 127\.0\.0\.1:(\d+)/.exec(stdout)![1]);
      const url = /(ws:\/\/127\.0\.0\.1:\d+)/.exec(stdout)![1];
      const tc = await openConsole();
      const client = await connect(url);
      await tc.send(buildArtDmx({ universe: 0, data: levels(0, { 0: 1 }) }), artnetPort);
      await tc.send(buildE131({ cid: CID_A, universe: 3, data: levels(0, { 0: 2 }) }), sacnPort);
      await client.waitFor((f) => f.universe === 1 && f.channels[0] === 1, 'Art-Net frame from the CLI bridge');
      await client.waitFor((f) => f.universe === 3 && f.channels[0] === 2, 'sACN frame from the CLI bridge');
      const closed = new Promise<number>((resolve) => client.ws.once('close', (code) => resolve(code)));
      await tc.close();
      child.kill('SIGTERM');
      expect(await exited).toBe(0);
      // The bridge said goodbye properly: 1001 "going away", not a dropped connection (1006).
      expect(await closed).toBe(1001);
      expect(stderr).toMatch(/luxbox dmx: closed\n$/);
    } finally {
      child.kill('SIGKILL');
    }
  });

  it.each([
    [['--port', 'abc'], /^luxbox dmx: --port needs a port number 0–65535, not "abc"\n$/],
    [['--port', '70000'], /^luxbox dmx: --port needs a port number/],
    [['--bind', 'localhost'], /^luxbox dmx: --bind needs an IPv4 address/],
    [['--universes', '0-4'], /^luxbox dmx: --universes: "0-4" is not a universe/],
    [['--frobnicate'], /^luxbox dmx: unknown option --frobnicate; usage: luxbox dmx/],
  ])('bad flags %j: one clear stderr line, exit 1', (args, message) => {
    const r = spawnSync(process.execPath, [bin, 'dmx', ...args], { cwd: root, encoding: 'utf8', timeout: 60_000 });
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(message);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stdout).toBe('');
  });

  it('a port in use is one clear line, exit 1', async () => {
    const blocker = spawn(process.execPath, [bin, 'dmx', '--sacn', '--sacn-port', '0', '--port', '0', '--bind', '127.0.0.1'], { cwd: root });
    let out = '';
    await new Promise<void>((resolve) => blocker.stdout.on('data', (d) => ((out += d), /WebSocket/.test(out) && resolve())));
    const taken = /ws:\/\/127\.0\.0\.1:(\d+)/.exec(out)![1];
    try {
      const r = spawnSync(process.execPath, [bin, 'dmx', '--sacn', '--sacn-port', '0', '--port', taken], { cwd: root, encoding: 'utf8', timeout: 60_000 });
      expect(r.status).toBe(1);
      expect(r.stderr).toBe(`luxbox dmx: WebSocket: cannot listen on 127.0.0.1:${taken} (port in use by another program)\n`);
    } finally {
      const gone = new Promise((resolve) => blocker.on('exit', resolve));
      blocker.kill('SIGTERM');
      await gone;
    }
  });

  it('parses its flags: both protocols by default, universe lists', () => {
    expect(parseDmxArgs([])).toMatchObject({ artnet: true, sacn: true, wsPort: 9090, artnetPort: 6454, sacnPort: 5568, bind: '0.0.0.0', universes: [1] });
    expect(parseDmxArgs(['--sacn'])).toMatchObject({ artnet: false, sacn: true });
    expect(parseDmxArgs(['--artnet', '--port', '0'])).toMatchObject({ artnet: true, sacn: false, wsPort: 0 });
    expect(parseUniverseList('1-4')).toEqual([1, 2, 3, 4]);
    expect(parseUniverseList('7, 3,1-2,3')).toEqual([1, 2, 3, 7]);
    expect(() => parseUniverseList('1-100')).toThrow(/at most 64/);
    expect(() => parseUniverseList('4-1')).toThrow(/not a universe/);
  });
});
