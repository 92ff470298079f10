#!/usr/bin/env bash
# The print hosts the end-to-end tests send G-code to (test/e2e/print-hosts.ts), from PyPI, pinned: OctoPrint
# (with its virtual printer) and Moonraker, one virtualenv each (their dependencies conflict), under
# $STRATA_PRINT_HOSTS (default ~/.cache/strata/print-hosts). Kept between runs: a venv is made again only
# when its pinned version changes. Needs python3 with venv (tested: 3.11) and libsodium (Moonraker's libnacl).
set -euo pipefail
DIR="${STRATA_PRINT_HOSTS:-$HOME/.cache/strata/print-hosts}"
PYTHON="${PYTHON:-python3}"
OCTOPRINT_SPEC="OctoPrint==1.11.8"
MOONRAKER_SPEC="moonraker==0.11.0"

install() {
  local name="$1" spec="$2"
  local marker="$DIR/$name/.installed-$spec"
  [ -f "$marker" ] && return 0
  rm -rf "${DIR:?}/$name"
  "$PYTHON" -m venv "$DIR/$name"
  "$DIR/$name/bin/pip" install -q --disable-pip-version-check --no-input "$spec"
  touch "$marker"
}

mkdir -p "$DIR"
start=$SECONDS
install octoprint "$OCTOPRINT_SPEC" & octoprint=$!
install moonraker "$MOONRAKER_SPEC" & moonraker=$!
wait "$octoprint"
wait "$moonraker"
echo "print hosts ready in $DIR ($((SECONDS - start)) s)"
