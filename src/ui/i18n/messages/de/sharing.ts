// Copying and sharing the share link.
import type { AreaMessages } from '../../messageTypes';
import type en from '../en/sharing';

export default {
  copyLink: 'Link kopieren',
  shareVia: 'Teilen…',
  shareTitle: 'Meine Lichtplanung',
  linkCopied: 'Link kopiert.',
  linkCopyFailed: 'Dieser Browser erlaubt das Kopieren nicht: Link markieren und kopieren.',
  linkShared: 'Link geteilt.',
} satisfies AreaMessages<typeof en>;
