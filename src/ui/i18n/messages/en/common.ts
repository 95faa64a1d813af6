// Texts shared by several screens: the language switch, generic buttons, the banner.
export default {
  languageLabel: 'Language',
  dismissMessage: 'Dismiss message',
  close: 'Close',
  cancel: 'Cancel',
  ok: 'OK',
  loading: 'Loading…',
  notANumber: '{label}: "{value}" is not a number',
  labelWithReason: '{label}: {reason}',
};
