import { DMX_SLOTS } from './parseArtDmx';

export interface MergeInput {
  /** 0–200; E1.31 §6.2.3. Art-Net sources take part at 100, the E1.31 default. */
  priority: number;
  /** The source's last accepted slots; shorter arrays mean 0 for the missing slots. */
  channels: Uint8Array;
}

/**
 * The merged levels of one universe: the sources at the highest priority win outright
 * (E1.31-2018 §6.2.3: a receiver treats lower-priority data as absent), and among them each slot
 * takes the highest value (HTP, the merge Art-Net 4 describes as its default). Returns null when
 * there is no source at all.
 */
export function mergeUniverse(sources: readonly MergeInput[]): Uint8Array | null {
  if (sources.length === 0) return null;
  let top = -1;
  for (const s of sources) if (s.priority > top) top = s.priority;
  const out = new Uint8Array(DMX_SLOTS);
  for (const s of sources) {
    if (s.priority !== top) continue;
    const n = Math.min(s.channels.length, DMX_SLOTS);
    for (let i = 0; i < n; i++) if (s.channels[i] > out[i]) out[i] = s.channels[i];
  }
  return out;
}
