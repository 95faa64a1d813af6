/**
 * Candela lookup in the packed profile table (src/engines/bake/profileTable.ts).
 * Interpolation is done here in full float precision instead of by the
 * texture unit, whose bilinear weights have only ~8 fractional bits on many
 * GPUs (too coarse for a 1° spot). Inputs are parameters: `table`, the name
 * of the R32F sampler the caller declares, and `dataWidth`, the table's width
 * in texels (DATA_TEXTURE_WIDTH), compiled in as a constant.
 */
export const profileLookup = ({ table, dataWidth }: { table: string; dataWidth: number }): string => /* glsl */ `
float profileValue(int k) {
  return texelFetch(${table}, ivec2(k % ${dataWidth}, k / ${dataWidth}), 0).r;
}

// Equal steps: the cell is found arithmetically.
void locateUniform(float a, float first, float invStep, int count, out int i0, out float t) {
  float f = clamp((a - first) * invStep, 0.0, float(count - 1));
  i0 = min(int(f), count - 2);
  t = f - float(i0);
}

// Unequal steps: a bin table gives the cell at the bin start; at most maxSearch
// grid angles can follow inside the bin. The weight uses the stored angles.
void locateMapped(float a, int anglesOffset, int count, float first, int mapOffset, int mapSize,
                  float binsPerDegree, int maxSearch, out int i0, out float t) {
  int bin = clamp(int((a - first) * binsPerDegree), 0, mapSize - 1);
  i0 = int(profileValue(mapOffset + bin) + 0.5);
  for (int s = 0; s < maxSearch; s++) {
    if (i0 >= count - 2 || a < profileValue(anglesOffset + i0 + 1)) break;
    i0++;
  }
  float a0 = profileValue(anglesOffset + i0);
  float a1 = profileValue(anglesOffset + i0 + 1);
  t = clamp((a - a0) / (a1 - a0), 0.0, 1.0);
}
`;
