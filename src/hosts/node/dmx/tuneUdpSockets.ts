import type { Socket } from 'node:dgram';
import { sacnMulticastGroup } from './sacnMulticastGroup';

/** Joins each universe's sACN multicast group (E1.31-2018 §9.3.1: 239.255.hi.lo; unicast needs no join); returns the groups joined. */
export function joinSacnMulticast(socket: Socket, universes: readonly number[], bind: string, log: (line: string) => void): string[] {
  const joined: string[] = [];
  for (const universe of universes) {
    const group = sacnMulticastGroup(universe);
    try {
      socket.addMembership(group, bind === '0.0.0.0' ? undefined : bind);
      joined.push(group);
    } catch (error) {
      log(`dmx: sACN: cannot join multicast group ${group} for universe ${universe} (${(error as Error).message}); unicast still works`);
    }
  }
  return joined;
}

/** Consoles send bursts (one packet per universe per frame); a larger receive buffer loses fewer. */
export function enlargeReceiveBuffers(sockets: readonly Socket[]): void {
  for (const s of sockets) {
    try {
      s.setRecvBufferSize(1 << 20);
    } catch {
      // Capped by the OS (net.core.rmem_max): the default buffer still works.
    }
  }
}
