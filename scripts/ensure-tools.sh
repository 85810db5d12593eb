#!/usr/bin/env bash
# Installs what the build and the runtime need when missing: Debian's gradle (4.4.1) and
# minizinc (with Gecode). Idempotent: does nothing when both are on the PATH.
set -euo pipefail
missing=()
command -v gradle >/dev/null 2>&1 || missing+=(gradle)
command -v minizinc >/dev/null 2>&1 || missing+=(minizinc)
command -v java >/dev/null 2>&1 || missing+=(default-jdk-headless)
[ ${#missing[@]} -eq 0 ] && exit 0

echo "miron: installing ${missing[*]} (apt)" >&2
if [ "$(id -u)" -eq 0 ]; then
    sudo=()
elif command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
else
    echo "miron: please install ${missing[*]} (apt-get install ${missing[*]}) and retry" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq >&2
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
