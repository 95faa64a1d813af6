/**
 * Trees of rails (docs/model.md, "Trees of rails"): T and X connectors, branches, tree distances,
 * removal into pieces, connector changes, BOM counts and scene file version 8.
 * Worked example, by hand: the 'single' preset (1.5 m, three 43 W spots) at (1, 3) heading 0; a
 * T-connector (0.05 m arms) at its end, pivot (2.55, 3):
 *   A (rail 0): (1, 3) → (2.5, 3)
 *   B (rail 1, through, turn 0):  start = pivot + 0.05·(1, 0) = (2.6, 3) → (3.6, 3)
 *   C (rail 2, branch, turn 90):  start = pivot + 0.05·(0, −1) = (2.55, 2.95) → (2.55, 1.95)
 * Chain coordinates: A [0, 1.5], T point 1.55, B [1.6, 2.6], C [2.7, 3.7] (its bridge 2.6–2.7);
 * tree depth of B's and C's starts: 1.6. Derived suspensions (2 m, 0.5 m): A 0.375 (1.5/4) and the
 * T at 1.55; B: 1.55 → 2.35 (1 m rail: inset 0.25; gap 0.8, no interior point); C: its node
 * 1.55 (s 2.65 before its start), end support 3.45: points 0.375, 1.55, 2.35, 3.45.
 */
import { describe, expect, it } from 'vitest';
import { billOfMaterials } from '../../../../src/core/model/power/billOfMaterials';
import { chainCoordinates, distancesFrom, feedLocation, onRail, treeDistance } from '../../../../src/core/model/rails/chainCoordinates';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { allowedFeedPositions, feedLoads } from '../../../../src/core/model/power/feedLoads';
import { fixingProblem } from '../../../../src/core/model/rails/fixingRules';
import { modulePlacements, railPlacements } from '../../../../src/core/model/rails/geometry';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { suspensionPoints } from '../../../../src/core/model/rails/suspensionPoints';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, only, run, withPreset } from '../helpers';

function tee(): Configuration {
  let s = withPreset('single', 1, 3);
  const a = only(s).rails[0].id;
  s = run(s, 'addBranch', { railId: a, connector: 'tee', turn: 0, length: 1 });
  return run(s, 'addBranch', { railId: a, turn: 90, length: 1 });
}

const close = (got: readonly number[], want: readonly number[]) => want.forEach((w, i) => expect(got[i]).toBeCloseTo(w, 9));

describe('trees of rails', () => {
  it('places branches of a T-connector by hand', () => {
    const sys = only(tee());
    expect(sys.joints).toEqual([
      { connector: 'tee', turn: 0 },
      { connector: 'tee', turn: 90, parent: 0 },
    ]);
    const p = railPlacements(sys, catalog);
    close([...p[0].start, ...p[0].end], [1, 3, 2.5, 3]);
    close([...p[1].start, ...p[1].end], [2.6, 3, 3.6, 3]);
    close([...p[2].start, ...p[2].end], [2.55, 2.95, 2.55, 1.95]);
    expect(p[2].heading).toBe(90);
    expect(validate(tee(), catalog)).toEqual([]);
  });

  it('measures chain coordinates and distances along the tree', () => {
    const sys = only(tee());
    const c = chainCoordinates(sys, catalog);
    close(c.railStart, [0, 1.6, 2.7]);
    close(c.jointAt, [1.55, 1.55]);
    close(c.depthStart, [0, 1.6, 1.6]);
    expect(c.length).toBeCloseTo(3.7, 9);
    // B's start to C's start: 0.05 + 0.05 through the T, not |1.6 − 2.7| along the list.
    expect(treeDistance(c, onRail(c, 1, 0), onRail(c, 2, 0))).toBeCloseTo(0.1, 9);
    // A's middle to C's end: 0.75 + 0.05 + 0.05 + 1.
    expect(treeDistance(c, onRail(c, 0, 0.75), onRail(c, 2, 1))).toBeCloseTo(1.85, 9);
    expect(allowedFeedPositions(sys, catalog)).toEqual(['start', { joint: 0 }, { end: 1 }, 'end']);
    expect(feedLocation({ joint: 1 }, c)).toEqual(feedLocation({ joint: 0 }, c));
  });

  it('the per-feed distance field agrees with the pairwise tree distance on an X tree', () => {
    let s = tee();
    const a = only(s).rails[0].id;
    s = run(run(s, 'setConnector', { railId: a, connector: 'cross' }), 'addBranch', { railId: a, turn: -90, length: 1 });
    s = run(s, 'addBranch', { railId: only(s).rails[2].id, connector: 'tee', turn: -90, length: 0.5 });
    const c = chainCoordinates(only(s), catalog);
    const places = only(s).rails.flatMap((r, i) => [0, 0.3, r.length].map((u) => onRail(c, i, u)));
    places.push(...only(s).rails.flatMap((_, i) => (Number.isNaN(c.nodeAt[i]) ? [] : [{ rail: i, depth: c.nodeDepth[i] }])));
    for (const from of places) {
      const field = distancesFrom(c, from);
      for (const to of places) expect(field(to)).toBeCloseTo(treeDistance(c, from, to), 9);
    }
  });

  it('derives a suspension on every branch and one at the connector', () => {
    const pts = suspensionPoints(only(tee()), catalog);
    close(
      pts.map((q) => q.s),
      [0.375, 1.55, 2.35, 3.45],
    );
    expect(pts.map((q) => q.joint)).toEqual([null, 0, null, null]);
    close(
      pts.flatMap((q) => [...q.plan]),
      [1.375, 3, 2.55, 3, 3.35, 3, 2.55, 2.2],
    );
    const bom = billOfMaterials(tee(), catalog);
    expect(bom.lines.filter((l) => l.kind === 'connector').map((l) => [l.article, l.count])).toEqual([['LX-CON-T', 1]]);
    expect(bom.lines.find((l) => l.kind === 'suspension')?.count).toBe(4);
  });

  it('assigns loads by distance along the tree, not along the list', () => {
    let s = tee();
    const sys = only(s);
    s = run(s, 'addFeed', { systemId: sys.id, at: 'end' });
    s = run(s, 'setDistribution', { railId: sys.rails[1].id, distribution: 'start' });
    s = run(s, 'addModule', { railId: sys.rails[1].id, type: 'spot' });
    // The B spot's centre: s 1.675, depth 1.675. To the start 1.675; to C's end (1.675 − 1.55) + (2.7 − 1.55) = 1.275.
    // Along the list it would be |3.7 − 1.675| = 2.025 from the chain end, so it would go to the start.
    const loads = feedLoads(only(s), catalog);
    expect(loads.map((l) => l.load)).toEqual([129, 43]);
    expect(loads[1].moduleIds).toEqual([only(s).rails[1].modules[0].id]);
  });

  it('refuses a branch through a taken or missing port, and a connector that cannot hold the branches', () => {
    const s = tee();
    const a = only(s).rails[0].id;
    expect(enabled(s, 'addBranch', { railId: a, turn: -90 })).toEqual({ ok: false, reason: 'the T-connector at the end of this rail has no free port; change it to one with more ports' });
    expect(enabled(s, 'addBranch', { railId: a, connector: 'corner90', turn: -90 })).toEqual({ ok: false, reason: "a connector already sits at the end of this rail ('tee'); change it first" });
    expect(enabled(s, 'setConnector', { railId: a, connector: 'straight' })).toEqual({ ok: false, reason: 'the Straight connector joins 2 rail ends; 2 branches leave this connector' });
    const leaf = only(s).rails[1].id;
    expect(enabled(s, 'addBranch', { railId: leaf, connector: 'tee', turn: 45 })).toEqual({ ok: false, reason: 'the T-connector takes branches straight on or at ±90°' });
    // An X takes the third branch.
    const x = run(run(s, 'setConnector', { railId: a, connector: 'cross' }), 'addBranch', { railId: a, turn: -90, length: 1 });
    const p = railPlacements(only(x), catalog);
    close([...p[3].start, ...p[3].end], [2.55, 3.05, 2.55, 4.05]);
    expect(validate(x, catalog)).toEqual([]);
    expect(
      billOfMaterials(x, catalog)
        .lines.filter((l) => l.kind === 'connector')
        .map((l) => [l.article, l.count]),
    ).toEqual([['LX-CON-X', 1]]);
    // A branch into the rail it hangs on: B turned back through a corner runs into A's T.
    expect(enabled(x, 'addBranch', { railId: only(x).rails[1].id, connector: 'corner90', turn: 90, length: 3 })).toMatchObject({ ok: false });
  });

  it('removing the root leaves each branch as its own system, modules and feeds where they were', () => {
    let s = tee();
    s = run(s, 'addFeed', { systemId: only(s).id, at: 'end' });
    s = run(s, 'addModule', { railId: only(s).rails[1].id, type: 'spot' });
    const before = new Map(modulePlacements(only(s), catalog).map((m) => [m.moduleId, m.centre]));
    const after = run(s, 'removeRail', { railId: only(s).rails[0].id });
    expect(after.systems.map((x) => x.rails.length)).toEqual([1, 1]);
    expect(after.systems[0].id).toBe(only(s).id);
    close([after.systems[0].x, after.systems[0].z, after.systems[0].rotation], [2.6, 3, 0]);
    close([after.systems[1].x, after.systems[1].z, after.systems[1].rotation], [2.55, 2.95, 90]);
    expect(after.systems[0].feeds.map((f) => f.at)).toEqual(['start']);
    expect(after.systems[1].feeds.map((f) => f.at)).toEqual(['end']);
    for (const m of after.systems.flatMap((x) => modulePlacements(x, catalog))) close([...m.centre], [...before.get(m.moduleId)!]);
    expect(validate(after, catalog)).toEqual([]);
  });

  it('removing a branch keeps the rest as one system; a T left with one branch stays a T', () => {
    const s = tee();
    const after = run(s, 'removeRail', { railId: only(s).rails[1].id });
    expect(only(after).joints).toEqual([{ connector: 'tee', turn: 90 }]);
    close([...railPlacements(only(after), catalog)[1].start], [2.55, 2.95]);
    expect(validate(after, catalog)).toEqual([]);
  });

  it('removing a rail with a parent and two branches leaves three systems', () => {
    // A (1.5 m) → straight → R (1 m) → T → B (1 m, through) and C (1 m, left). By hand: R from (2.52, 3)
    // to (3.52, 3); T pivot (3.57, 3); B from (3.62, 3), C from (3.57, 2.95) heading 90°.
    let s = withPreset('single', 1, 3);
    s = run(s, 'addRail', { systemId: only(s).id, connector: 'straight', turn: 0, length: 1 });
    const r = only(s).rails[1].id;
    s = run(s, 'addBranch', { railId: r, connector: 'tee', turn: 0, length: 1 });
    s = run(s, 'addBranch', { railId: r, turn: 90, length: 1 });
    const after = run(s, 'removeRail', { railId: r });
    expect(after.systems.map((x) => x.rails.map((q) => q.id))).toEqual([[only(s).rails[0].id], [only(s).rails[2].id], [only(s).rails[3].id]]);
    close([after.systems[1].x, after.systems[1].z, after.systems[1].rotation], [3.62, 3, 0]);
    close([after.systems[2].x, after.systems[2].z, after.systems[2].rotation], [3.57, 2.95, 90]);
    // The start feed stays with A; each branch gets its own planned feed.
    expect(after.systems.map((x) => x.feeds.map((f) => f.at))).toEqual([['start'], ['start'], ['start']]);
    expect(validate(after, catalog)).toEqual([]);
  });

  it('judges moved fixing points per branch', () => {
    const sys = only(tee());
    expect(fixingProblem(sys, [0.375, 1.55, 2.35, 3.45], catalog)).toBeNull();
    // C's end support moved to 3.1: C's end overhangs it by 0.6.
    expect(fixingProblem(sys, [0.375, 1.55, 2.35, 3.1], catalog)).toMatchObject({ code: 'fixing-overhang', message: 'the chain end would overhang its last suspension by 0.6 m (at most 0.5 m)' });
    expect(fixingProblem(sys, [0.375, 1.55, 2.0, 3.45], catalog)).toMatchObject({ code: 'fixing-overhang', message: 'the end of rail 2 would overhang its last suspension by 0.6 m (at most 0.5 m)' });
    expect(fixingProblem(sys, [0.375, 2.35, 3.45], catalog)).toMatchObject({ code: 'fixing-joint' });
  });

  it('writes version 8 and reads it back; a version 7 snake reads exactly; branches in a version 7 file are refused', () => {
    const s = tee();
    const text = serializeConfiguration(s, catalog);
    expect(JSON.parse(text).version).toBe(SCENE_FILE_VERSION);
    expect(deserializeConfiguration(text, catalog)).toEqual(s);
    const snake = withPreset('u-shape', 1, 4);
    const v7 = { ...JSON.parse(serializeConfiguration(snake, catalog)), version: 7 };
    expect(deserializeConfiguration(JSON.stringify(v7), catalog)).toEqual(snake);
    const bad = { ...JSON.parse(text), version: 7 };
    expect(() => deserializeConfiguration(JSON.stringify(bad), catalog)).toThrow('configuration.systems[0].joints[1].parent: needs "version": 8 (this file says version 7)');
  });
});
