/**
 * Fuzz target: share links (`#c=…` in the app's address) through
 * decodeShareString. The input is the link text after `#c=`. Mutations work on
 * the JSON inside most of the time (shareLinkCodec), so they reach the
 * decoder's checks rather than stopping at base64url; raw link bytes are
 * mutated too.
 */
import { demoConfiguration } from '../../src/core/catalog/demoConfiguration';
import { defaultCatalog } from '../../src/core/catalog/defaultCatalog';
import type { Configuration } from '../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration } from '../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../src/core/model/files/sceneFileError';
import { decodeShareString, encodeShareString } from '../../src/core/model/files/shareLink';
import { configurationProblems, configurationSeeds } from './configurationTarget';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

const encoder = new TextEncoder();
const decoder = new TextDecoder('utf-8');

/** JSON text ↔ link text, for mutating the JSON inside a link. */
export const shareLinkCodec = {
  decode: (link: Uint8Array): Uint8Array | null => {
    const text = decoder.decode(link);
    return /^[A-Za-z0-9_-]+$/.test(text) ? new Uint8Array(Buffer.from(text, 'base64url')) : null;
  },
  encode: (json: Uint8Array): Uint8Array => encoder.encode(Buffer.from(json).toString('base64url')),
};

export const shareLinkFuzzTarget: FuzzTarget = {
  name: 'share-link',
  seeds(): FuzzSeed[] {
    const seeds: FuzzSeed[] = configurationSeeds().map((s) => {
      const config = deserializeConfiguration(decoder.decode(s.bytes), defaultCatalog);
      return { name: `${s.name} (link)`, bytes: encoder.encode(encodeShareString(config, defaultCatalog)) };
    });
    // A link as written before issue 18 (indented JSON) must keep working.
    const old = serializeConfiguration(demoConfiguration(defaultCatalog), defaultCatalog, 2);
    seeds.push({ name: 'demo (indented link)', bytes: shareLinkCodec.encode(encoder.encode(old)) });
    return seeds;
  },
  run(input: Uint8Array): FuzzOutcome {
    const link = decoder.decode(input);
    let config: Configuration;
    try {
      config = decodeShareString(link, defaultCatalog);
    } catch (error) {
      if (error instanceof SceneFileError) return { kind: 'refused', message: error.message };
      throw error;
    }
    const json = shareLinkCodec.decode(input);
    return { kind: 'accepted', problems: json ? configurationProblems(decoder.decode(json), config) : ['accepted a link that is not base64url'] };
  },
};
