// Copying and sharing the share link.
import type { AreaMessages } from '../../messageTypes';
import type en from '../en/sharing';

export default {
  copyLink: 'Copia link',
  shareVia: 'Condividi…',
  shareTitle: 'Il mio progetto di illuminazione',
  linkCopied: 'Link copiato.',
  linkCopyFailed: 'Questo browser non consente la copia: seleziona il link e copialo.',
  linkShared: 'Link condiviso.',
} satisfies AreaMessages<typeof en>;
