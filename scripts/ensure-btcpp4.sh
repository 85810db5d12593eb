#!/usr/bin/env bash
# The BehaviorTree.CPP 4 oracle: a Python venv with behaviortreepy (bindings of the real library)
# at build/btcpp4-venv. Tests that compare with the real version-4 library run its python
# (build/btcpp4-venv/bin/python) and are skipped, with this reason printed, when it is missing.
# Idempotent; never fails the caller: without network or python3-venv it only says why.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/lib/pip-venv.sh"
pip_venv "btcpp4 oracle" "$root/build/btcpp4-venv" behaviortreepy 0.1.4 behaviortreepy \
    "version-4 oracle tests will be skipped"
exit 0
