import type { TriangleMesh } from '../../core/mesh/triangleMesh';

/** An RGBA image, row 0 at the top, 8 bits per channel, straight (not premultiplied) alpha. */
export interface RgbaImage {
  readonly width: number;
  readonly height: number;
  readonly data: Uint8Array;
}

/** The view every thumbnail shares: a three-quarter view from the front right, above. */
export const THUMBNAIL_VIEW = {
  /** Turn of the camera about the vertical from the item's front (+z) toward +x, degrees. */
  azimuth: 35,
  /** Camera height above the horizon, degrees. */
  elevation: 24,
  /** Subsamples per pixel side (anti-aliasing: 4 × 4 = 16 coverage samples per pixel). */
  supersample: 4,
  /** Light direction (toward the light) in view coordinates: from the upper left, a little toward the viewer. */
  light: [-0.45, 0.75, 0.5] as const,
  /** Share of the diffuse shading that is ambient, so faces turned from the light keep their colour. */
  ambient: 0.42,
} as const;

/** sRGB transfer function (IEC 61966-2-1): linear [0, 1] → 8-bit code value. */
function encodeSrgb(c: number): number {
  const v = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
  return Math.round(255 * Math.min(1, Math.max(0, v)));
}

/**
 * A small picture of a mesh drawn from its own triangles and reflectances: orthographic, in
 * THUMBNAIL_VIEW, fitted into `size` × `size` pixels with a margin, each face flat-shaded with its
 * material's reflectance as a colour (Lambert under one directional light plus ambient, scaled so
 * a face square to the light shows ρ's own display colour), hidden faces removed with a depth
 * buffer, edges anti-aliased by 4 × 4 supersampling, transparent outside the item. Pure
 * arithmetic in a fixed order, so the same mesh gives the same bytes on every machine: the
 * committed thumbnails are checked against it (tests/hosts/node/furnitureThumbnails.test.ts).
 */
export function meshThumbnail(mesh: TriangleMesh, size: number): RgbaImage {
  const { view, bounds } = viewCoordinates(mesh);
  const s = size * THUMBNAIL_VIEW.supersample;
  const margin = 0.06 * s;
  const { minX, maxX, minY, maxY } = bounds;
  const scale = (s - 2 * margin) / Math.max(maxX - minX, maxY - minY);
  const offX = (s - scale * (maxX - minX)) / 2;
  const offY = (s - scale * (maxY - minY)) / 2;
  const screen: Screen = {
    size: s,
    x: (i) => offX + (view[3 * i] - minX) * scale,
    y: (i) => s - offY - (view[3 * i + 1] - minY) * scale,
  };
  const samples = rasterize(mesh, view, screen);
  return resolveSamples(samples, size, THUMBNAIL_VIEW.supersample);
}

/** The supersampled picture's pixel positions of the mesh's vertices. */
interface Screen {
  size: number;
  x: (vertex: number) => number;
  y: (vertex: number) => number;
}

/** Subsamples: depth (−∞ where nothing is drawn) and linear colour. */
interface Samples {
  depth: Float64Array;
  colour: Float64Array;
}

/** Every vertex in view coordinates (right, up, toward the viewer) for THUMBNAIL_VIEW's camera, and their extent on screen. */
function viewCoordinates(mesh: TriangleMesh): { view: Float64Array; bounds: { minX: number; maxX: number; minY: number; maxY: number } } {
  const a = (THUMBNAIL_VIEW.azimuth * Math.PI) / 180;
  const e = (THUMBNAIL_VIEW.elevation * Math.PI) / 180;
  // View axes: right, up and toward the viewer, for a camera at azimuth a, elevation e.
  const right = [Math.cos(a), 0, -Math.sin(a)];
  const toward = [Math.sin(a) * Math.cos(e), Math.sin(e), Math.cos(a) * Math.cos(e)];
  const up = [-Math.sin(a) * Math.sin(e), Math.cos(e), -Math.cos(a) * Math.sin(e)];
  const p = mesh.positions;
  const n = p.length / 3;
  const view = new Float64Array(n * 3);
  let [minX, maxX, minY, maxY] = [Infinity, -Infinity, Infinity, -Infinity];
  for (let i = 0; i < n; i++) {
    const [x, y, z] = [p[3 * i], p[3 * i + 1], p[3 * i + 2]];
    const vx = x * right[0] + y * right[1] + z * right[2];
    const vy = x * up[0] + y * up[1] + z * up[2];
    view[3 * i] = vx;
    view[3 * i + 1] = vy;
    view[3 * i + 2] = x * toward[0] + y * toward[1] + z * toward[2];
    minX = Math.min(minX, vx);
    maxX = Math.max(maxX, vx);
    minY = Math.min(minY, vy);
    maxY = Math.max(maxY, vy);
  }
  return { view, bounds: { minX, maxX, minY, maxY } };
}

/** Each front face flat-shaded (Lambert plus ambient) into the subsamples it covers, nearest face kept (depth buffer). */
function rasterize(mesh: TriangleMesh, view: Float64Array, screen: Screen): Samples {
  const { light, ambient } = THUMBNAIL_VIEW;
  const s = screen.size;
  const samples: Samples = { depth: new Float64Array(s * s).fill(-Infinity), colour: new Float64Array(s * s * 3) };
  const lightLength = Math.hypot(light[0], light[1], light[2]);
  const l = light.map((c) => c / lightLength);
  for (let t = 0; t < mesh.indices.length / 3; t++) {
    const [i0, i1, i2] = [mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]];
    // Face normal in view coordinates (the mesh is wound counterclockwise from outside).
    const u = [view[3 * i1] - view[3 * i0], view[3 * i1 + 1] - view[3 * i0 + 1], view[3 * i1 + 2] - view[3 * i0 + 2]];
    const v = [view[3 * i2] - view[3 * i0], view[3 * i2 + 1] - view[3 * i0 + 1], view[3 * i2 + 2] - view[3 * i0 + 2]];
    const nx = u[1] * v[2] - u[2] * v[1];
    const ny = u[2] * v[0] - u[0] * v[2];
    const nz = u[0] * v[1] - u[1] * v[0];
    if (nz <= 0) continue; // back face: it faces away from the viewer
    const nl = (nx * l[0] + ny * l[1] + nz * l[2]) / Math.hypot(nx, ny, nz);
    const shade = ambient + (1 - ambient) * Math.max(0, nl);
    const rho = mesh.materials[mesh.materialOfTriangle[t]].reflectance;
    const rgb = typeof rho === 'number' ? [rho, rho, rho] : rho;
    fillTriangle(samples, s, [screen.x(i0), screen.y(i0), screen.x(i1), screen.y(i1), screen.x(i2), screen.y(i2)], [view[3 * i0 + 2], view[3 * i1 + 2], view[3 * i2 + 2]], [rgb[0] * shade, rgb[1] * shade, rgb[2] * shade]);
  }
  return samples;
}

/** One triangle's subsamples: inside by barycentric edge functions, depth interpolated, nearer than what is there. */
function fillTriangle(samples: Samples, s: number, [x0, y0, x1, y1, x2, y2]: number[], [z0, z1, z2]: number[], rgb: number[]): void {
  const area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  if (area === 0) return;
  const colMin = Math.max(0, Math.floor(Math.min(x0, x1, x2)));
  const colMax = Math.min(s - 1, Math.ceil(Math.max(x0, x1, x2)));
  const rowMin = Math.max(0, Math.floor(Math.min(y0, y1, y2)));
  const rowMax = Math.min(s - 1, Math.ceil(Math.max(y0, y1, y2)));
  for (let row = rowMin; row <= rowMax; row++) {
    const py = row + 0.5;
    for (let col = colMin; col <= colMax; col++) {
      const px = col + 0.5;
      // Barycentric weights (edge functions over the signed area): inside when all are ≥ 0.
      const w0 = ((x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)) / area;
      const w1 = ((x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)) / area;
      const w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const z = w0 * z0 + w1 * z1 + w2 * z2;
      const k = row * s + col;
      if (z <= samples.depth[k]) continue;
      samples.depth[k] = z;
      samples.colour[3 * k] = rgb[0];
      samples.colour[3 * k + 1] = rgb[1];
      samples.colour[3 * k + 2] = rgb[2];
    }
  }
}

/** ss × ss subsamples per pixel: linear colours averaged over the covered ones, then encoded; coverage is the alpha. */
function resolveSamples({ depth, colour }: Samples, size: number, ss: number): RgbaImage {
  const s = size * ss;
  const data = new Uint8Array(size * size * 4);
  for (let row = 0; row < size; row++) {
    for (let col = 0; col < size; col++) {
      let covered = 0;
      const sum = [0, 0, 0];
      for (let j = 0; j < ss; j++) {
        for (let i = 0; i < ss; i++) {
          const k = (row * ss + j) * s + col * ss + i;
          if (depth[k] === -Infinity) continue;
          covered++;
          for (let c = 0; c < 3; c++) sum[c] += colour[3 * k + c];
        }
      }
      const o = 4 * (row * size + col);
      for (let c = 0; c < 3; c++) data[o + c] = covered ? encodeSrgb(sum[c] / covered) : 0;
      data[o + 3] = Math.round((255 * covered) / (ss * ss));
    }
  }
  return { width: size, height: size, data };
}

/** Images of equal height side by side, left to right, in one image (a sprite sheet). */
export function spriteSheet(images: readonly RgbaImage[]): RgbaImage {
  const height = images[0].height;
  const width = images.reduce((w, im) => w + im.width, 0);
  const data = new Uint8Array(width * height * 4);
  let x0 = 0;
  for (const im of images) {
    if (im.height !== height) throw new Error('sprite images differ in height');
    for (let row = 0; row < height; row++) data.set(im.data.subarray(row * im.width * 4, (row + 1) * im.width * 4), (row * width + x0) * 4);
    x0 += im.width;
  }
  return { width, height, data };
}
