#!/usr/bin/env bash
# Builds the VS Code extension without Gradle: npm ci, npm test (which compiles the extension and
# bundles the diagram webview with esbuild into pack/webview.js; JUnit XML in
# editors/build/test-results/test/) and vsce package into editors/vscode/build/miron-vscode.vsix.
# Needs Node.js 20+ with npm, and the npm registry (or a populated npm cache) for npm ci.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root/editors/vscode"
if ! command -v npm >/dev/null 2>&1; then
    echo "build-vscode: npm is missing (install Node.js 20 or later)" >&2
    exit 1
fi
major="$(node -p 'process.versions.node.split(".")[0]')"
if [ "$major" -lt 20 ]; then
    echo "build-vscode: Node.js $(node -v) is too old: @vscode/vsce needs 20 or later" >&2
    exit 1
fi
npm ci --no-audit --no-fund
npm test
npm run package
echo "VS Code extension: $root/editors/vscode/build/miron-vscode.vsix"
