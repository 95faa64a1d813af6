import { InputError } from '../../core/inputError';
import type { BillOfMaterials } from '../../core/model/power/billOfMaterials';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import type { LuxboxInstance, LuxboxOptions } from '../embed/types';
import { createMountController, type MountController } from './createMountController';

/** The `detail` of each DOM event `<luxbox-configurator>` dispatches (they bubble and are composed). */
export interface LuxboxElementEventMap {
  /** Mounted (again after a change of attributes or properties). */
  'luxbox-ready': CustomEvent<{ instance: LuxboxInstance }>;
  /** The configuration changed: the scene-file JSON (as mountLuxbox's onChange). */
  'luxbox-change': CustomEvent<{ sceneFile: string }>;
  /** The bill of materials after mounting and after every change (for a cart or a price label). */
  'luxbox-bom': CustomEvent<{ billOfMaterials: BillOfMaterials }>;
  /** Mounting failed: a catalog that does not load or validate, or a bad attribute (an InputError naming it). */
  'luxbox-error': CustomEvent<{ error: Error }>;
}

/** The room attribute: width, depth and height in metres, e.g. `"6 4.5 3"` or `"6x4.5x3"`. */
export function parseRoomAttribute(text: string): { width: number; depth: number; height: number } {
  const parts = text.trim().split(/\s*[x×,\s]\s*/i);
  const numbers = parts.map((p) => (/^\d+(\.\d+)?$/.test(p) ? Number(p) : NaN));
  if (numbers.length !== 3 || numbers.some((n) => !Number.isFinite(n))) throw new InputError(`room attribute: ${JSON.stringify(text)} is not "width depth height" in metres, e.g. "6 4.5 3"`);
  return { width: numbers[0], depth: numbers[1], height: numbers[2] };
}

/** The exposure attribute: 'auto' or an EV100 number (mountLuxbox checks the range). */
function parseExposureAttribute(text: string): 'auto' | number {
  if (text.trim() === 'auto') return 'auto';
  const n = text.trim() === '' ? NaN : Number(text);
  if (!Number.isFinite(n)) throw new InputError(`exposure attribute: ${JSON.stringify(text)} is neither 'auto' nor an EV100 number`);
  return n;
}

// Node (server-side rendering) has no HTMLElement: the class is then defined on a stand-in and never registered.
const ElementBase: typeof HTMLElement = typeof HTMLElement === 'undefined' ? (class {} as unknown as typeof HTMLElement) : HTMLElement;

const OBSERVED = ['catalog', 'room', 'locale', 'quality', 'exposure', 'asset-base'] as const;

/**
 * `<luxbox-configurator>`: the configurator as a custom element, for pages without a bundler
 * (docs/package.md). Attributes (and the same-named properties, which take objects too):
 * `catalog` (URL of a catalog.json), `room` ("6 4.5 3"), `locale`, `quality`, `exposure`,
 * `asset-base` (property `assetBase`); the property `options` takes any other mountLuxbox option.
 * Mounts when connected, remounts (keeping the user's configuration) when one of them changes,
 * unmounts when disconnected. `instance` is the LuxboxInstance once mounted.
 */
export class LuxboxConfiguratorElement extends ElementBase {
  static readonly observedAttributes = OBSERVED;
  /** Asset base used when neither the attribute nor a catalog URL gives one; the single-file script sets its own folder. */
  static defaultAssetBase: string | undefined;

  private controller: MountController | null = null;
  private scheduled = false;
  private catalogValue: string | object | undefined;
  private roomValue: LuxboxOptions['room'];
  private extraOptions: Omit<LuxboxOptions, 'catalog'> = {};

  /** The mounted configurator, or null before mounting, after a failure or when disconnected. */
  get instance(): LuxboxInstance | null {
    return this.controller?.current() ?? null;
  }

  get catalog(): string | object | undefined {
    return this.catalogValue ?? this.getAttribute('catalog') ?? undefined;
  }
  set catalog(value: string | object | undefined) {
    this.catalogValue = value;
    this.schedule();
  }
  get room(): LuxboxOptions['room'] {
    return this.roomValue;
  }
  set room(value: LuxboxOptions['room']) {
    this.roomValue = value;
    this.schedule();
  }
  get locale(): string | null {
    return this.getAttribute('locale');
  }
  set locale(value: string | null) {
    this.reflect('locale', value);
  }
  get quality(): QualityLevel | null {
    return this.getAttribute('quality') as QualityLevel | null;
  }
  set quality(value: QualityLevel | null) {
    this.reflect('quality', value);
  }
  get exposure(): string | null {
    return this.getAttribute('exposure');
  }
  set exposure(value: 'auto' | number | string | null) {
    this.reflect('exposure', value === null ? null : String(value));
  }
  get assetBase(): string | null {
    return this.getAttribute('asset-base');
  }
  set assetBase(value: string | null) {
    this.reflect('asset-base', value);
  }
  /** Any other mountLuxbox option (brand, firstRun, expert, currency, …); attributes and the properties above win. */
  get options(): Omit<LuxboxOptions, 'catalog'> {
    return this.extraOptions;
  }
  set options(value: Omit<LuxboxOptions, 'catalog'>) {
    this.extraOptions = { ...value };
    this.schedule();
  }

  connectedCallback(): void {
    if (!this.style.display) this.style.display = 'block';
    this.schedule();
  }

  disconnectedCallback(): void {
    this.controller?.destroy();
    this.controller = null;
  }

  attributeChangedCallback(): void {
    this.schedule();
  }

  private reflect(name: string, value: string | null): void {
    if (value === null) this.removeAttribute(name);
    else this.setAttribute(name, value);
  }

  /** Attributes and properties set one after another (as a page's script does) make one mount, in a microtask. */
  private schedule(): void {
    if (this.scheduled) return;
    this.scheduled = true;
    queueMicrotask(() => {
      this.scheduled = false;
      if (this.isConnected) void this.mountNow();
    });
  }

  private emit<K extends keyof LuxboxElementEventMap>(type: K, detail: LuxboxElementEventMap[K]['detail']): void {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }

  private async mountNow(): Promise<void> {
    const controller = (this.controller ??= createMountController(this, {
      onMount: (instance) => {
        this.emit('luxbox-ready', { instance });
        this.emit('luxbox-bom', { billOfMaterials: instance.getBillOfMaterials() });
      },
      onError: (error) => this.emit('luxbox-error', { error }),
    }));
    let options: Omit<LuxboxOptions, 'catalog'>;
    try {
      const roomText = this.getAttribute('room');
      const exposureText = this.getAttribute('exposure');
      const assetBase = this.getAttribute('asset-base') ?? this.extraOptions.assetBase ?? (typeof this.catalog === 'string' ? undefined : LuxboxConfiguratorElement.defaultAssetBase);
      options = {
        ...this.extraOptions,
        ...(this.roomValue ? { room: this.roomValue } : roomText !== null ? { room: parseRoomAttribute(roomText) } : {}),
        ...(this.locale !== null ? { locale: this.locale } : {}),
        ...(this.quality !== null ? { quality: this.quality } : {}),
        ...(exposureText !== null ? { exposure: parseExposureAttribute(exposureText) } : {}),
        ...(assetBase !== undefined ? { assetBase } : {}),
        onChange: (sceneFile) => {
          this.extraOptions.onChange?.(sceneFile);
          this.emit('luxbox-change', { sceneFile });
          const instance = this.instance;
          if (instance) this.emit('luxbox-bom', { billOfMaterials: instance.getBillOfMaterials() });
        },
      };
    } catch (e) {
      controller.destroy();
      this.emit('luxbox-error', { error: e as Error });
      return;
    }
    const catalog = this.catalog;
    await controller.mount({ ...(catalog !== undefined ? { catalog } : {}), options });
  }
}

declare global {
  interface HTMLElementTagNameMap {
    'luxbox-configurator': LuxboxConfiguratorElement;
  }
}
