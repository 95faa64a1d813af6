// The package's main door, `luxbox` (docs/package.md): mountLuxbox and its types, the same
// function the standalone app and the shop page example mount (docs/embedding.md). Built with
// the UI on preact (vite.lib.config.ts); `luxbox/react` is the door for React apps.
export { mountLuxbox, EmbedOptionsError } from '../embed/mountLuxbox';
export type { LuxboxOptions, LuxboxInstance, LuxboxActionInfo, LuxboxSceneInfo, LuxboxRunResult } from '../embed/types';
export { loadCatalogFromUrl, type CatalogFolder } from './loadCatalogFromUrl';
export { ACTION_NAMES, type ActionName, type ActionParams } from '../../core/model/actions/actionDefinitions';
export { InputError, type MessageParams } from '../../core/inputError';
export { CatalogError, parseCatalog, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
export { SceneFileError } from '../../core/model/files/sceneFileError';
export type { BillOfMaterials } from '../../core/model/power/billOfMaterials';
export type { InstallationNeeds } from '../../core/model/power/installationNeeds';
export type { ViewerStatus } from '../../ui/viewer/viewerStatus';
export type { GpuViewStatus } from '../../engines/view/controller/gpuRelightFrame';
export type { CompileCounters } from '../../engines/view/createCompileGate';
export type { QualityLevel } from '../../engines/relight/qualityLevels';
export type { Language } from '../../ui/i18n/languages';
export type { LightingScene } from '../../core/model/lightingScene/lightingScene';
