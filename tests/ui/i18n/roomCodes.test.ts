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
