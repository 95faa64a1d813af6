import { isIPv4 } from 'node:net';
import { InputError } from '../../core/inputError';
import { ARTNET_PORT, createDmxBridge, DMX_WS_PORT, DmxBridgeStartError, SACN_PORT } from '../node/dmx/createDmxBridge';
import { MAX_UNIVERSE } from '../node/dmx/parseE131';

/** A usage problem or a port that cannot be opened: one stderr line, exit 1. */
export class DmxCommandError extends InputError {
  override name = 'DmxCommandError';
}

const USAGE = 'usage: luxbox dmx [--artnet] [--sacn] [--port N] [--bind ADDR] [--universes 1-4] [--artnet-port N] [--sacn-port N]';

/** The most sACN multicast groups one bridge joins; Linux allows 20 per socket by default (igmp_max_memberships). */
const MAX_MULTICAST_UNIVERSES = 64;

export interface DmxCommandOptions {
  artnet: boolean;
  sacn: boolean;
  wsPort: number;
  artnetPort: number;
  sacnPort: number;
  bind: string;
  universes: number[];
}

function port(flag: string, value: string | undefined): number {
  if (value === undefined || !/^\d{1,5}$/.test(value) || Number(value) > 65535) {
    throw new DmxCommandError(`${flag} needs a port number 0–65535${value === undefined ? '' : `, not "${value}"`}`);
  }
  return Number(value);
}

/** "1-4", "1,3,7-9": the sACN universes (1–63999) whose multicast groups to join. */
export function parseUniverseList(text: string): number[] {
  const out = new Set<number>();
  for (const part of text.split(',')) {
    const m = /^(\d{1,5})(?:-(\d{1,5}))?$/.exec(part.trim());
    const from = m ? Number(m[1]) : NaN;
    const to = m ? Number(m[2] ?? m[1]) : NaN;
    if (!m || from < 1 || to > MAX_UNIVERSE || to < from) {
      throw new DmxCommandError(`--universes: "${part}" is not a universe 1–${MAX_UNIVERSE} or a range like 1-4`);
    }
    if (to - from + 1 + out.size > MAX_MULTICAST_UNIVERSES) {
      throw new DmxCommandError(`--universes: at most ${MAX_MULTICAST_UNIVERSES} multicast universes (unicast sACN reaches any universe without joining)`);
    }
    for (let u = from; u <= to; u++) out.add(u);
  }
  return [...out].sort((a, b) => a - b);
}

export function parseDmxArgs(args: string[]): DmxCommandOptions {
  let artnet = false;
  let sacn = false;
  const o = { wsPort: DMX_WS_PORT, artnetPort: ARTNET_PORT, sacnPort: SACN_PORT, bind: '0.0.0.0', universes: [1] };
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    const value = () => {
      const v = args[i + 1];
      i++;
      return v;
    };
    switch (a) {
      case '--artnet':
        artnet = true;
        break;
      case '--sacn':
        sacn = true;
        break;
      case '--port':
        o.wsPort = port(a, value());
        break;
      case '--artnet-port':
        o.artnetPort = port(a, value());
        break;
      case '--sacn-port':
        o.sacnPort = port(a, value());
        break;
      case '--bind': {
        const v = value();
        if (v === undefined || !isIPv4(v)) throw new DmxCommandError(`--bind needs an IPv4 address of this machine${v === undefined ? '' : `, not "${v}"`}`);
        o.bind = v;
        break;
      }
      case '--universes': {
        const v = value();
        if (v === undefined) throw new DmxCommandError('--universes needs a list like 1-4 or 1,3,5');
        o.universes = parseUniverseList(v);
        break;
      }
      default:
        throw new DmxCommandError(a.startsWith('-') ? `unknown option ${a}; ${USAGE}` : `unexpected argument "${a}"; ${USAGE}`);
    }
  }
  // Neither flag: both protocols.
  if (!artnet && !sacn) artnet = sacn = true;
  return { artnet, sacn, ...o };
}

/** `luxbox dmx`: runs the DMX bridge (docs/dmx.md) until Ctrl-C or SIGTERM. */
export async function run(args: string[]): Promise<number> {
  if (args.includes('--help') || args.includes('-h')) {
    process.stdout.write(USAGE + '\n');
    return 0;
  }
  const options = parseDmxArgs(args);
  let bridge;
  try {
    bridge = await createDmxBridge(options);
  } catch (error) {
    if (error instanceof DmxBridgeStartError) throw new DmxCommandError(error.message);
    throw error;
  }
  const a = bridge.address();
  const lines: string[] = [];
  if (a.artnet) lines.push(`Art-Net   udp ${a.artnet.address}:${a.artnet.port}`);
  if (a.sacn) lines.push(`sACN      udp ${a.sacn.address}:${a.sacn.port}` + (a.sacn.multicast.length ? `, multicast ${a.sacn.multicast.join(' ')}` : ''));
  lines.push(`WebSocket ${a.ws.url}`);
  process.stdout.write(lines.map((l) => `luxbox dmx: ${l}\n`).join(''));

  await new Promise<void>((resolve) => {
    const stop = () => {
      process.off('SIGINT', stop);
      process.off('SIGTERM', stop);
      resolve();
    };
    process.on('SIGINT', stop);
    process.on('SIGTERM', stop);
  });
  await bridge.close();
  process.stderr.write('luxbox dmx: closed\n');
  return 0;
}
