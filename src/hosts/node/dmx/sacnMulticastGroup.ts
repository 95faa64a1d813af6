/** E1.31-2018 §9.3.1: universe u is multicast to 239.255.(u >> 8).(u & 0xff). */
export function sacnMulticastGroup(universe: number): string {
  return `239.255.${(universe >> 8) & 0xff}.${universe & 0xff}`;
}
