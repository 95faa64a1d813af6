/** The three engines the cross-engine suite drives (docs/browsers.md). */
export type EngineName = 'chromium' | 'firefox' | 'webkit';

/**
 * The few page operations the cross-engine scenario needs, implemented once per automation
 * protocol: Playwright (Chromium, CDP), puppeteer-core (Firefox ESR, WebDriver BiDi) and
 * selenium-webdriver (WebKitGTK, WebDriver classic). Clicks and keys go through each protocol's
 * input emulation (real pointer and keyboard events), not through element.click() in the page.
 */
export interface EngineDriver {
  readonly engine: EngineName;
  goto(url: string): Promise<void>;
  /**
   * Evaluates a JavaScript expression in the page and returns its value through JSON (the same
   * round trip in all three protocols). A string, not a function: functions would be serialised
   * after the test runner's transform, which may add helpers the page does not have.
   */
  evaluate<T>(expression: string): Promise<T>;
  /** Pointer click in the middle of the first element matching the CSS selector. */
  click(selector: string): Promise<void>;
  /** Replaces the text of an input by typing (select all, then the keys). */
  fill(selector: string, text: string): Promise<void>;
  /** Focuses the element and presses one key (`Home`, `ArrowLeft`, `Tab`, …) `times` times. */
  press(selector: string, key: DriverKey, times?: number): Promise<void>;
  /** Hands a file to an `<input type="file">`, as the file chooser would. */
  setInputFile(selector: string, path: string): Promise<void>;
  /** PNG of the viewport. */
  screenshot(path: string): Promise<void>;
  close(): Promise<void>;
}

export type DriverKey = 'Home' | 'End' | 'ArrowLeft' | 'ArrowRight';

export const VIEWPORT = { width: 1280, height: 800 } as const;
