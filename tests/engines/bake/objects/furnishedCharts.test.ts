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
import { layoutAtlas } from '../../../../src/engines/bake/objects/layoutAtlas';
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
});
