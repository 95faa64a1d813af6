// The 3D view's frame in the planner (loading, unsupported, failed): in the first-screen bundle.
export default {
  backTo2d: 'Back to 2D plan',
  loading: 'Loading the 3D view…',
  loadFailed: 'The 3D view could not be loaded ({problem}). Your configuration is unchanged.',
  noDocument: 'The 3D view needs a browser page.',
  noWebgl2: 'This browser or device has no WebGL2, which the 3D light view needs. The 2D planner works as before.',
  noFloatTargets: 'This device cannot render to floating-point textures (EXT_color_buffer_float), which the light baking needs. The 2D planner works as before.',
};
