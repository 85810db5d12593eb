# Sourced by the ensure-*.sh scripts that put a PyPI package in a venv of its own under build/.
# pip_venv LABEL VENV PACKAGE VERSION IMPORT SKIPPED: installs PACKAGE==VERSION into VENV once (a
# marker file records it), checks that `import IMPORT` works, and prints what was done. Never fails
# the caller: without python3, python3-venv or the registry it says why ("LABEL: not installed: ...;
# SKIPPED") and returns 1, so the tests that need it are skipped with that reason.
pip_venv() {
    local label="$1" venv="$2" package="$3" version="$4" module="$5" skipped="$6"
    local marker="$venv/.$package-$version"
    [ -f "$marker" ] && return 0
    _pip_venv_refuse() { echo "$label: not installed: $*; $skipped" >&2; }
    command -v python3 >/dev/null 2>&1 || { _pip_venv_refuse "no python3"; return 1; }
    if ! python3 -c 'import ensurepip, venv' >/dev/null 2>&1; then
        # Debian splits venv/ensurepip into python3-venv.
        local sudo
        if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo -n); else sudo=(false); fi
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends python3-venv >&2 \
            || { _pip_venv_refuse "python3-venv is missing and could not be installed"; return 1; }
    fi
    rm -rf "$venv"
    python3 -m venv "$venv" >&2 || { _pip_venv_refuse "python3 -m venv failed"; return 1; }
    "$venv/bin/pip" install -q --disable-pip-version-check "$package==$version" >&2 \
        || { rm -rf "$venv"; _pip_venv_refuse "pip could not install $package==$version"; return 1; }
    "$venv/bin/python" -c "import $module" >&2 || { rm -rf "$venv"; _pip_venv_refuse "$package does not import"; return 1; }
    touch "$marker"
    echo "$label: $package $version installed in ${venv#"$root/"}" >&2
}
