import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { AdaptationControl } from '../../../src/ui/viewer/AdaptationControl';
import { ExposureControl } from '../../../src/ui/viewer/ExposureControl';

/** The 3D view's exposure control (static markup, English): auto with compensation, or a fixed EV100. */
const target = () => null;

describe('exposure control', () => {
  it('auto: "Auto" pressed, the compensation slider (−4..4 EV) and a lock button; no EV100 slider', () => {
    const html = renderToStaticMarkup(<ExposureControl initial="auto" target={target} />);
    expect(html).toMatch(/data-ev100="auto"/);
    expect(html).toMatch(/aria-pressed="true"[^>]*data-testid="exposure-auto"/);
    expect(html).toMatch(/aria-pressed="false"[^>]*data-testid="exposure-lock"[^>]*>Lock exposure</);
    expect(html).toContain('Exposure 0.0 EV');
    expect(html).toMatch(/min="-4" max="4" step="0.5"[^>]*data-testid="exposure" value="0"/);
    expect(html).not.toContain('exposure-ev100');
  });

  it('a fixed EV100 (embed option exposure: 5.5): "Lock exposure" pressed, the EV100 slider at 5.5, no compensation', () => {
    const html = renderToStaticMarkup(<ExposureControl initial={5.5} target={target} />);
    expect(html).toMatch(/data-ev100="5.5"/);
    expect(html).toMatch(/aria-pressed="true"[^>]*data-testid="exposure-lock"/);
    expect(html).toContain('EV100 5.5');
    expect(html).toMatch(/min="-2" max="16" step="0.1"[^>]*data-testid="exposure-ev100" value="5.5"/);
    expect(html).not.toContain('data-testid="exposure"');
    // Outside the slider's usual range the slider widens to hold the value.
    expect(renderToStaticMarkup(<ExposureControl initial={18.3} target={target} />)).toMatch(/min="-2" max="19"/);
  });
});

describe('re-adapt and colour adaptation', () => {
  it('auto shows a Re-adapt button (hold explained in its title); a locked EV100 does not', () => {
    expect(renderToStaticMarkup(<ExposureControl initial="auto" target={target} />)).toMatch(/title="Adapt to the light on screen now[^"]*"[^>]*data-testid="exposure-readapt"[^>]*>Re-adapt</);
    expect(renderToStaticMarkup(<ExposureControl initial={5.5} target={target} />)).not.toContain('exposure-readapt');
  });

  it('Eye pressed by default; camera white balance shows its CCT slider (2000..6500 K, 100 K steps); none', () => {
    const eye = renderToStaticMarkup(<AdaptationControl initial={{ kind: 'eye' }} target={target} />);
    expect(eye).toMatch(/data-adapt="eye"/);
    expect(eye).toMatch(/aria-pressed="true"[^>]*data-testid="adapt-eye"[^>]*>Eye</);
    expect(eye).toMatch(/aria-pressed="false"[^>]*data-testid="adapt-camera"[^>]*>Camera</);
    expect(eye).not.toContain('adapt-cct');
    const camera = renderToStaticMarkup(<AdaptationControl initial={{ kind: 'camera', cct: 3000 }} target={target} />);
    expect(camera).toMatch(/data-adapt="camera:3000"/);
    expect(camera).toContain('White balance 3000 K');
    expect(camera).toMatch(/min="2000" max="6500" step="100"[^>]*value="3000"/);
    expect(renderToStaticMarkup(<AdaptationControl initial={{ kind: 'none' }} target={target} />)).toMatch(/aria-pressed="true"[^>]*data-testid="adapt-none"/);
  });
});
