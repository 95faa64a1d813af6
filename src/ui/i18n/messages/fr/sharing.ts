// Copying and sharing the share link.
import type { AreaMessages } from '../../messageTypes';
import type en from '../en/sharing';

export default {
  copyLink: 'Copier le lien',
  shareVia: 'Partager…',
  shareTitle: 'Mon projet d’éclairage',
  linkCopied: 'Lien copié.',
  linkCopyFailed: 'Ce navigateur n’autorise pas la copie : sélectionnez le lien et copiez-le.',
  linkShared: 'Lien partagé.',
} satisfies AreaMessages<typeof en>;
