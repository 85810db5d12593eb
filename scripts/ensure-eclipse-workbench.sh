#!/usr/bin/env bash
# What the Eclipse workbench test (org.miron.eclipse WorkbenchTest) needs besides Maven Central:
# Xvfb to run the workbench in, GTK 3 for SWT, ImageMagick's `import` for its screenshot, and a
# Java 21+ for current platform bundles (these machines ship Temurin 25 at
# /usr/lib/jvm/temurin-25-jdk-amd64; MIRON_WORKBENCH_JAVA names another java). Debian's packages.
# Idempotent, bounded (apt gets 5 minutes); never fails the caller: without apt or network it
# only says why, and the test is skipped, saying so.
set -uo pipefail
java="${MIRON_WORKBENCH_JAVA:-/usr/lib/jvm/temurin-25-jdk-amd64/bin/java}"
[ -x "$java" ] || echo "eclipse workbench: no Java 21+ at $java: the workbench test will be skipped" >&2
packages=(xvfb libgtk-3-0 imagemagick xauth libxtst6 dbus-x11 fonts-dejavu-core)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ "${#missing[@]}" -eq 0 ] && exit 0
reason() { echo "eclipse workbench: ${missing[*]} not installed: $*; the workbench test will be skipped" >&2; exit 0; }
if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo -n); else reason "not root and no sudo"; fi
export DEBIAN_FRONTEND=noninteractive
install() { timeout 300 "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2; }
install || { timeout 120 "${sudo[@]}" apt-get update -qq >&2 && install; } || reason "apt-get install failed"
echo "eclipse workbench: installed ${missing[*]} (apt)" >&2
