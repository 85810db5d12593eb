#!/usr/bin/env bash
# The DDS peer of org.miron.dds's tests: a Python venv with Cyclone DDS from PyPI (cyclonedds
# 11.0.1, which bundles its C library) at build/dds-venv. DdsBridgeTest runs its python
# (build/dds-venv/bin/python) and is skipped, with this reason printed, when it is missing.
# Idempotent; never fails the caller: without network or python3-venv it only says why.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/lib/pip-venv.sh"
pip_venv "dds peer" "$root/build/dds-venv" cyclonedds 11.0.1 cyclonedds.domain \
    "the DDS bridge scenarios will be skipped" || exit 0
# The namespace the scenarios run in needs ip (iproute2) and unshare (util-linux).
if ! command -v ip >/dev/null 2>&1 && [ "$(id -u)" -eq 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends iproute2 >&2 || true
fi
exit 0
