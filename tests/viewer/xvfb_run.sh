#!/bin/sh
# xvfb-run with an X authority file of the test's own. Without -f, Debian
# 12's xvfb-run makes a temporary folder for that file and, when the command
# ends, removes the folder before it stops Xvfb, which may still write
# there: the removal fails and xvfb-run exits 5 in place of the command's
# own code (seen twice in a row in a sanitizer run). With -f there is no
# folder to remove.
set -u
auth=$(mktemp "${TMPDIR:-/tmp}/facet-xauth.XXXXXX") || exit 1
xvfb-run -f "$auth" "$@"
rc=$?
rm -f "$auth" "$auth-c" "$auth-l" "$auth-n"
exit "$rc"
