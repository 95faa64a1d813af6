/**
 * Adds one of luxbox's stylesheets to the page as a `<style data-luxbox="…">` once. The package's
 * builds (vite.lib.config.ts, injectCssPlugin) turn each CSS import into a call of this, so a
 * shop's bundler needs no CSS handling and a lazy chunk (the 3D view) brings its styles when it
 * loads. Every rule is scoped under `.luxbox` (docs/embedding.md, "Styles").
 */
export function injectStyle(name: string, css: string): void {
  if (typeof document === 'undefined') return;
  if (document.head.querySelector(`style[data-luxbox="${CSS.escape(name)}"]`)) return;
  const style = document.createElement('style');
  style.dataset.luxbox = name;
  style.textContent = css;
  document.head.append(style);
}
