/**
 * The furnished presets' objects in the light-map atlas at each quality level of the 3D view
 * (docs/furniture.md, "Meshes and the light-map atlas"): the library's pieces are made of flat
 * facets so their planar charts stay few. The living and dining rooms must fit every level's
 * atlas, and at Balanced and Best keep the texel size the level asks for (the atlas grows the
 * texel by 1.25 at a time only when the charts do not fit).
 */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../../src/core/catalog/defaultCatalog';
import { FURNISHED_PRESETS } from '../../../../src/core/catalog/furnishedPresets';
import { objectMesh, objectPlacement } from '../../../../src/core/model/objects/objectGeometry';
import { buildCharts } from '../../../../src/engines/bake/objects/buildCharts';
import { collectWorldTriangles } from '../../../../src/engines/bake/objects/collectWorldTriangles';
import { ATLAS_CEILING, layoutAtlas, TEXEL_GROWTH } from '../../../../src/engines/bake/objects/layoutAtlas';
import { QUALITY_LEVELS } from '../../../../src/engines/relight/qualityLevels';

function presetCharts(id: string) {
  const config = FURNISHED_PRESETS.find((p) => p.id === id)!.build(defaultCatalog);
  return buildCharts(collectWorldTriangles(config.objects.map((o) => ({ id: o.id, mesh: objectMesh(config, o.id), ...objectPlacement(o, config.room) }))));
}

describe('furnished presets in the objects atlas', () => {
  for (const id of ['living-room', 'dining-room']) {
    it(`${id}: fits every quality level's atlas; Balanced and Best at their own texel size`, () => {
      const charts = presetCharts(id);
      for (const [level, settings] of Object.entries(QUALITY_LEVELS)) {
        const layout = layoutAtlas(charts, settings.texelSize!, settings.maxTextureSize!);
        expect(Math.max(layout.width, layout.height), level).toBeLessThanOrEqual(settings.maxTextureSize!);
        if (level !== 'fast') expect(layout.texelSize, level).toBe(settings.texelSize);
      }
    });
  }

  it("shop window: 2 000-odd facets do not fit Fast's 128² atlas even at one texel each, so the limit doubles to 256² and the texel search starts again", () => {
    const charts = presetCharts('shop-window');
    const fast = QUALITY_LEVELS.fast;
    // One texel each needs a 3 × 3 cell per chart: more than 128² holds.
    expect(9 * charts.length).toBeGreaterThan(128 * 128);
    const layout = layoutAtlas(charts, fast.texelSize!, fast.maxTextureSize!);
    expect(Math.max(layout.width, layout.height)).toBeGreaterThan(128);
    expect(Math.max(layout.width, layout.height)).toBeLessThanOrEqual(256);
    // The search restarted from the level's own texel size at 256², not from where 128² gave up.
    expect(layout.texelSize).toBeLessThan(fast.texelSize! * TEXEL_GROWTH ** 6);
    // Still an error, with the size it reached, where no atlas up to the ceiling holds them.
    const many = Array.from({ length: Math.ceil((ATLAS_CEILING / 3) ** 2) + 1 }, () => charts[0]);
    expect(() => layoutAtlas(many, 0.1, 128)).toThrow(`do not fit in a ${ATLAS_CEILING} × ${ATLAS_CEILING} atlas even at one texel each`);
  });
});
