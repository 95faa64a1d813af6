import { describe, expect, it } from 'vitest';
import { roomSchema } from '../../../src/core/room/roomSchema';
import { attic, issueExample, plainReflectance } from './roomFixtures';

/** The first issue as `path: message`, and its code for a UI (a geometric rule's code, else zod's). */
function firstIssue(value: unknown): { where: string; code: string } {
  const r = roomSchema.safeParse(value);
  expect(r.success).toBe(false);
  if (r.success) return { where: '', code: '' };
  const issue = r.error.issues[0];
  const params = (issue as { params?: { code?: string } }).params;
  return { where: `${issue.path.join('.')}: ${issue.message}`, code: params?.code ?? issue.code };
}

describe('version-3 room schema', () => {
  it('accepts the issue example, an attic, per-wall and RGB reflectances', () => {
    expect(roomSchema.safeParse(issueExample).success).toBe(true);
    expect(roomSchema.safeParse(attic).success).toBe(true);
    expect(roomSchema.safeParse({ ...attic, reflectance: { floor: [0.2, 0.3, 0.4], ceiling: 0.8, walls: [0.5, [0.6, 0.5, 0.4], 0.5, 0.5] } }).success).toBe(true);
    expect(roomSchema.safeParse({ ...attic, slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40, reflectance: 0.6 }] }).success).toBe(true);
  });

  it("refuses bad structure with zod's path and message", () => {
    expect(firstIssue({ ...attic, width: 4 })).toMatchObject({ code: 'unrecognized_keys' });
    expect(
      firstIssue({
        ...attic,
        outline: [
          [0, 0],
          [1, 0],
        ],
      }).where,
    ).toBe('outline: needs at least 3 corners');
    expect(
      firstIssue({
        ...attic,
        outline: [
          [0, 0],
          [4, 0],
          [4, 'x'],
          [0, 6],
        ],
      }).where,
    ).toBe('outline.2.1: must be a number, got "x"');
    expect(firstIssue({ ...attic, height: 0 }).where).toBe('height: 0 m is outside 0.1..500 m');
    expect(firstIssue({ ...attic, slopes: [{ wall: 0, kneeHeight: 1, pitch: 95 }] }).where).toBe('slopes.0.pitch: 95° is not between 0° and 90°');
    expect(firstIssue({ ...attic, slopes: [{ wall: 0.5, kneeHeight: 1, pitch: 30 }] }).where).toBe('slopes.0.wall: must be a whole number');
    expect(firstIssue({ ...attic, openings: [{ wall: 1, offset: 1, width: 1, sill: 0, height: 2, kind: 'hatch' }] }).where).toBe('openings.0.kind: must be "door", "window" or "opening", got "hatch"');
    expect(firstIssue({ ...attic, reflectance: { ...plainReflectance, walls: 1.2 } }).where).toMatch(/^reflectance\.walls: /);
    expect(firstIssue({ ...attic, reflectance: { floor: 0.2, ceiling: 0.8 } }).where).toBe('reflectance.walls: is missing');
  });

  it("refuses each geometric rule with its message at its path, and the rule's code", () => {
    expect(
      firstIssue({
        ...attic,
        outline: [
          [0, 0],
          [4, 0],
          [4, 0.05],
          [4, 6],
          [0, 6],
        ],
      }),
    ).toEqual({
      where: 'outline.1: wall 1 (corner 1 to corner 2) is 0.05 m long; each wall must be at least 0.1 m',
      code: 'room-wall-short',
    });
    expect(
      firstIssue({
        ...attic,
        outline: [
          [0, 0],
          [2, 2],
          [2, 0],
          [0, 2],
        ],
      }),
    ).toEqual({ where: 'outline.2: wall 0 and wall 2 cross or touch; the outline must not intersect itself', code: 'room-self-intersection' });
    expect(firstIssue({ ...attic, slopes: [{ wall: 0, kneeHeight: 3, pitch: 30 }] })).toEqual({
      where: 'slopes.0.kneeHeight: slope 0 has a knee height of 3 m; it must lie between 0 and the ceiling height 2.6 m',
      code: 'room-slope-knee',
    });
    expect(firstIssue({ ...attic, slopes: [{ wall: 7, kneeHeight: 1, pitch: 30 }] }).code).toBe('room-slope-wall');
    expect(firstIssue({ ...attic, openings: [{ wall: 1, offset: 5.5, width: 0.9, sill: 0, height: 2, kind: 'door' }] })).toEqual({
      where: "openings.0.offset: opening 0 reaches from 5.5 to 6.4 m along wall 1, which is 6 m long; it must stay between the wall's ends",
      code: 'room-opening-beyond-wall',
    });
    expect(firstIssue({ ...attic, openings: [{ wall: 0, offset: 1, width: 0.9, sill: 0, height: 2, kind: 'door' }] })).toEqual({
      where: 'openings.0.height: opening 0 reaches 2 m up wall 0, above its top (1.2 m there)',
      code: 'room-opening-above-ceiling',
    });
    expect(
      firstIssue({
        ...attic,
        openings: [
          { wall: 1, offset: 1, width: 1, sill: 0, height: 2, kind: 'door' },
          { wall: 1, offset: 1.5, width: 1, sill: 1, height: 1, kind: 'window' },
        ],
      }),
    ).toEqual({ where: 'openings.1: openings 0 and 1 overlap on wall 1', code: 'room-openings-overlap' });
    expect(firstIssue({ ...attic, reflectance: { ...plainReflectance, walls: [0.5, 0.5] } })).toEqual({
      where: "reflectance.walls: the walls' reflectances list 2 entries for 4 walls",
      code: 'room-wall-reflectance-count',
    });
  });
});
