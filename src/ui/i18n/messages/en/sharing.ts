// Copying and sharing the share link (ShareLinkField, a lazy chunk that registers these English texts).
export default {
  copyLink: 'Copy link',
  shareVia: 'Share…',
  shareTitle: 'My lighting plan',
  linkCopied: 'Link copied.',
  linkCopyFailed: 'This browser did not allow copying: select the link and copy it.',
  linkShared: 'Link shared.',
};
