/**
 * Removing any rail of a chain (docs/model.md, "Removing a rail"): the last shortens the chain at
 * its end, the first at its start (anchor and heading move to the next rail), a middle one splits
 * the system in two. Every module left keeps its plan position (1e-9 m); feeds follow their
 * positions; a part without a feed gets one whose driver carries its load.
 * U-shape preset at (1, 4) heading 0, corner connectors with 0.05 m arms, by hand:
 *   rail 0: (1, 4) → (2.5, 4); corner at (2.55, 4), heading 90 (plan −z)
 *   rail 1: (2.55, 3.95) → (2.55, 1.95); corner at (2.55, 1.9), heading 180 (plan −x)
 *   rail 2: (2.5, 1.9) → (1, 1.9)
 */
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import type { Configuration, LightSystem } from '../../../../src/core/model/configuration/configuration';
import { feedLoads } from '../../../../src/core/model/power/feedLoads';
import { modulePlacements } from '../../../../src/core/model/rails/geometry';
import { suspensionPoints } from '../../../../src/core/model/rails/suspensionPoints';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, only, run, withPreset } from '../helpers';

const centres = (c: Configuration) => new Map(c.systems.flatMap((s) => modulePlacements(s, catalog)).map((p) => [p.moduleId, p.centre]));

function expectModulesStay(before: Configuration, after: Configuration, removedRail: string) {
  const old = centres(before);
  const gone = new Set(before.systems.flatMap((s) => s.rails.filter((r) => r.id === removedRail).flatMap((r) => r.modules.map((m) => m.id))));
  const now = centres(after);
  expect([...now.keys()].sort()).toEqual([...old.keys()].filter((id) => !gone.has(id)).sort());
  for (const [id, c] of now) {
    expect(c[0]).toBeCloseTo(old.get(id)![0], 9);
    expect(c[1]).toBeCloseTo(old.get(id)![1], 9);
  }
}

describe('removeRail', () => {
  const u = () => withPreset('u-shape', 1, 4);
  it('the last rail: the chain ends one connector earlier', () => {
    const s = u();
    const after = run(s, 'removeRail', { railId: only(s).rails[2].id });
    expect(only(after).rails.map((r) => r.id)).toEqual(
      only(s)
        .rails.slice(0, 2)
        .map((r) => r.id),
    );
    expect(only(after).joints).toEqual(only(s).joints.slice(0, 1));
    expectModulesStay(s, after, only(s).rails[2].id);
  });
  it('the first rail: the chain starts at the next rail, anchor (2.55, 3.95) heading 90', () => {
    const s = u();
    const after = run(s, 'removeRail', { railId: only(s).rails[0].id });
    const sys = only(after);
    expect(sys.x).toBeCloseTo(2.55, 9);
    expect(sys.z).toBeCloseTo(3.95, 9);
    expect(sys.rotation).toBe(90);
    expect(sys.rails.map((r) => r.id)).toEqual(
      only(s)
        .rails.slice(1)
        .map((r) => r.id),
    );
    expect(sys.joints).toEqual([{ connector: 'corner90', turn: 90 }]);
    expect(sys.feeds).toEqual(only(s).feeds); // the start feed slides to the new start
    expectModulesStay(s, after, only(s).rails[0].id);
  });
  it('a middle rail splits the chain: the second part is a new system at (2.5, 1.9) heading 180 with its own feed', () => {
    const s = u();
    const before = only(s);
    const after = run(s, 'removeRail', { railId: before.rails[1].id });
    expect(validate(after, catalog)).toEqual([]);
    expect(after.systems).toHaveLength(2);
    const [a, b] = after.systems as [LightSystem, LightSystem];
    expect(a.id).toBe(before.id);
    expect(a.rails.map((r) => r.id)).toEqual([before.rails[0].id]);
    expect(a.joints).toEqual([]);
    expect(a.feeds).toEqual(before.feeds);
    expect(b.id).toBe(`s${s.nextId}`);
    expect([b.x, b.z, b.rotation]).toEqual([expect.closeTo(2.5, 9), expect.closeTo(1.9, 9), 180]);
    expect(b.rails.map((r) => r.id)).toEqual([before.rails[2].id]);
    expect([b.suspension, b.mounting]).toEqual([before.suspension, before.mounting]);
    // Its two 43 W spots (86 W) fit the catalog's default 100.8 W driver, at its start.
    expect(b.feeds).toEqual([{ id: `f${s.nextId + 1}`, at: 'start', driver: catalog.feed.defaultDriver }]);
    expect(feedLoads(b, catalog)[0].load).toBeCloseTo(86, 9);
    expect(after.nextId).toBe(s.nextId + 2);
    expectModulesStay(s, after, before.rails[1].id);
    // Suspensions follow: a lone 1.5 m rail hangs at its quarter points, 0.375 m in from each end.
    expect(suspensionPoints(b, catalog).map((p) => p.plan)).toEqual([
      [expect.closeTo(2.125, 9), expect.closeTo(1.9, 9)],
      [expect.closeTo(1.375, 9), expect.closeTo(1.9, 9)],
    ]);
  });
  it("feeds at the connectors of the removed rail become the parts' ends; nothing new is added then", () => {
    let s = u();
    const sys = only(s);
    s = run(s, 'setFeedDriver', { feedId: sys.feeds[0].id, driver: 'hlg-320h-48' });
    s = run(s, 'addFeed', { systemId: sys.id, at: { joint: 0 }, driver: 'hlg-320h-48' });
    s = run(s, 'addFeed', { systemId: sys.id, at: { joint: 1 }, driver: 'hlg-320h-48' });
    const [f0, f1, f2] = only(s).feeds;
    const after = run(s, 'removeRail', { railId: sys.rails[1].id });
    expect(after.systems[0].feeds).toEqual([f0, { ...f1, at: 'end' }]);
    expect(after.systems[1].feeds).toEqual([{ ...f2, at: 'start' }]);
    expect(after.nextId).toBe(s.nextId + 1);
  });
  it("a snake split in the middle keeps each side's joints", () => {
    const s = withPreset('snake', 1, 5, 0, { width: 10, depth: 8, height: 3 });
    const before = only(s);
    const after = run(s, 'removeRail', { railId: before.rails[2].id });
    expect(after.systems.map((x) => x.rails.map((r) => r.id))).toEqual([before.rails.slice(0, 2).map((r) => r.id), before.rails.slice(3).map((r) => r.id)]);
    expect(after.systems.map((x) => x.joints)).toEqual([before.joints.slice(0, 1), before.joints.slice(3)]);
    expectModulesStay(s, after, before.rails[2].id);
  });
  it('refused with the reason when feeds would meet or the only rail would go', () => {
    let s = u();
    const sys = only(s);
    s = run(s, 'setFeedDriver', { feedId: sys.feeds[0].id, driver: 'hlg-320h-48' });
    s = run(s, 'addFeed', { systemId: sys.id, at: { joint: 0 }, driver: 'hlg-320h-48' });
    expect(enabled(s, 'removeRail', { railId: sys.rails[0].id })).toEqual({ ok: false, reason: 'a feed at the chain start and one at the first connector would meet; remove one of them first' });
    expect(validate(bindAction('removeRail', { railId: sys.rails[0].id }, catalog).perform(s), catalog).map((p) => p.code)).toEqual(['feed-duplicate']);
    const one = withPreset('single', 1, 1);
    expect(enabled(one, 'removeRail', { railId: only(one).rails[0].id })).toEqual({ ok: false, reason: 'a system keeps at least one rail; delete the system instead' });
  });
});
