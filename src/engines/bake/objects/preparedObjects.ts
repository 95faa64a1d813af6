/**
 * The objects of a bake scene as the GPU passes read them (docs/baker.md, "Objects"): one light-map
 * atlas for all objects, with its G-buffer computed on the CPU, and one bounding volume hierarchy
 * over all their triangles in world space, packed into RGBA32F textures for the GLSL traversal
 * (shaders/bvhTraversal.glsl.ts). Built by `prepareObjects` (./prepareObjects.ts).
 */
import type { Bounds3 } from '../../../core/mesh/triangleMesh';
import type { ChartFrame } from './chartFrame';

/** The objects' light-map atlas: every object's triangles in planar charts packed into one texture. */
export interface ObjectAtlas {
  width: number;
  height: number;
  /** Metres per texel (the same in u and v everywhere in the atlas). */
  texelSize: number;
  /** RGBA per texel, row 0 first: world x, y, z of the texel's sample point; a = the fraction of the texel covered by its chart (0 = empty texel). */
  position: Float32Array;
  /** RGBA per texel: unit normal of the lit (front) side; a = chart id + 1 (0 = empty texel). */
  normal: Float32Array;
  /** RGBA per texel: diffuse reflectance ρ, linear RGB; a = object index + 1 (0 = empty texel). */
  reflectance: Float32Array;
}

export interface PreparedObjectInfo {
  id: string;
  triangleCount: number;
  /** Surface area of the placed mesh, m². */
  area: number;
  /** Atlas texels with coverage > 0 that belong to this object. */
  texelCount: number;
  /** World bounds of the placed mesh. */
  bounds: Bounds3;
}

/** The BVH flattened into RGBA32F textures (`width` texels per row); the texel layout is documented in shaders/bvhTraversal.glsl.ts. */
export interface ObjectBvhTextures {
  width: number;
  nodes: Float32Array;
  nodesHeight: number;
  triangles: Float32Array;
  trianglesHeight: number;
}

/** One planar chart of the atlas: its texels are columns × rows from (x, y), with a gutter of empty texels around them. */
export interface ObjectChart {
  /** Index of its object in PreparedObjects.objects. */
  object: number;
  x: number;
  y: number;
  columns: number;
  rows: number;
  triangleCount: number;
  /** The chart's plane in the world (chartFrame.ts): what the bright-patch search tiles. */
  frame: ChartFrame;
}

export interface PreparedObjects {
  atlas: ObjectAtlas;
  bvh: ObjectBvhTextures;
  objects: PreparedObjectInfo[];
  /** The atlas's charts; chart c's texels carry c + 1 in ObjectAtlas.normal's a. */
  charts: ObjectChart[];
  triangleCount: number;
  /** World bounds of all objects together. */
  bounds: Bounds3;
}
