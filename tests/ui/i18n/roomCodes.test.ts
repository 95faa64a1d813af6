import { describe, expect, it } from 'vitest';
import { createFormat } from '../../../src/ui/i18n/createFormat';
import { createTranslator } from '../../../src/ui/i18n/createTranslator';
import { loadMessages } from '../../../src/ui/i18n/loadMessages';
import type { Language } from '../../../src/ui/i18n/languages';
import type { Translate } from '../../../src/ui/i18n/messageTypes';
import { translateCoded } from '../../../src/ui/i18n/translateCoded';
import { roomProblems } from '../../../src/core/room/roomProblems';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { issueExample } from '../../core/room/roomFixtures';
import { createConfiguration, type Configuration, type LightSystem, type RoomShape } from '../../../src/core/model/configuration/configuration';
import { validate } from '../../../src/core/model/validation/validate';
import { problemText } from '../../../src/core/model/configuration/coding';
import { RoomShapeSupportMissing } from '../../../src/core/model/configuration/roomShapeSupport';
import { noticeText } from '../../../src/ui/i18n/noticeText';
import { catalog, run } from '../../core/model/helpers';

/**
 * The room-shape rules' codes (src/core/room/roomProblems.ts, issue 29) in every language: each
 * problem the rules really produce, worded from its code and params. English from the code is the
 * core's sentence byte for byte; de, fr and it are their own, with no placeholder left.
 */
const box: RoomInput = {
  outline: [
    [0, 0],
    [4, 0],
    [4, 3],
    [0, 3],
  ],
  height: 2.6,
  reflectance: { floor: 0.2, ceiling: 0.8, walls: 0.5 },
};
const door = { wall: 0, offset: 1, width: 0.9, sill: 0, height: 2, kind: 'door' as const };

/** One room per rule, broken the way the rule names. */
const BROKEN: Record<string, RoomInput> = {
  'room-corner-count': { ...box, outline: box.outline.slice(0, 2) },
  'room-corner-invalid': {
    ...box,
    outline: [
      [0, 0],
      [1e4, 0],
      [0, 1],
    ],
  },
  'room-wall-short': {
    ...box,
    outline: [
      [0, 0],
      [4, 0],
      [4, 0.05],
      [4, 3],
      [0, 3],
    ],
  },
  'room-corners-close': {
    ...box,
    outline: [
      [0, 0],
      [2, -1],
      [4, 0],
      [2, -0.95],
    ],
  },
  'room-self-intersection': {
    ...box,
    outline: [
      [0, 0],
      [2, 2],
      [2, 0],
      [0, 2],
    ],
  },
  'room-height': { ...box, height: 0 },
  'room-slope-wall': { ...box, slopes: [{ wall: 9, kneeHeight: 1, pitch: 30 }] },
  'room-slope-twice': {
    ...box,
    slopes: [
      { wall: 0, kneeHeight: 1, pitch: 30 },
      { wall: 0, kneeHeight: 1.2, pitch: 30 },
    ],
  },
  'room-slope-pitch': { ...box, slopes: [{ wall: 0, kneeHeight: 1, pitch: 95 }] },
  'room-slope-knee': { ...box, slopes: [{ wall: 0, kneeHeight: 3, pitch: 30 }] },
  'room-reflectance': { ...box, reflectance: { ...box.reflectance, walls: [0.5, 0.5, 0.5, 2] } },
  'room-ceiling-below-floor': { ...issueExample, slopes: [{ wall: 2, kneeHeight: 0.5, pitch: 60 }], openings: [] },
  'room-opening-wall': { ...box, openings: [{ ...door, wall: 9 }] },
  'room-opening-kind': { ...box, openings: [{ ...door, kind: 'hatch' as 'door' }] },
  'room-opening-size': { ...box, openings: [{ ...door, width: 0 }] },
  'room-opening-sill': { ...box, openings: [{ ...door, sill: -1 }] },
  'room-opening-beyond-wall': { ...box, openings: [{ ...door, offset: 3.5 }] },
  'room-opening-above-ceiling': { ...box, openings: [{ ...door, height: 3 }] },
  'room-openings-overlap': { ...box, openings: [door, { ...door, offset: 1.5 }] },
  'room-wall-reflectance-count': { ...box, reflectance: { ...box.reflectance, walls: [0.5, 0.5] } },
};

describe('room-shape codes in every language', async () => {
  const tr = {} as Record<Language, Translate>;
  for (const [language, locale] of [
    ['de', 'de-CH'],
    ['fr', 'fr-CH'],
    ['it', 'it-CH'],
    ['en', 'en'],
  ] as const)
    tr[language] = createTranslator(await loadMessages(language), locale, (x) => createFormat(locale).number(x));

  for (const [code, room] of Object.entries(BROKEN)) {
    it(code, () => {
      const problem = roomProblems(room)[0];
      expect(problem?.code).toBe(code);
      const msg = { text: problem.message, code: problem.code, params: problem.params };
      expect(translateCoded(tr.en, 'notices', msg)).toBe(problem.message);
      for (const language of ['de', 'fr', 'it'] as const) {
        const text = translateCoded(tr[language], 'notices', msg);
        expect(text, language).not.toBe(problem.message);
        expect(text).not.toMatch(/\{\w+\}/);
      }
    });
  }
});

/**
 * validate()'s own sentences for a room with a shape (docs/model.md "Room shape"): systems and
 * objects outside the outline or under a slope, the outline's bounding box, a malformed shape,
 * and the lazy chunk's refusal before it has loaded. Each comes from a real configuration; its
 * sentence code (problemText) must be worded in de, fr and it. A code added to these rules
 * without its translations fails here.
 */
describe("validate()'s room-shape sentences in every language", async () => {
  const tr = {} as Record<Language, Translate>;
  for (const [language, locale] of [
    ['de', 'de-CH'],
    ['fr', 'fr-CH'],
    ['it', 'it-CH'],
    ['en', 'en'],
  ] as const)
    tr[language] = createTranslator(await loadMessages(language), locale, (x) => createFormat(locale).number(x));

  const L: RoomShape = {
    outline: [
      [0, 0],
      [6, 0],
      [6, 3],
      [3.5, 3],
      [3.5, 5],
      [0, 5],
    ],
    slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 45 }],
    openings: [],
  };
  const room = createConfiguration({ width: 6, depth: 5, height: 2.6, shape: L });
  const system = (x: number, z: number, over: Partial<LightSystem> = {}): LightSystem => ({
    id: 's1',
    x,
    z,
    rotation: 0,
    suspension: 0.4,
    rails: [{ id: 'r2', length: 1, distribution: 'start', modules: [] }],
    joints: [],
    feeds: [{ id: 'f3', at: 'start', driver: catalog.feed.defaultDriver }],
    mounting: 'suspended',
    ...over,
  });
  const withSystem = (s: LightSystem): Configuration => ({ ...room, systems: [s], nextId: 20 });
  const table = run(room, 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 1.5, z: 3.5 } });
  const placed = (item: string, x: number, z: number): Configuration => {
    const c = run(room, 'addObject', { source: { kind: 'library', item }, placement: { on: 'floor', x: 1.5, z: 3.5 } });
    return { ...c, objects: c.objects.map((o) => ({ ...o, placement: { on: 'floor' as const, x, z } })) };
  };
  const CASES: Record<string, Configuration> = {
    outsideOutline: withSystem(system(4, 4)),
    underSlopeClearance: withSystem(system(0.5, 0.9)),
    underSlopeClips: withSystem(system(0.5, 1.0, { mounting: 'surface' })),
    objectOutsideOutline: { ...table, objects: table.objects.map((o) => ({ ...o, placement: { on: 'floor' as const, x: 4.8, z: 4 } })) },
    objectAboveSlope: placed('open-shelf', 1.5, 0.5),
    'room-shape-bounds': { ...room, room: { ...room.room, width: 7 } },
    'room-shape': { ...room, room: { ...room.room, shape: { ...L, slopes: undefined } as unknown as RoomShape } },
  };

  for (const [code, config] of Object.entries(CASES)) {
    it(code, () => {
      const problem = validate(config, catalog)[0];
      expect(problem, code).toBeDefined();
      const msg = problemText(problem);
      expect(msg.code).toBe(code);
      expect(noticeText(tr.en, 'en', catalog, msg)).toBe(problem.message);
      for (const language of ['de', 'fr', 'it'] as const) {
        const text = noticeText(tr[language], language, catalog, msg);
        expect(text, language).not.toBe(problem.message);
        expect(text, `${language}: ${text}`).not.toMatch(/\{\w+\}/);
      }
    });
  }

  it('roomShapeLoading: a room-shape action refused before its chunk has loaded', () => {
    const msg = { text: new RoomShapeSupportMissing('setRoomShapePreset').message, code: 'roomShapeLoading' };
    for (const language of ['de', 'fr', 'it'] as const) expect(noticeText(tr[language], language, catalog, msg)).not.toBe(noticeText(tr.en, 'en', catalog, msg));
  });
});
