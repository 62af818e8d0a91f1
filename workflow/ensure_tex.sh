#!/usr/bin/env bash
# Make sure latexmk and the LaTeX packages of paper/ms.tex are present (Debian's TeX Live).
set -euo pipefail
packages="latexmk texlive-latex-base texlive-latex-recommended texlive-latex-extra texlive-fonts-recommended"
if command -v latexmk >/dev/null 2>&1 && kpsewhich natbib.sty booktabs.sty caption.sty upgreek.sty >/dev/null 2>&1; then
  exit 0
fi
if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
  echo "ensure_tex: installing TeX Live from Debian's packages ($packages)" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $packages >/dev/null
else
  echo "ensure_tex: latexmk/TeX Live missing and not root: install the Debian packages $packages" \
       "(or an equivalent TeX distribution) and run again" >&2
  exit 1
fi
