#!/usr/bin/env bash
# The libzmq peer of the end-to-end benchmarks (docs/performance.md, issue 39): a Python venv with
# pyzmq from PyPI (27.3.0, whose wheel bundles libzmq) at build/pyzmq-venv. The benchmarks run its
# python (build/pyzmq-venv/bin/python) on org.miron.runtime/src/test/python/zmq_path.py and print
# "not measured: <reason>" for the libzmq floor when it is missing.
# Idempotent; never fails the caller: without network or python3-venv it only says why.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$root/scripts/lib/pip-venv.sh"
pip_venv "libzmq peer" "$root/build/pyzmq-venv" pyzmq 27.3.0 zmq \
    "the benchmarks will not measure the libzmq floor" || exit 0
exit 0
