/**
 * Vertex shader for every bake pass: one triangle that covers the viewport
 * (no vertex buffer; the vertex id picks the corner), so each fragment is one
 * texel of the target light map and gl_FragCoord.xy is its centre.
 */
export const fullscreenVertex = /* glsl */ `#version 300 es
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
`;

/** Common fragment-shader preamble: highp everywhere (light maps hold lux up to ~1e12 without overflow). */
export const fragmentHeader = /* glsl */ `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
`;
