/**
 * A test lighting console: builds ArtDmx and E1.31 data packets byte by byte from the standards'
 * tables (Art-Net 4 "ArtDmx"; ANSI E1.31-2018 Table 4-1), independently of the bridge's parsers,
 * and sends them as real UDP datagrams on the loopback interface.
 */
import { createSocket, type Socket } from 'node:dgram';
import WebSocket from 'ws';
import type { DmxBridgeStatus } from '../../../../src/hosts/node/dmx/createDmxBridge';

export interface ArtDmxFields {
  sequence?: number;
  physical?: number;
  net?: number;
  subNet?: number;
  universe?: number;
  version?: number;
  data: ArrayLike<number>;
}

export function buildArtDmx(f: ArtDmxFields): Buffer {
  const b = Buffer.alloc(18 + f.data.length);
  b.write('Art-Net\0', 0, 'latin1');
  b[8] = 0x00; // OpCode 0x5000, low byte first
  b[9] = 0x50;
  const version = f.version ?? 14;
  b[10] = version >> 8;
  b[11] = version & 0xff;
  b[12] = f.sequence ?? 0;
  b[13] = f.physical ?? 0;
  b[14] = ((f.subNet ?? 0) << 4) | (f.universe ?? 0);
  b[15] = f.net ?? 0;
  b[16] = f.data.length >> 8;
  b[17] = f.data.length & 0xff;
  for (let i = 0; i < f.data.length; i++) b[18 + i] = f.data[i];
  return b;
}

export interface E131Fields {
  cid: number[];
  sourceName?: string;
  priority?: number;
  sequence?: number;
  terminated?: boolean;
  preview?: boolean;
  universe: number;
  startCode?: number;
  data: ArrayLike<number>;
}

export function buildE131(f: E131Fields): Buffer {
  const slots = f.data.length;
  const total = 126 + slots;
  const b = Buffer.alloc(total);
  // Root layer
  b.writeUInt16BE(0x0010, 0);
  b.writeUInt16BE(0x0000, 2);
  Buffer.from([0x41, 0x53, 0x43, 0x2d, 0x45, 0x31, 0x2e, 0x31, 0x37, 0, 0, 0]).copy(b, 4);
  b.writeUInt16BE(0x7000 | (total - 16), 16);
  b.writeUInt32BE(0x00000004, 18);
  Buffer.from(f.cid).copy(b, 22);
  // Framing layer
  b.writeUInt16BE(0x7000 | (total - 38), 38);
  b.writeUInt32BE(0x00000002, 40);
  b.write(f.sourceName ?? 'test console', 44, 63, 'utf8');
  b[108] = f.priority ?? 100;
  b.writeUInt16BE(0, 109);
  b[111] = f.sequence ?? 0;
  b[112] = (f.preview ? 0x80 : 0) | (f.terminated ? 0x40 : 0);
  b.writeUInt16BE(f.universe, 113);
  // DMP layer
  b.writeUInt16BE(0x7000 | (total - 115), 115);
  b[117] = 0x02;
  b[118] = 0xa1;
  b.writeUInt16BE(0x0000, 119);
  b.writeUInt16BE(0x0001, 121);
  b.writeUInt16BE(slots + 1, 123);
  b[125] = f.startCode ?? 0;
  for (let i = 0; i < slots; i++) b[126 + i] = f.data[i];
  return b;
}

/** 512 slots, `value` everywhere unless `at` sets some. */
export function levels(value: number, at: Record<number, number> = {}): number[] {
  const out = new Array<number>(512).fill(value);
  for (const [i, v] of Object.entries(at)) out[Number(i)] = v;
  return out;
}

export interface TestConsole {
  send(packet: Buffer, port: number): Promise<void>;
  close(): Promise<void>;
}

export async function openConsole(): Promise<TestConsole> {
  const socket: Socket = createSocket('udp4');
  await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
  return {
    send: (packet, port) => new Promise((resolve, reject) => socket.send(packet, port, '127.0.0.1', (e) => (e ? reject(e) : resolve()))),
    close: () => new Promise((resolve) => socket.close(() => resolve())),
  };
}

export interface Frame {
  universe: number;
  channels: number[];
}

/** A real `ws` client that records every frame and answers "status" requests. */
export interface TestClient {
  ws: WebSocket;
  frames: Frame[];
  /** Resolves with the first frame matching, among those recorded from index `after` on and those to come. */
  waitFor(match: (f: Frame) => boolean, what: string, timeoutMs?: number, after?: number): Promise<Frame>;
  status(): Promise<DmxBridgeStatus>;
  close(): Promise<void>;
}

export async function connect(url: string): Promise<TestClient> {
  const ws = new WebSocket(url);
  const frames: Frame[] = [];
  type Message = Frame | DmxBridgeStatus;
  const waiters: { match: (m: Message) => boolean; resolve: (m: Message) => void }[] = [];
  ws.on('message', (data) => {
    const msg = JSON.parse(data.toString()) as Message;
    if (!('type' in msg)) frames.push(msg);
    for (const w of [...waiters]) {
      if (w.match(msg)) {
        waiters.splice(waiters.indexOf(w), 1);
        w.resolve(msg);
      }
    }
  });
  await new Promise<void>((resolve, reject) => {
    ws.once('open', () => resolve());
    ws.once('error', reject);
  });
  function wait<T extends Message>(match: (m: Message) => boolean, what: string, timeoutMs: number): Promise<T> {
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`timed out waiting for ${what}`)), timeoutMs);
      waiters.push({
        match,
        resolve: (m) => {
          clearTimeout(timer);
          resolve(m as T);
        },
      });
    });
  }
  return {
    ws,
    frames,
    waitFor(match, what, timeoutMs = 5000, after = 0) {
      const seen = frames.slice(after).find(match);
      if (seen) return Promise.resolve(seen);
      return wait<Frame>((m) => !('type' in m) && match(m), what, timeoutMs);
    },
    status() {
      const p = wait<DmxBridgeStatus>((m) => 'type' in m, 'status', 5000);
      ws.send('status');
      return p;
    },
    close: () =>
      new Promise((resolve) => {
        if (ws.readyState === ws.CLOSED) return resolve();
        ws.once('close', () => resolve());
        ws.close();
      }),
  };
}

export const CID_A = Array.from({ length: 16 }, (_, i) => 0xa0 + i);
export const CID_B = Array.from({ length: 16 }, (_, i) => 0xb0 + i);
