// The component tests' page is a touch screen, as the phones and tablets the plan's pinch is for:
// @use-gesture decides once, when it loads, whether pinches come from pointer events
// (navigator.maxTouchPoints > 1) or not at all on a desktop without Safari's gesture events.
Object.defineProperty(window.navigator, 'maxTouchPoints', { value: 5, configurable: true });
