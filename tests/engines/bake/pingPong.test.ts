/** The ping-pong pair that replaced the baker's index juggling (pingPong.ts): no GL needed, targets are opaque. */
import { describe, expect, it } from 'vitest';
import type { FloatTarget } from '../../../src/engines/bake/floatTarget';
import { createPingPong } from '../../../src/engines/bake/pingPong';

const target = (name: string) => ({ name, width: 1, height: 1 }) as unknown as FloatTarget;

describe('createPingPong', () => {
  it('swap exchanges read and write; exchange hands out read and takes a fresh target', () => {
    const [a, b, c] = ['a', 'b', 'c'].map(target);
    const pair = createPingPong(a, b);
    expect([pair.read, pair.write]).toEqual([a, b]);
    pair.swap();
    expect([pair.read, pair.write]).toEqual([b, a]);
    expect(pair.exchange(c)).toBe(b);
    expect([pair.read, pair.write]).toEqual([c, a]);
    expect(pair.targets).toEqual([c, a]);
  });

  it('three targets rotate through a bounce loop without ever writing what is read (the baker: samples pair + previous)', () => {
    const targets = ['a', 'b', 'c'].map(target);
    const samples = createPingPong(targets[0], targets[1]);
    let previous = targets[2];
    for (let bounce = 0; bounce < 5; bounce++) {
      for (let draw = 0; draw < 3; draw++) {
        expect(samples.write).not.toBe(samples.read);
        expect(samples.write).not.toBe(previous);
        samples.swap();
      }
      previous = samples.exchange(previous);
      expect(new Set([samples.read, samples.write, previous]).size).toBe(3);
    }
  });
});
