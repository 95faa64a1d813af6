import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';

/** A receiver's relit (or basis) maps: RGB lux per texel, 3 floats. */
export interface DirectTotal {
  direct: Float32Array;
  total: Float32Array;
}

/** The objects' atlas maps (scenes with objects; bakedMaps.ts ObjectMaps without the indirect map). */
export interface ObjectDirectTotal extends DirectTotal {
  atlas: ObjectAtlas;
}

/** One group's basis: RGB lux per texel (3 floats), direct and total, per surface (and the objects' atlas), at unit weight. */
export type BasisMaps = Record<SurfaceName, DirectTotal> & { objects?: ObjectDirectTotal };

/** Relit maps: what the viewer shows and the statistics read. `objects` is there when the bases have objects. */
export interface LitMaps {
  layouts: Record<SurfaceName, SurfaceLayout>;
  maps: Record<SurfaceName, DirectTotal> & { objects?: ObjectDirectTotal };
}

/** Zeroed output buffers for a set of layouts. */
export function emptyLitMaps(layouts: readonly SurfaceLayout[]): LitMaps {
  const byName = Object.fromEntries(layouts.map((l) => [l.name, l])) as Record<SurfaceName, SurfaceLayout>;
  const maps = Object.fromEntries(
    layouts.map((l) => [l.name, { direct: new Float32Array(l.width * l.height * 3), total: new Float32Array(l.width * l.height * 3) }]),
  ) as LitMaps['maps'];
  return { layouts: byName, maps };
}

/**
 * out = Σ weight_g · basis_g, per surface and channel (light is linear in the
 * sources: the bounce operator is linear too, so this holds for the indirect
 * part as well as the direct). Writes into `out` (no allocation), so a relight
 * is one pass over the texels per group.
 */
export function relightMaps(parts: readonly { basis: BasisMaps; weight: Rgb }[], out: LitMaps): LitMaps {
  const add = (name: string, dst: DirectTotal, pick: (basis: BasisMaps) => DirectTotal | undefined) => {
    dst.direct.fill(0);
    dst.total.fill(0);
    for (const { basis, weight } of parts) {
      const [wr, wg, wb] = weight;
      if (wr === 0 && wg === 0 && wb === 0) continue;
      const src = pick(basis);
      if (!src) throw new Error(`relightMaps: a basis has no ${name} maps`);
      if (src.total.length !== dst.total.length) throw new Error(`relightMaps: ${name} basis has ${src.total.length / 3} texels, output ${dst.total.length / 3}`);
      for (const kind of ['direct', 'total'] as const) {
        const s = src[kind];
        const d = dst[kind];
        for (let i = 0; i < d.length; i += 3) {
          d[i] += s[i] * wr;
          d[i + 1] += s[i + 1] * wg;
          d[i + 2] += s[i + 2] * wb;
        }
      }
    }
  };
  for (const name of SURFACE_NAMES) add(name, out.maps[name], (b) => b[name]);
  // The objects' atlas: every basis of one scene has the same atlas (the same objects, the same settings).
  const atlas = parts.find((p) => p.basis.objects)?.basis.objects?.atlas;
  if (atlas) {
    const size = atlas.width * atlas.height * 3;
    if (!out.maps.objects || out.maps.objects.total.length !== size) {
      out.maps.objects = { atlas, direct: new Float32Array(size), total: new Float32Array(size) };
    }
    out.maps.objects.atlas = atlas;
    add('objects', out.maps.objects, (b) => b.objects);
  } else delete out.maps.objects;
  return out;
}
