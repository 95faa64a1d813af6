/**
 * The viewer's hardware (rails, modules, cables; three.js GLSL3 material): a
 * flat sRGB colour `uColor` under a fixed fake light so boxes read as boxes.
 * They are not part of the light solution.
 */
export const hardwareVertex = /* glsl */ `
out float vShade;
void main() {
  vec3 n = normalize(mat3(modelMatrix) * normal);
  vShade = 0.55 + 0.45 * clamp(0.5 * n.y + 0.5, 0.0, 1.0) - 0.1 * abs(n.x);
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

export const hardwareFragment = /* glsl */ `
precision highp float;
in float vShade;
uniform vec3 uColor;
out vec4 fragColor;
void main() { fragColor = vec4(uColor * vShade, 1.0); }
`;
