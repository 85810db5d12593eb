#!/usr/bin/env bash
# The DDS peer of org.miron.dds's tests: a Python venv with Cyclone DDS from PyPI (cyclonedds
# 11.0.1, which bundles its C library) at build/dds-venv. DdsBridgeTest runs its python
# (build/dds-venv/bin/python) and is skipped, with this reason printed, when it is missing.
# Idempotent; never fails the caller: without network or python3-venv it only says why.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$root/build/dds-venv"
version="11.0.1"
marker="$venv/.cyclonedds-$version"
[ -f "$marker" ] && exit 0

reason() { echo "dds peer: not installed: $*; the DDS bridge scenarios will be skipped" >&2; exit 0; }
command -v python3 >/dev/null 2>&1 || reason "no python3"
if ! python3 -c 'import ensurepip, venv' >/dev/null 2>&1; then
    if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo -n); else sudo=(false); fi
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends python3-venv >&2 \
        || reason "python3-venv is missing and could not be installed"
fi
rm -rf "$venv"
python3 -m venv "$venv" >&2 || reason "python3 -m venv failed"
"$venv/bin/pip" install -q --disable-pip-version-check "cyclonedds==$version" >&2 \
    || { rm -rf "$venv"; reason "pip could not install cyclonedds==$version"; }
"$venv/bin/python" -c 'import cyclonedds.domain' >&2 || { rm -rf "$venv"; reason "cyclonedds does not import"; }
# The namespace the scenarios run in needs ip (iproute2) and unshare (util-linux).
if ! command -v ip >/dev/null 2>&1 && [ "$(id -u)" -eq 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends iproute2 >&2 || true
fi
touch "$marker"
echo "dds peer: cyclonedds $version installed in build/dds-venv" >&2
