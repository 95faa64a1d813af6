// English messages of the core's codes (docs/i18n.md, "Messages from the core", "Bundles"). An
// English page shows the core's own sentences, so these ship with the other languages' chunks:
// loadMessages registers them with the English tree (every language's fallback and the source of
// isMessageKey) when it loads German, French or Italian.
import fileErrors from './fileErrors';
import photometry from './photometry';
import refusals from './refusals';

export default {
  fileErrors,
  photometry,
  refusals,
};
