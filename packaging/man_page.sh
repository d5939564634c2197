#!/usr/bin/env bash
# Writes facet's man page, facet.1.gz, from the command line's own help:
# help2man reads `facet --help` and `facet --version`; a COMMANDS section
# holds each command's `facet CMD --help`, so the page never falls behind.
#   man_page.sh FACET OUT.1.gz
set -euo pipefail
facet=$1
out=$2
include=$(mktemp)
page=$(mktemp)
trap 'rm -f "$include" "$page"' EXIT

# roff: a backslash is \e; a line starting with . or ' would be a request.
roff() { sed -e 's/\\/\\e/g' -e "s/^\([.']\)/\\\\\&\1/"; }

commands=$("$facet" --help | sed -n '/^Subcommands:/,/^$/s/^  \([a-z][a-z-]*\) .*/\1/p')
[ -n "$commands" ] || { echo "man_page.sh: no commands in $facet --help" >&2; exit 1; }
{
  echo "[COMMANDS]"
  for command in $commands; do
    echo ".SS \"facet $command\""
    echo ".nf"
    "$facet" "$command" --help | roff
    echo ".fi"
  done
  echo "[FILES]"
  echo "The window of \\fBfacet view\\fR is a program of its own, facet-view, installed under libexec: it alone needs GLFW and X11."
  echo "[SEE ALSO]"
  echo "idiff(1), whose thresholds and exit codes \\fBfacet diff\\fR follows."
} > "$include"
help2man --no-info --no-discard-stderr --section 1 \
  --name "the rendering pipeline of a computer-graphics course: OpenGL and CPU rasterizers, a ray tracer, image comparison" \
  --include "$include" --output "$page" "$facet"
gzip -9n < "$page" > "$out.tmp"
mv "$out.tmp" "$out"
