/**
 * A zip container read as an upload (GLDF products; L3D geometry uses the same reader): the
 * central directory is read and checked first — entry count, names, declared sizes, their sum,
 * the compression ratio — and nothing is inflated until all of it passes. Entries are inflated
 * on demand through fflate's streaming `Inflate`, in small input chunks, so an entry that
 * inflates to more than its directory entry claims is stopped as soon as it does (a lying
 * directory cannot make us allocate more than the caps). Format: PKWARE APPNOTE.TXT 6.3.9,
 * §4.3.7 (local header), §4.3.12 (central directory header), §4.3.16 (end of central directory).
 */
import { Inflate } from 'fflate';
import { GldfError, quoteName } from './GldfError';
import { UPLOAD_LIMITS } from './uploadLimits';

export interface ZipEntryInfo {
  /** The name as stored, checked: relative, '/'-separated, no '..' or '.' segments, no control characters. */
  name: string;
  method: 0 | 8;
  compressedSize: number;
  size: number;
  crc32: number;
  /** Offset of the entry's local header. */
  localOffset: number;
}

export interface UploadZip {
  /** The container's file name, for messages. */
  source: string;
  /** Every file entry (folders left out), in directory order. */
  entries: readonly ZipEntryInfo[];
  has(name: string): boolean;
  /** The entry's bytes, inflated and CRC-checked; throws GldfError naming the entry. */
  read(name: string): Uint8Array;
}

const EOCD_SIGNATURE = 0x06054b50;
const CENTRAL_SIGNATURE = 0x02014b50;
const LOCAL_SIGNATURE = 0x04034b50;
/** Bytes of input handed to the inflater at a time: at most ~1032× that comes out before the size check runs. */
const INFLATE_CHUNK = 16 * 1024;

const u16 = (b: Uint8Array, at: number): number => b[at] | (b[at + 1] << 8);
const u32 = (b: Uint8Array, at: number): number => (b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (b[at + 3] << 24)) >>> 0;

const megabytes = (n: number): string => `${Math.round((n / (1024 * 1024)) * 10) / 10} MB`;

/**
 * Why an entry name is refused, or null: absolute paths, drive letters, backslashes, '.' and
 * '..' segments, empty segments and control characters (zip-slip: an entry that would land
 * outside the folder it is unpacked into), and names over the length cap.
 */
export function unsafeEntryName(name: string): string | null {
  if (name.length === 0) return 'has an empty name';
  if (name.length > UPLOAD_LIMITS.maxNameLength) return `has a name longer than ${UPLOAD_LIMITS.maxNameLength} characters`;
  for (let i = 0; i < name.length; i++) {
    const c = name.charCodeAt(i);
    if (c < 0x20 || c === 0x7f) return 'has a control character in its name';
  }
  if (name.includes('\\')) return 'uses a backslash in its name (zip names use /)';
  if (name.startsWith('/')) return 'has an absolute path';
  if (/^[a-zA-Z]:/.test(name)) return 'names a drive';
  const segments = name.replace(/\/$/, '').split('/');
  if (segments.some((s) => s === '..')) return "climbs out of the container ('..')";
  if (segments.some((s) => s === '.' || s === '')) return "has an empty or '.' path segment";
  return null;
}

/** CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320) as zip stores it (APPNOTE §4.4.7). */
const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

export function crc32(bytes: Uint8Array): number {
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function findEndOfCentralDirectory(zip: Uint8Array, source: string): number {
  // The record is 22 bytes plus a comment of at most 65 535 bytes, at the very end.
  const lowest = Math.max(0, zip.length - 22 - 0xffff);
  for (let at = zip.length - 22; at >= lowest; at--) if (u32(zip, at) === EOCD_SIGNATURE) return at;
  throw new GldfError(`${source}: not a zip container (no end of central directory)`);
}

const decoder = new TextDecoder('utf-8');
const latin1 = new TextDecoder('latin1');

/**
 * Opens a zip upload. Throws GldfError (one line, naming the file and the entry) for anything
 * that is not a plain, unencrypted zip within UPLOAD_LIMITS.
 */
export function readUploadZip(zip: Uint8Array, source: string): UploadZip {
  if (zip.length > UPLOAD_LIMITS.maxContainerBytes) {
    throw new GldfError(`${source}: the file is ${megabytes(zip.length)}, over the ${megabytes(UPLOAD_LIMITS.maxContainerBytes)} limit`);
  }
  if (zip.length < 22) throw new GldfError(`${source}: not a zip container (${zip.length} bytes)`);
  const eocd = findEndOfCentralDirectory(zip, source);
  const count = u16(zip, eocd + 10);
  const cdSize = u32(zip, eocd + 12);
  const cdOffset = u32(zip, eocd + 16);
  if (count === 0xffff || cdSize === 0xffffffff || cdOffset === 0xffffffff) throw new GldfError(`${source}: ZIP64 containers are not read (a GLDF is far below 4 GB)`);
  if (count > UPLOAD_LIMITS.maxEntries) throw new GldfError(`${source}: ${count} entries, over the limit of ${UPLOAD_LIMITS.maxEntries}`);
  if (u16(zip, eocd + 4) !== 0 || u16(zip, eocd + 6) !== 0 || u16(zip, eocd + 8) !== count) throw new GldfError(`${source}: multi-part zip archives are not read`);
  if (cdOffset + cdSize > eocd) throw new GldfError(`${source}: the central directory lies outside the file`);

  const entries: ZipEntryInfo[] = [];
  const seen = new Set<string>();
  let total = 0;
  let at = cdOffset;
  for (let i = 0; i < count; i++) {
    if (at + 46 > eocd || u32(zip, at) !== CENTRAL_SIGNATURE) throw new GldfError(`${source}: central directory entry ${i + 1} is damaged`);
    const flags = u16(zip, at + 8);
    const method = u16(zip, at + 10);
    const crc = u32(zip, at + 16);
    const compressedSize = u32(zip, at + 20);
    const size = u32(zip, at + 24);
    const nameLength = u16(zip, at + 28);
    const extraLength = u16(zip, at + 30);
    const commentLength = u16(zip, at + 32);
    const localOffset = u32(zip, at + 42);
    if (at + 46 + nameLength > eocd) throw new GldfError(`${source}: central directory entry ${i + 1} is damaged`);
    const rawName = zip.subarray(at + 46, at + 46 + nameLength);
    // Bit 11: the name is UTF-8; otherwise IBM 437, read here as Latin-1 (APPNOTE appendix D).
    const name = (flags & 0x800 ? decoder : latin1).decode(rawName);
    at += 46 + nameLength + extraLength + commentLength;
    const entry = `${source}: entry ${quoteName(name)}`;
    const unsafe = unsafeEntryName(name);
    if (unsafe) throw new GldfError(`${entry} ${unsafe}`);
    const key = name.toLowerCase();
    if (seen.has(key)) throw new GldfError(`${entry} appears twice`);
    seen.add(key);
    if (name.endsWith('/')) continue; // a folder
    if (flags & 0x1) throw new GldfError(`${entry} is encrypted`);
    if (method !== 0 && method !== 8) throw new GldfError(`${entry} uses compression method ${method} (only stored and deflate are read)`);
    if (compressedSize === 0xffffffff || size === 0xffffffff) throw new GldfError(`${entry}: ZIP64 entries are not read`);
    if (size > UPLOAD_LIMITS.maxEntryBytes) throw new GldfError(`${entry} is ${megabytes(size)} uncompressed, over the ${megabytes(UPLOAD_LIMITS.maxEntryBytes)} limit per entry`);
    total += size;
    if (total > UPLOAD_LIMITS.maxTotalBytes) throw new GldfError(`${entry}: the entries add up to over ${megabytes(UPLOAD_LIMITS.maxTotalBytes)} uncompressed`);
    if (method === 0 && compressedSize !== size) throw new GldfError(`${entry} is stored uncompressed but its two sizes differ`);
    if (size >= UPLOAD_LIMITS.ratioFloorBytes && size / Math.max(compressedSize, 1) > UPLOAD_LIMITS.maxRatio) {
      throw new GldfError(`${entry} compresses ${Math.round(size / Math.max(compressedSize, 1))}:1, over the ${UPLOAD_LIMITS.maxRatio}:1 limit (a zip bomb?)`);
    }
    if (localOffset + 30 > cdOffset) throw new GldfError(`${entry}: its data lies outside the file`);
    entries.push({ name, method, compressedSize, size, crc32: crc, localOffset });
  }
  const byName = new Map(entries.map((e) => [e.name, e]));
  return {
    source,
    entries,
    has: (name) => byName.has(name),
    read(name) {
      const e = byName.get(name);
      if (!e) throw new GldfError(`${source}: no entry ${quoteName(name)}`);
      return inflateEntry(zip, e, cdOffset, `${source}: entry ${quoteName(name)}`);
    },
  };
}

function inflateEntry(zip: Uint8Array, e: ZipEntryInfo, dataEnd: number, label: string): Uint8Array {
  const h = e.localOffset;
  if (u32(zip, h) !== LOCAL_SIGNATURE) throw new GldfError(`${label}: its local header is damaged`);
  const start = h + 30 + u16(zip, h + 26) + u16(zip, h + 28);
  const end = start + e.compressedSize;
  if (end > dataEnd) throw new GldfError(`${label}: its data runs past the end of the file`);
  const data = zip.subarray(start, end);
  let out: Uint8Array;
  if (e.method === 0) out = data.slice();
  else {
    out = new Uint8Array(e.size);
    let written = 0;
    let done = false;
    const inflater = new Inflate((chunk, final) => {
      if (written + chunk.length > e.size) throw new GldfError(`${label} inflates to more than the ${e.size} bytes its directory entry states (a zip bomb?)`);
      out.set(chunk, written);
      written += chunk.length;
      if (final) done = true;
    });
    try {
      for (let i = 0; i < data.length; i += INFLATE_CHUNK) inflater.push(data.subarray(i, Math.min(i + INFLATE_CHUNK, data.length)), i + INFLATE_CHUNK >= data.length);
      if (data.length === 0) inflater.push(data, true);
    } catch (error) {
      if (error instanceof GldfError) throw error;
      throw new GldfError(`${label}: the compressed data is damaged`);
    }
    if (!done || written !== e.size) throw new GldfError(`${label} inflates to ${written} bytes, not the ${e.size} its directory entry states`);
  }
  if (crc32(out) !== e.crc32) throw new GldfError(`${label}: checksum mismatch (the data is damaged)`);
  return out;
}
