#!/usr/bin/env bash
# The tools of the VS Code end-to-end test (editors/vscode/test/e2e): code-server from npm, in a
# cache outside the repository (~/.cache/miron-e2e/code-server, MIRON_E2E_CACHE overrides
# ~/.cache/miron-e2e), and Chromium, ripgrep and a compiler from apt (editors/vscode/test/e2e/
# install-code-server.sh does the work). Idempotent: a finished install leaves a marker naming
# its version, and a second run only checks it.
# Exit status: 0 ready; 1 skipped because a registry (npm, apt) cannot be reached, with the reason
# on standard error; 2 the install failed for another reason (the test then runs and fails).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
version="${CODE_SERVER_VERSION:-4.100.3}"
cache="${MIRON_E2E_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/miron-e2e}"
dir="$cache/code-server"
marker="$dir/.miron-installed"
skip() { echo "vscode e2e: skipped: $*" >&2; exit 1; }

if [ -f "$marker" ] && [ "$(cat "$marker")" = "$version" ] && [ -x "$dir/node_modules/.bin/code-server" ] \
    && [ -x /usr/bin/chromium ]; then
    exit 0
fi
command -v npm >/dev/null 2>&1 || skip "no npm (Node.js 20+)"
# One look-up of the package we install: tells an unreachable registry from a broken install.
npm view --silent "code-server@$version" version >/dev/null 2>&1 \
    || skip "the npm registry does not answer for code-server@$version"
if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
    for p in chromium ripgrep libkrb5-dev g++ make python3 pkg-config; do
        dpkg -s "$p" >/dev/null 2>&1 || skip "$p is missing and apt-get needs root"
    done
fi
rm -rf "$dir"
mkdir -p "$cache"
log="$cache/install.log"
echo "vscode e2e: installing code-server $version into $dir (log: $log)..." >&2
started=$(date +%s)
if ! CODE_SERVER_VERSION="$version" "$root/editors/vscode/test/e2e/install-code-server.sh" "$dir" >"$log" 2>&1; then
    if grep -qE 'Temporary failure resolving|Could not resolve|Unable to fetch|Failed to fetch|ENOTFOUND|EAI_AGAIN|ETIMEDOUT|ECONNRESET' "$log"; then
        rm -rf "$dir"
        skip "a registry failed while installing code-server (see $log)"
    fi
    tail -n 30 "$log" >&2
    echo "vscode e2e: installing code-server failed (see $log)" >&2
    exit 2
fi
echo "$version" >"$marker"
echo "vscode e2e: code-server $version installed in $(( $(date +%s) - started )) s" >&2
