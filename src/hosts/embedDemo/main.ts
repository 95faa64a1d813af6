/**
 * The demo shop page (embed.html): a product page that embeds luxbox and talks to it only
 * through the public API of docs/embedding.md — options on mount, onChange, getBillOfMaterials,
 * listActions/runAction, undo/redo, destroy. No React and no luxbox internals on the host side.
 */
import { mountLuxbox } from '../embed/mountLuxbox';
import type { LuxboxInstance } from '../embed/types';
import { formatMoney } from '../../ui/planner/formatMoney';
import { addToCart, cartTotal, type CartLine } from './cart';
import { fetchCatalogFolder } from '../embed/fetchCatalogFolder';
import { SHOP_ROOM, SHOP_VARIANTS, shopVariant } from './shopVariants';
import './shop.css';

declare global {
  interface Window {
    /** The demo shop's handle on its embedded instance (null while closed); e2e/embedHost.spec.ts uses it. */
    shopDemo?: { readonly instance: LuxboxInstance | null; readonly changes: number };
  }
}

interface PresetData {
  id: string;
  name: string;
  description: string;
}

function byId<T extends HTMLElement = HTMLElement>(id: string): T {
  const found = document.getElementById(id);
  if (!found) throw new Error(`embed.html lacks #${id}`);
  return found as T;
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, props: Partial<HTMLElementTagNameMap[K]> = {}, ...children: (Node | string)[]): HTMLElementTagNameMap[K] {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}

const query = new URLSearchParams(location.search);
const shop = shopVariant(query.get('shop'));
const firstRun = query.get('firstRun');
// `?catalog=<url of a catalog.json>` opens the configurator on a catalog folder as `luxbox catalog import`
// writes it, as the standalone app does (docs/gldf.md): its JSON as `catalog`, its folder as `assetBase`,
// and an autosave of its own so the shop's usual catalog's plan is not mixed in.
const catalogUrl = query.get('catalog');
let catalogData: unknown = shop.catalog;
let catalogAssets: string | undefined;
let presets = (shop.catalog as { presets: PresetData[] }).presets;
const money = (x: number) => formatMoney(x, shop.currency, shop.locale);
const count = (x: number) => new Intl.NumberFormat(shop.locale).format(x);

const host = byId('configurator');
const closedNote = byId('configurator-closed');
const totalOut = byId('host-total');
const metaOut = byId('host-meta');
const bomBody = byId('host-bom');
const actionList = byId('host-actions');
const cartList = byId('cart');
const cartTotalOut = byId('cart-total');
const addButton = byId<HTMLButtonElement>('add-to-cart');
const toggleButton = byId<HTMLButtonElement>('toggle-configurator');
const undoButton = byId<HTMLButtonElement>('host-undo');
const redoButton = byId<HTMLButtonElement>('host-redo');

let instance: LuxboxInstance | null = null;
let changes = 0;
let cart: CartLine[] = [];
let hostMessage = '';

window.shopDemo = {
  get instance() {
    return instance;
  },
  get changes() {
    return changes;
  },
};

function renderRegions(): void {
  byId('region').replaceChildren(...SHOP_VARIANTS.map((v) => element('a', { href: `?shop=${v.id}`, className: v.id === shop.id ? 'current' : '', textContent: v.label })));
  for (const a of byId('region').querySelectorAll('a.current')) a.setAttribute('aria-current', 'page');
}

function renderConfiguration(lx: LuxboxInstance | null): void {
  const bom = lx?.getBillOfMaterials();
  totalOut.textContent = bom ? money(bom.total) : '—';
  metaOut.textContent = bom ? `${count(bom.watts)} W · ${count(bom.lumens)} lm · incl. VAT` : '';
  bomBody.replaceChildren(
    ...(bom && bom.lines.length > 0
      ? bom.lines.map((l) => element('tr', {}, element('td', { className: 'num' }, `${l.count}×`), element('td', {}, l.name), element('td', { className: 'num' }, money(l.total))))
      : [element('tr', {}, element('td', { className: 'muted', colSpan: 3 }, bom ? 'Nothing placed yet.' : 'Open the configurator to plan a system.'))]),
  );
  addButton.disabled = !bom || bom.lines.length === 0;
}

function renderActions(lx: LuxboxInstance | null): void {
  actionList.replaceChildren(
    ...presets.map((p) => {
      // One listActions call per preset: its verdict depends on the parameters (which preset).
      const listing = lx?.listActions({ placePreset: { presetId: p.id } }).find((a) => a.name === 'placePreset');
      const reason = !listing ? 'the configurator is closed' : listing.reason;
      const button = element('button', { type: 'button', className: 'shop-btn', disabled: !listing?.enabled, title: reason ?? p.description, textContent: `Place “${p.name}”` });
      button.dataset.testid = `host-action-${p.id}`;
      button.addEventListener('click', () => {
        const r = instance?.runAction('placePreset', { presetId: p.id });
        hostMessage = r && !r.ok ? r.reason : '';
        render();
      });
      const note = element('span', { className: reason ? 'action-reason' : 'action-detail', textContent: reason ?? p.description });
      note.dataset.testid = `host-action-note-${p.id}`;
      return element('li', {}, button, note);
    }),
    ...(hostMessage ? [element('li', { className: 'action-reason', role: 'status', textContent: hostMessage })] : []),
  );
  undoButton.disabled = !lx;
  redoButton.disabled = !lx;
}

function renderCart(): void {
  cartList.replaceChildren(
    ...(cart.length > 0
      ? cart.map((l) =>
          element(
            'li',
            {},
            element('span', { className: 'cart-article', textContent: l.article }),
            element('span', { className: 'cart-name', textContent: `${l.count}× ${l.name}` }),
            element('span', { className: 'num', textContent: money(l.total) }),
          ),
        )
      : [element('li', { className: 'muted', textContent: 'Your cart is empty.' })]),
  );
  cartTotalOut.textContent = money(cartTotal(cart));
}

function render(): void {
  renderConfiguration(instance);
  renderActions(instance);
  renderCart();
}

function open(): void {
  host.hidden = false;
  closedNote.hidden = true;
  instance = mountLuxbox(host, {
    room: SHOP_ROOM,
    // The storefront's locale picks the configurator's language and formatting (de-DE: German); `?locale=fr-CH` tries another.
    locale: query.get('locale') ?? shop.locale,
    currency: shop.currency,
    catalog: catalogData,
    storageKey: catalogUrl ? `${shop.storageKey}.catalog` : shop.storageKey,
    // A shop may serve the photometry from its own asset folder (?assetBase=/cdn/ tries it).
    assetBase: query.get('assetBase') ?? catalogAssets,
    // The empty plan's suggestions: the best for the room by default; `?firstRun=corner-l,single` tries a shop's own list, `?firstRun=off` none.
    firstRun: firstRun === null ? undefined : firstRun === 'off' ? false : { presets: firstRun.split(',') },
    // The shop's own name in the configurator's header (`?brand=none` shows none); the API's texts in the
    // configurator's language unless `?apiLanguage=en` asks for the core's English (docs/embedding.md).
    brand: query.get('brand') === 'none' ? null : { name: 'Lichtwerk' },
    apiLanguage: query.get('apiLanguage') === 'en' ? 'en' : 'ui',
    // The shop decides on the expert tools (DMX live control, Radiance download, photometric data notes):
    // none by default; `?expert=on` shows them, `?expert=switch` offers the user the switch.
    ...(query.get('expert') === 'on' ? { expert: true } : query.get('expert') === 'switch' ? { expert: 'switch' as const } : {}),
    onChange: () => {
      // Everything the host shows is re-read through the API after each change.
      changes++;
      render();
    },
  });
  toggleButton.textContent = 'Close configurator';
  render();
  // Once the configurator's language has loaded, the API's texts (reasons, BOM names) come in it: show them again.
  const mounted = instance;
  void mounted.whenReady().then(() => {
    if (instance === mounted) render();
  });
}

function close(): void {
  instance?.destroy();
  instance = null;
  host.hidden = true;
  closedNote.hidden = false;
  toggleButton.textContent = 'Open configurator';
  hostMessage = '';
  render();
}

addButton.addEventListener('click', () => {
  if (!instance) return;
  cart = addToCart(cart, instance.getBillOfMaterials().lines);
  render();
});
toggleButton.addEventListener('click', () => (instance ? close() : open()));
undoButton.addEventListener('click', () => instance?.undo());
redoButton.addEventListener('click', () => instance?.redo());

renderRegions();
if (catalogUrl) {
  fetchCatalogFolder(catalogUrl, location.href).then(
    (folder) => {
      catalogData = folder.catalog;
      catalogAssets = folder.assetBase;
      presets = (folder.catalog as { presets?: PresetData[] }).presets ?? [];
      open();
    },
    (e: Error) => (closedNote.textContent = `The catalog ${catalogUrl} could not be loaded: ${e.message}`),
  );
} else open();
