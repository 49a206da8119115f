#!/usr/bin/env bash
# build_slides.sh DECK FIGURE_DIR OUT_DIR: builds slides/DECK.tex into OUT_DIR/DECK.pdf. DECK
# "course" is every chapter deck in one PDF: they must be in OUT_DIR already.
# Figures resolve through TEXINPUTS against FIGURE_DIR (\includegraphics{01-free-fall/x.pdf}),
# so a missing or misnamed figure stops the build with an error.
set -euo pipefail
deck=$1 figures=$2 out=$3
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ -f "$root/slides/$deck.tex" ] || { echo "build_slides: no deck slides/$deck.tex" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd) figures=$(cd "$figures" && pwd)  # gnuplot runs from a figure's folder
if [ "$deck" = course ]; then
  # The course includes every chapter deck, built first into OUT_DIR: list them, with the title
  # each deck gives itself, for course.tex.
  : >"$out/course-decks.tex.tmp"
  for tex in "$root"/slides/[0-9][0-9]-*.tex; do
    name=$(basename "$tex" .tex)
    [ -f "$out/$name.pdf" ] || { echo "build_slides: course: build the deck $name first ($out/$name.pdf)" >&2; exit 2; }
    title=$(sed -n 's/^\\title{\(.*\)}$/\1/p' "$tex" | head -1)
    printf '\\kitdeck{%s}{%s}\n' "$name" "${title:-$name}" >>"$out/course-decks.tex.tmp"
  done
  mv "$out/course-decks.tex.tmp" "$out/course-decks.tex"
fi
log="$out/$deck.latexmk.log"
latex() {
  if ! TEXINPUTS="$out:$figures//:$root/slides//:" latexmk -g -pdf -interaction=nonstopmode -halt-on-error \
        -outdir="$out" "$root/slides/$deck.tex" >"$log" 2>&1; then
    echo "build_slides: $deck failed; the end of the LaTeX log:" >&2
    grep -E -A3 "^!|not found" "$out/$deck.log" >&2 || tail -30 "$log" >&2
    exit 1
  fi
}
latex
# Each figure again, at the size of its slot on the slide (kit-slides.sty, \kitfigure), with 9 pt
# text; then the deck once more, which places them at 1:1. 1 in = 72.27 pt = 72.27 * 65536 sp.
inches() { awk -v sp="$1" 'BEGIN { printf "%.4f", sp / (72.27 * 65536) }'; }
if [ -s "$out/$deck.kitfigures" ]; then
  while read -r name width height; do
    slide="$out/slide-figures/$name-${width}x${height}.pdf"
    script="$figures/$name.gp"
    [ -f "$slide" ] && [ "$slide" -nt "$script" ] && [ "$slide" -nt "$figures/$name.dat" ] && continue
    mkdir -p "$(dirname "$slide")"
    if ! (cd "$(dirname "$script")" && gnuplot -e "fmt='pdf'; out='$slide.tmp'; width_in=$(inches "$width");
          height_in=$(inches "$height"); font_pt=9" "$(basename "$script")") 2>"$slide.log"; then
      echo "build_slides: gnuplot could not redraw $name for its slide:" >&2
      cat "$slide.log" >&2
      exit 1
    fi
    rm -f "$slide.log"
    mv "$slide.tmp" "$slide"
  done < <(sort -u "$out/$deck.kitfigures")
  latex
fi
echo "slides: $out/$deck.pdf"
