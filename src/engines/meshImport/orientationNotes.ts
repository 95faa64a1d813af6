import type { OrientationSummary } from '../../core/mesh/orientMesh';

/**
 * What orienting a model did, as English lines for the command line and the API (the import panel
 * words the same counts in the UI language): closed parts turned outward, open surfaces made
 * two-sided, parts with no clear inside. Nothing for a model whose parts were all closed and outward.
 */
export function orientationNotes(name: string, o: OrientationSummary): string[] {
  const lines: string[] = [];
  const n = (count: number, one: string, many: string) => `${count} ${count === 1 ? one : many}`;
  if (o.turnedOutward > 0) lines.push(`${name}: ${n(o.turnedOutward, 'closed part', 'closed parts')} faced inward and ${o.turnedOutward === 1 ? 'was' : 'were'} turned outward (${o.trianglesReversed} triangles reversed)`);
  if (o.twoSided > 0) lines.push(`${name}: ${n(o.twoSided, 'open surface', 'open surfaces')} lit and reflecting on both sides (${o.backTriangles} back-side triangles added)`);
  if (o.undecided > 0) lines.push(`${name}: ${n(o.undecided, 'part', 'parts')} with no clear inside (faces that cannot be wound alike) lit on both sides`);
  return lines;
}
