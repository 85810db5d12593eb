#!/usr/bin/env bash
# Installs code-server (npm) into DIR (default /tmp/code-server) for the end-to-end test, on a
# machine that reaches the npm registry and Debian's apt mirror but not github.com:
#   - code-server's postinstall builds VS Code's native modules (kerberos needs libkrb5-dev) and
#     @vscode/ripgrep downloads rg from api.github.com, which fails offline; so the install skips
#     the scripts, builds the native modules with `npm rebuild`, and uses Debian's ripgrep;
#   - code-server 4.100.x is the newest release that runs on Node.js 20 (later ones want 22+).
# Also installs chromium. Prints the code-server path: CODE_SERVER=... npm run test:e2e
# Usage: install-code-server.sh [DIR]
set -euo pipefail
dir="${1:-/tmp/code-server}"
version="${CODE_SERVER_VERSION:-4.100.3}"

need=()
for p in chromium ripgrep libkrb5-dev g++ make python3 pkg-config; do
    dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
    sudo=(); [ "$(id -u)" -eq 0 ] || sudo=(sudo)
    # Other apt users (CI steps, unattended upgrades) may hold the lock for a while: wait for it.
    lock=(-o DPkg::Lock::Timeout=600)
    "${sudo[@]}" apt-get "${lock[@]}" update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get "${lock[@]}" install -y -qq --no-install-recommends "${need[@]}"
fi

mkdir -p "$dir"
cd "$dir"
[ -f package.json ] || npm init -y >/dev/null
npm install --no-audit --no-fund --ignore-scripts "code-server@$version"
npm rebuild argon2

vscode="$dir/node_modules/code-server/lib/vscode"
(
    cd "$vscode"
    npm install --no-audit --no-fund --omit=dev --ignore-scripts
    mkdir -p node_modules/@vscode/ripgrep/bin
    ln -sf "$(command -v rg)" node_modules/@vscode/ripgrep/bin/rg
    # node-pty's own post-install (compile_commands.json) may fail after its addon is built.
    npm rebuild kerberos @vscode/deviceid @vscode/spdlog native-watchdog node-pty || true
    for addon in node_modules/kerberos/build/Release/kerberos.node node_modules/node-pty/build/Release/pty.node \
        node_modules/@vscode/spdlog/build/Release/spdlog.node node_modules/native-watchdog/build/Release/watchdog.node; do
        [ -f "$addon" ] || { echo "install-code-server: $addon was not built" >&2; exit 1; }
    done
    # What code-server's postinstall.sh does after installing.
    ln -sfn node_modules node_modules.asar
    (cd bin/remote-cli && ln -sf code-linux.sh code-server)
    (cd bin/helpers && ln -sf browser-linux.sh browser.sh)
    (cd extensions && npm install --no-audit --no-fund --omit=dev --ignore-scripts)
)
XDG_CONFIG_HOME="$dir/.config" "$dir/node_modules/.bin/code-server" --version >&2
echo "$dir/node_modules/.bin/code-server"
