#!/usr/bin/env bash
# `cmake --install` into a scratch prefix, and the .deb packages CPack
# builds unpacked into a scratch root: from there facet renders the same
# bytes as the build tree's facet, `facet view` finds facet-view, the man
# page and the shell completion are where Debian looks, and the headless
# binary links neither GLFW nor X11.
#   install.sh BUILD_DIR SCRATCH {prefix|deb}
set -euo pipefail
build=$1
scratch=$2
mode=$3
rm -rf "$scratch"
mkdir -p "$scratch"

fail() { echo "FAIL: $*" >&2; exit 1; }

case $mode in
  prefix)
    cmake --install "$build" --prefix "$scratch/usr" --component facet >/dev/null
    cmake --install "$build" --prefix "$scratch/usr" --component viewer >/dev/null
    root=$scratch
    ;;
  deb)
    # CPack computes each package's Depends with dpkg-shlibdeps, which needs file(1).
    for tool in file dpkg-shlibdeps; do
      command -v "$tool" >/dev/null || fail "$tool is not installed (Debian packages file and dpkg-dev, scripts/install-deps.sh)"
    done
    (cd "$build" && cpack -G DEB -B "$scratch/packages" >/dev/null) || fail "cpack failed"
    for deb in "$scratch"/packages/*.deb; do
      dpkg-deb -x "$deb" "$scratch/root"
      package=$(dpkg-deb -f "$deb" Package)
      depends=$(dpkg-deb -f "$deb" Depends)
      # Every dependency (the first of alternatives) is a Debian package this
      # machine has: what apt would have installed with it.
      for dependency in $(echo "$depends" | tr ',' '\n' | sed -e 's/|.*//' -e 's/(.*)//' -e 's/ //g'); do
        [ "$dependency" = facet ] && continue
        dpkg-query -W -f='${Status}' "$dependency" 2>/dev/null | grep -q "install ok installed" ||
          fail "$package depends on $dependency, which is not an installed Debian package"
      done
      if [ "$package" = facet ]; then
        echo "$depends" | grep -qiE 'glfw|libx11' && fail "the facet package depends on GLFW or X11: $depends"
        [ -n "$(dpkg-deb -f "$deb" Recommends)" ] || fail "the facet package recommends no OpenGL driver"
      fi
      echo "$package: Depends: $depends"
    done
    [ -f "$scratch"/packages/facet_*.deb ] || fail "no facet .deb"
    [ -f "$scratch"/packages/facet-viewer_*.deb ] || fail "no facet-viewer .deb"
    root=$scratch/root
    ;;
  *) fail "mode is prefix or deb, not $mode" ;;
esac

facet=$root/usr/bin/facet
[ -x "$facet" ] || fail "no $facet"
[ -x "$root/usr/libexec/facet/facet-view" ] || fail "no usr/libexec/facet/facet-view"

# The headless binary links no window system.
ldd "$facet" | grep -qiE 'libglfw|libX11|libxcb' && fail "$facet links a window system library: $(ldd "$facet" | grep -iE 'glfw|X11|xcb' | tr '\n' ' ')"

# The installed facet renders what the build tree's renders, to the byte.
"$facet" render --backend cpu --size 160x120 -o "$scratch/installed.png" >/dev/null
"$build/app/facet" render --backend cpu --size 160x120 -o "$scratch/built.png" >/dev/null
"$facet" diff --agreement "$scratch/built.png" "$scratch/installed.png" >/dev/null || fail "the installed facet renders other bytes"

# `facet view` runs the installed facet-view (its help, no window needed).
"$facet" view --help | grep -q -- '--screenshot' || fail "facet view --help did not reach facet-view"

# The man page: gzipped roff with each command's help.
page=$root/usr/share/man/man1/facet.1.gz
[ -f "$page" ] || fail "no man page at usr/share/man/man1/facet.1.gz"
for command in info settings render diff bench view; do
  zcat "$page" | grep -q "^\.SS \"facet $command\"" || fail "the man page has no section for facet $command"
done
if command -v man >/dev/null; then
  MANWIDTH=80 man -l "$page" 2>/dev/null | grep -q "^COMMANDS" || fail "man cannot format the page"
fi

# The completion completes commands, options, choices and settings keys
# from the installed facet.
completion=$root/usr/share/bash-completion/completions/facet
[ -f "$completion" ] || fail "no completion at usr/share/bash-completion/completions/facet"
complete_words() {
  PATH="$root/usr/bin:$PATH" bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _facet; echo "${COMPREPLY[*]}"' _ "$completion" "$@"
}
[ "$(complete_words facet ren)" = render ] || fail "facet ren<TAB> gave '$(complete_words facet ren)'"
[ "$(complete_words facet render --backend c)" = cpu ] || fail "--backend c<TAB> gave '$(complete_words facet render --backend c)'"
complete_words facet render --set shadows.pcf | grep -q 'shadows.pcfRadius=' || fail "--set shadows.pcf<TAB> gave no settings key"
[ "$(complete_words facet view --tab ma)" = matrices ] || fail "view --tab ma<TAB> gave '$(complete_words facet view --tab ma)'"
# Without facet-view (a headless install), `facet view` says so in one line
# and exits 1; the other commands are untouched.
if [ "$mode" = prefix ]; then
  rm "$root/usr/libexec/facet/facet-view"
  set +e
  message=$("$facet" view 2>&1 >/dev/null)
  status=$?
  set -e
  [ $status -eq 1 ] || fail "facet view without facet-view exited $status, not 1"
  [ "$(echo "$message" | wc -l)" -eq 1 ] && echo "$message" | grep -q "facet-view is not installed" ||
    fail "facet view without facet-view printed: $message"
  "$facet" render --backend cpu --size 16x16 -o "$scratch/headless.png" >/dev/null || fail "render failed without facet-view"
fi
echo "installed ($mode) into $scratch: renders, runs facet-view, man page and completion in place"
