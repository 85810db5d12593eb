#!/usr/bin/env bash
# The BehaviorTree.CPP 4 oracle: a Python venv with behaviortreepy (bindings of the real library)
# at build/btcpp4-venv. Tests that compare with the real version-4 library run its python
# (build/btcpp4-venv/bin/python) and are skipped, with this reason printed, when it is missing.
# Idempotent; never fails the caller: without network or python3-venv it only says why.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$root/build/btcpp4-venv"
version="0.1.4"
marker="$venv/.behaviortreepy-$version"
[ -f "$marker" ] && exit 0

reason() { echo "btcpp4 oracle: not installed: $*; version-4 oracle tests will be skipped" >&2; exit 0; }
command -v python3 >/dev/null 2>&1 || reason "no python3"
if ! python3 -c 'import ensurepip, venv' >/dev/null 2>&1; then
    # Debian splits venv/ensurepip into python3-venv.
    if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo -n); else sudo=(false); fi
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends python3-venv >&2 \
        || reason "python3-venv is missing and could not be installed"
fi
rm -rf "$venv"
python3 -m venv "$venv" >&2 || reason "python3 -m venv failed"
"$venv/bin/pip" install -q --disable-pip-version-check "behaviortreepy==$version" >&2 \
    || { rm -rf "$venv"; reason "pip could not install behaviortreepy==$version"; }
"$venv/bin/python" -c 'import behaviortreepy' >&2 || { rm -rf "$venv"; reason "behaviortreepy does not import"; }
touch "$marker"
echo "btcpp4 oracle: behaviortreepy $version installed in build/btcpp4-venv" >&2
