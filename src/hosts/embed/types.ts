import type { ActionName, ActionParams } from '../../core/model/actions/actionDefinitions';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import type { BillOfMaterials } from '../../core/model/power/billOfMaterials';
import type { InstallationNeeds } from '../../core/model/power/installationNeeds';
import type { ViewerStatus } from '../../ui/viewer/viewerStatus';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import type { Language } from '../../ui/i18n/languages';

/** Options of mountLuxbox (docs/embedding.md). */
export interface LuxboxOptions {
  /** Catalog data (parsed JSON in the documented format); default: the bundled demo catalog. */
  catalog?: unknown;
  /** Start directly on the plan of this room (metres) instead of the room-setup screen. */
  room?: { width: number; depth: number; height: number };
  /**
   * BCP 47 tag or preference list choosing the UI language (en, de, fr, it) and the formatting
   * of numbers, prices and dates, e.g. 'de-CH' (German texts, Swiss formatting); default: the
   * browser's navigator.languages (docs/i18n.md, "Locale resolution").
   */
  locale?: string | readonly string[];
  /** Show the language switch in the top bar; default false (the shop chooses the locale). The standalone app turns it on. */
  languageSwitch?: boolean;
  /**
   * 'region' (default): luxbox is one region landmark named "luxbox lighting configurator" inside the
   * host's page, which keeps its own banner and main. 'page': luxbox is the whole page (the standalone
   * app): its header is the banner and the plan the main (docs/accessibility.md, "Landmarks").
   */
  landmarks?: 'page' | 'region';
  /** Called after the user switched the language with the switch or setLanguage (the standalone app stores it). */
  onLanguageChange?: (language: Language) => void;
  /** ISO 4217 code the shop expects; must equal the catalog's currency (prices are never converted). */
  currency?: string;
  /** Called with the scene-file JSON after every change of the configuration. */
  onChange?: (sceneFileJson: string) => void;
  /** localStorage key for autosave; omitted or false: no autosave. The standalone app uses 'luxbox.autosave.v1'. */
  storageKey?: string | false;
  /** With nothing saved and no link or room, open the demo room with a preset instead of the room setup. */
  demo?: boolean;
  /** URL prefix under which the catalog's photometry paths ('ies/...') are served; default: the app's base URL. */
  assetBase?: string;
  /** Read a share link from location.hash at start (`#c=...`); default false. The standalone app turns it on. */
  shareLinks?: boolean;
  /**
   * Pins the 3D bake quality ('fast' | 'balanced' | 'best') over the user's stored choice
   * (docs/viewer.md, "Quality levels"); the user can still switch in the 3D panel.
   */
  quality?: QualityLevel;
  /**
   * Keep the user's quality choice and this device's bake calibration in localStorage
   * ('luxbox.quality', 'luxbox.calibration'); default false (an embedded configurator writes only
   * under storageKey). The standalone app turns it on.
   */
  rememberQuality?: boolean;
  /**
   * How the 3D view exposes (docs/viewer.md, "Exposure"): 'auto' (default; every configuration shown at the
   * same mean brightness) or a fixed EV100 in -6..20 (e.g. 5.5), so a dimmed configuration looks darker.
   * The user can still switch to auto or lock another value in the 3D panel.
   */
  exposure?: 'auto' | number;
  /**
   * How the 3D view adapts to the colour of the light (docs/viewer.md, "Adaptation"): 'eye' (default;
   * as a person in the room sees it, CAT16 with CAM16's degree of adaptation), 'camera:<K>' (a
   * camera's white balance at that colour temperature, 1000..20000, e.g. 'camera:3000') or 'none'
   * (the physical colour). The user can change it in the 3D panel.
   */
  adapt?: string;
  /**
   * The maker shown in the configurator's header instead of "luxbox": `{ name }` or `{ name, logo }`
   * (an image URL; the name is its text alternative), or null for no brand at all. Default luxbox.
   */
  brand?: { name: string; logo?: string } | null;
  /**
   * The language of the texts the API returns — bill-of-materials names, refusal reasons of
   * runAction / listActions / recordScene / recall: 'ui' (default) the configurator's own language,
   * so a German shop shows German everywhere; 'en' the core's English sentences (for logs).
   */
  apiLanguage?: 'ui' | 'en';
  /**
   * The empty plan's first step (docs/embedding.md, "First run"): a sentence and the presets that fit
   * the room best, one tap each. `false` hides it; `{ presets: ['corner-l', 'single'] }` offers the
   * shop's own choice (in that order, those that fit the room, at most three; ids the catalog lacks are left out); `{ presets: false }`
   * keeps the sentence and the way to all presets without suggestions. Default: the best three.
   */
  firstRun?: false | { presets?: readonly string[] | false };
  /**
   * The expert tools (docs/embedding.md, "Expert tools": DMX live control, the Radiance download,
   * the photometric files' data notes): `false` (default) hides them and offers no switch, `true`
   * shows them without a switch, `'switch'` puts an Expert switch in the side panel, off at first.
   */
  expert?: boolean | 'switch';
  /** With `expert: 'switch'`: keep the user's choice in localStorage (`luxbox.expert`); default off. The standalone app turns it on. */
  rememberExpert?: boolean;
  /** Called after the user switched the expert tools on or off. */
  onExpertChange?: (on: boolean) => void;
}

export interface LuxboxActionInfo {
  name: ActionName;
  label: string;
  enabled: boolean;
  /** Why it is disabled (null when enabled). */
  reason: string | null;
}

/** A light scene as the embedding API lists it. */
export interface LuxboxSceneInfo {
  id: string;
  name: string;
  /** Crossfade time, seconds. */
  fade: number;
  /** The scene recalled last (GO / BACK step from it). */
  current: boolean;
}

export type LuxboxRunResult = { ok: true } | { ok: false; reason: string };

/** runAction's parameters after the name: optional when the action's parameters have no required field. */
export type LuxboxActionArguments<N extends ActionName> = object extends ActionParams<N> ? [params?: ActionParams<N>] : [params: ActionParams<N>];

/** A mounted configurator. */
export interface LuxboxInstance {
  /** The current configuration as scene-file JSON (format 'luxbox-configuration'). */
  getConfig(): string;
  /** Replaces the configuration (undoable). Accepts JSON text or the parsed object; throws an InputError naming the problem. */
  setConfig(sceneFile: string | object): void;
  /** Calls listener with the scene-file JSON after every change; returns the unsubscribe function. */
  subscribe(listener: (sceneFileJson: string) => void): () => void;
  getBillOfMaterials(): BillOfMaterials;
  /** What the installer must know for the cart hand-off: feeds with load and capacity, ceiling fixings, total load (docs/model.md). */
  getInstallationNeeds(): InstallationNeeds;
  /** Every action with its enabled state for the given parameters (per action name, each typed as runAction's). */
  listActions(paramsByName?: { readonly [N in ActionName]?: ActionParams<N> }): LuxboxActionInfo[];
  /**
   * Runs an action by name if the model allows it. Typed: `name` is one of the model's actions
   * (ActionName) and `params` that action's parameters (ActionParams, from its schema; optional
   * where every field is). At run time it never throws, also for names and parameters the types
   * would refuse (from plain JavaScript): it refuses them with a reason.
   */
  runAction<N extends ActionName>(name: N, ...params: LuxboxActionArguments<N>): LuxboxRunResult;
  undo(): boolean;
  redo(): boolean;
  /** A link that opens this configuration (base URL + `#c=<share string>`). */
  getShareLink(): string;
  /** The lighting scene the baker and `luxbox bake` take (docs/scene-format.md), for the current configuration. */
  getLightingScene(): LightingScene;
  /**
   * Resolves once the configurator's language is loaded (the API's texts then come in it, option
   * apiLanguage) and everything getLightingScene needs for the current configuration is loaded: the
   * colour-filter spectra, fetched when a module or light scene first uses a filter (until then
   * getLightingScene of such a configuration throws an InputError saying so). Resolves at once
   * for English and a configuration without filters.
   */
  whenReady(): Promise<void>;
  /** State of the 3D view (docs/viewer.md): bake progress, counters (group bakes vs relights), floor lux; `open: false` in 2D; `bake`: the background bake service, also while 3D is closed. */
  view3d(): ViewerStatus;
  /** The UI language and the formatting locale in use, e.g. { language: 'de', locale: 'de-CH' }. */
  getLanguage(): { language: Language; locale: string };
  /** Switches the UI language (en, de, fr, it) without touching the configuration; resolves once the new texts show. Throws an InputError for another value. */
  setLanguage(language: Language): Promise<void>;
  /** The configuration's light scenes in playback order (docs/light-scenes.md). */
  scenes(): LuxboxSceneInfo[];
  /** Records every module's current on/off, level, colour temperature and filter as a new scene (undoable). */
  recordScene(name: string): LuxboxRunResult;
  /**
   * Recalls a scene by name (case-insensitive) with a crossfade of `fade` seconds (default: the
   * scene's own); resolves when the fade has ended, with `ok: false` and the reason if refused.
   */
  recall(name: string, options?: { fade?: number }): Promise<LuxboxRunResult>;
  /** Unmounts and releases everything; the instance must not be used afterwards. */
  destroy(): void;
}
