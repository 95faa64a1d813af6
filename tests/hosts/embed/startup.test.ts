import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { roomFieldError } from '../../../src/ui/app/RoomSetup';
import { SHARE_HASH_PREFIX, resolveStartup } from '../../../src/hosts/embed/startup';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { encodeShareString } from '../../../src/core/model/files/shareLink';
import { actionDefinitions } from '../../../src/core/model/actions/actionDefinitions';
import { validate } from '../../../src/core/model/validation/validate';
import { livingRoom } from '../../../src/core/catalog/furnishedPresets';
import { demoConfiguration } from '../../../src/core/catalog/demoConfiguration';
import { firstImpression } from '../../../src/ui/viewer/firstImpression';

const catalog = defaultCatalog;
const withPreset = actionDefinitions.placePreset.perform(createConfiguration(), { presetId: 'single' }, catalog);
const saved = serializeConfiguration(withPreset, catalog);

describe('resolveStartup', () => {
  it('opens the room setup when there is nothing saved and no link', () => {
    const s = resolveStartup({ catalog, hash: '', saved: null });
    expect(s.phase).toBe('setup');
    expect(s.banner).toBeNull();
  });

  it('restores the autosave', () => {
    const s = resolveStartup({ catalog, hash: '', saved });
    expect(s.phase).toBe('planner');
    expect(s.config).toEqual(withPreset);
    expect(s.saveNow).toBe(false);
  });

  it('a valid share link wins over the autosave and is saved', () => {
    const other = actionDefinitions.placePreset.perform(createConfiguration({ width: 8 }), { presetId: 'u-shape' }, catalog);
    const s = resolveStartup({ catalog, hash: SHARE_HASH_PREFIX + encodeShareString(other, catalog), saved });
    expect(s.config).toEqual(other);
    expect(s.saveNow).toBe(true);
    expect(s.clearHash).toBe(true);
  });

  it.each([
    ['damaged characters', `${SHARE_HASH_PREFIX}%%%`],
    ['truncated', `${SHARE_HASH_PREFIX}${encodeShareString(withPreset, catalog).slice(0, 41)}`],
    ['foreign hash', '#section-2'],
    ['empty link', SHARE_HASH_PREFIX],
  ])('a broken link (%s) gives an empty valid room, a message, and never saves', (_, hash) => {
    const s = resolveStartup({ catalog, hash, saved });
    expect(s.phase).toBe('planner');
    expect(s.config.systems).toHaveLength(0);
    expect(validate(s.config, catalog)).toEqual([]);
    expect(s.banner?.text).toMatch(/link/);
    expect(s.banner?.canRestore).toBe(true);
    expect(s.saveNow).toBe(false);
  });

  it('an unreadable autosave is reported, not thrown', () => {
    const s = resolveStartup({ catalog, hash: '', saved: '{"format":"luxbox-configuration","version":1,"catalog":"other"}' });
    expect(s.phase).toBe('setup');
    expect(s.banner?.text).toContain('could not be read');
  });

  it("uses the host's room when nothing else applies", () => {
    const s = resolveStartup({ catalog, hash: '', saved: null, room: { width: 7, depth: 3, height: 3.2 } });
    expect(s.phase).toBe('planner');
    expect(s.config.room).toMatchObject({ width: 7, depth: 3, height: 3.2 });
  });
});

describe('demo startup', () => {
  it('opens the furnished living room (L corner, furniture) when asked and nothing else applies', () => {
    const s = resolveStartup({ catalog, hash: '', saved: null, demo: true });
    expect(s.phase).toBe('planner');
    expect(s.config).toEqual(livingRoom(catalog));
    expect(s.config.room).toMatchObject({ width: 6, depth: 5, height: 2.7 });
    expect(s.config.systems.map((x) => x.presetId)).toEqual(['corner-l']);
    expect(s.config.objects.map((o) => (o.source.kind === 'library' ? o.source.item : o.source.mesh))).toContain('sofa');
    expect(validate(s.config, catalog)).toEqual([]);
    expect(s.saveNow).toBe(false);
  });

  it('a catalog without the presets the living room needs gets the plain demo', () => {
    const bare = { ...catalog, presets: [] };
    expect(firstImpression(bare)).toEqual(demoConfiguration(bare));
    expect(firstImpression(bare).objects).toEqual([]);
  });

  it('never replaces saved work with the demo', () => {
    expect(resolveStartup({ catalog, hash: '', saved, demo: true }).config).toEqual(withPreset);
  });
});

describe('roomFieldError', () => {
  it('accepts the model limits, decimal commas, and names the problem otherwise', () => {
    expect(roomFieldError('height', '2,8')).toBeNull();
    expect(roomFieldError('width', '30')).toBeNull();
    expect(roomFieldError('width', '30.01')).toBe('The width must be between 1 and 30 m.');
    expect(roomFieldError('height', '2.1')).toBe('The height must be between 2.2 and 8 m.');
    expect(roomFieldError('depth', 'four')).toBe('The depth "four" is not a number.');
    expect(roomFieldError('depth', ' ')).toBe('Enter the room depth in metres.');
  });
});
