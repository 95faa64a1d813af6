import * as react from 'react';
import { describe, expect, it } from 'vitest';

/** The component projects run what they say they run (vite.config.ts, componentProjects): the alias to preact/compat takes, or does not. */
describe('component test runtime', () => {
  it(`runs on ${process.env.LUXBOX_UI_RUNTIME}`, async () => {
    const preact = await import('preact');
    const onPreact = react.Component === (preact.Component as unknown);
    expect(onPreact).toBe(process.env.LUXBOX_UI_RUNTIME === 'preact');
  });
});
