#!/usr/bin/env bash
# Headless Chromium for the live monitor's browser test (org.miron.cli LivePageBrowserTest, driven
# over the DevTools protocol with the JDK's clients: no Node, no driver). Debian's chromium package.
# Idempotent; never fails the caller: without apt or network it only says why, and that test is
# skipped, saying so.
set -uo pipefail
for name in chromium chromium-browser google-chrome; do
    command -v "$name" >/dev/null 2>&1 && exit 0
done
reason() { echo "chromium: not installed: $*; the live page's browser test will be skipped" >&2; exit 0; }
if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo -n); else reason "not root and no sudo"; fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get install -y -qq --no-install-recommends chromium >&2 \
    || { "${sudo[@]}" apt-get update -qq >&2 && "${sudo[@]}" apt-get install -y -qq --no-install-recommends chromium >&2; } \
    || reason "apt-get install chromium failed"
echo "chromium: installed (apt)" >&2
