// The element's attribute parsing, and that the package's UI doors can be imported where there is
// no DOM (a Next.js server render imports luxbox/react; a server bundle may import luxbox/element).
import { describe, expect, it } from 'vitest';
import { InputError } from '../../../src/core/inputError';
import { parseRoomAttribute } from '../../../src/hosts/package/LuxboxConfiguratorElement';

describe('parseRoomAttribute', () => {
  it('reads width, depth and height in metres, separated by spaces, x, × or commas', () => {
    const room = { width: 6, depth: 4.5, height: 3 };
    for (const text of ['6 4.5 3', '6x4.5x3', '6 × 4.5 × 3', '6, 4.5, 3', '  6   4.5 3 ']) expect(parseRoomAttribute(text), text).toEqual(room);
  });

  it('refuses anything else with an InputError naming the attribute', () => {
    for (const text of ['', '6 4.5', '6 4.5 3 2', '6 four 3', '-6 4.5 3', '6 4.5 3m', '1e1 4 3']) {
      expect(() => parseRoomAttribute(text), text).toThrow(InputError);
      expect(() => parseRoomAttribute(text), text).toThrow(/^room attribute: /);
    }
  });
});

describe('the UI doors without a DOM', () => {
  it('luxbox/element and luxbox/react import under Node without touching the DOM or registering anything', async () => {
    expect(typeof document).toBe('undefined');
    const element = await import('../../../src/hosts/package/element');
    const react = await import('../../../src/hosts/package/react');
    expect(typeof element.LuxboxConfiguratorElement).toBe('function');
    expect(typeof react.Luxbox).toBe('object'); // a forwardRef component
    expect(typeof customElements).toBe('undefined');
  });
});
