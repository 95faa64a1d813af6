import { useStore } from 'zustand';
import type { UiStore } from '../../core/store/uiStore';

/**
 * The maker in the configurator's header (issue #27, "Embed speaks one language"): luxbox by
 * default, the shop's or manufacturer's name (and logo) when the embedding sets `brand`, nothing
 * when it sets `brand: null`. A logo keeps the name as its text alternative, so the heading still
 * names the page for screen readers.
 */
export function BrandMark({ ui }: { ui: UiStore }) {
  const brand = useStore(ui, (s) => s.brand);
  if (!brand) return null;
  return <h1 className="brand-mark">{brand.logo ? <img src={brand.logo} alt={brand.name} className="brand-logo" data-testid="brand-logo" /> : brand.name}</h1>;
}
