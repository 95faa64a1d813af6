/** The surface patterns the 3D view draws (finishTexture.ts; docs/viewer.md, "Surface textures"). */
export const FINISH_TEXTURES = ['plaster', 'wood', 'tiles', 'concrete', 'carpet', 'fabric', 'veneer'] as const;
export type FinishTexture = (typeof FINISH_TEXTURES)[number];

/**
 * Which pattern each shipped room finish (src/core/catalog/surface-finishes.json) shows. Kept here,
 * in the 3D view's lazy chunk, not as a field of the finish list: that list and its schema load
 * with the first screen, which is at its download budget, and the pattern is display only (the
 * baker uses the finish's reflectance, the pattern's mean). A finish not named here is drawn plain.
 */
export const FINISH_TEXTURE_OF: Readonly<Record<string, FinishTexture>> = {
  'white-paint': 'plaster',
  'warm-white': 'plaster',
  'light-grey': 'plaster',
  'mid-grey': 'plaster',
  'sage-green': 'plaster',
  'light-oak': 'wood',
  concrete: 'concrete',
  'grey-carpet': 'carpet',
  'dark-walnut': 'wood',
  'dark-slate': 'tiles',
};

/**
 * Which pattern each object finish (src/core/model/objects/furniture/objectFinishes.ts) shows on
 * furniture in the 3D view: the veneers show a wood veneer's grain (finishTexture.ts, veneerField). At most OBJECT_TEXTURE_SLOTS entries
 * (the objects' shader has one sampler per entry). Objects store reflectances, not finish ids, so
 * the shader finds a texel's finish by its reflectance, as the room's surfaces do.
 */
export const OBJECT_FINISH_TEXTURE_OF: Readonly<Record<string, FinishTexture>> = {
  'oak-veneer': 'veneer',
  'walnut-veneer': 'veneer',
};

/** Samplers the objects' shader has for finish patterns. */
export const OBJECT_TEXTURE_SLOTS = 2;
