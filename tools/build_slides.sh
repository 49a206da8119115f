#!/usr/bin/env bash
# build_slides.sh DECK FIGURE_DIR OUT_DIR: builds slides/DECK.tex into OUT_DIR/DECK.pdf.
# Figures resolve through TEXINPUTS against FIGURE_DIR (\includegraphics{01-free-fall/x.pdf}),
# so a missing or misnamed figure stops the build with an error.
set -euo pipefail
deck=$1 figures=$2 out=$3
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ -f "$root/slides/$deck.tex" ] || { echo "build_slides: no deck slides/$deck.tex" >&2; exit 2; }
mkdir -p "$out"
log="$out/$deck.latexmk.log"
if ! TEXINPUTS="$figures//:$root/slides//:" latexmk -g -pdf -interaction=nonstopmode -halt-on-error \
      -outdir="$out" "$root/slides/$deck.tex" >"$log" 2>&1; then
  echo "build_slides: $deck failed; the end of the LaTeX log:" >&2
  grep -E -A3 "^!|not found" "$out/$deck.log" >&2 || tail -30 "$log" >&2
  exit 1
fi
echo "slides: $out/$deck.pdf"
