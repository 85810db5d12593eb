#!/usr/bin/env bash
# The BehaviorTree.CPP 4 plugin of MIRoN (cpp/miron_btcpp: VariantAction and skill actions, the
# runner miron-btcpp-run) built against the real BehaviorTree.CPP 4.8.2, for the tests that run the
# woven trees on it and for `miron demo --executor btcpp`.
#   build/btcpp4/install   BehaviorTree.CPP 4.8.2, built once from the source in the behaviortreepy
#                          0.1.4 sdist on PyPI (folder BehaviorTree.CPP/), cached by a marker
#   build/miron-btcpp      our plugin and runner (CMake, incremental: a no-op when nothing changed)
# Users with their own BehaviorTree.CPP build cpp/miron_btcpp directly (docs/btcpp-plugin.md).
# Needs (apt, installed when missing): cmake g++ make pkg-config libzmq3-dev libpugixml-dev.
# Idempotent; never fails the caller: without a registry, a compiler or libzmq it says why and the
# tests that need the runner are skipped (they print the reason too).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
version="4.8.2"
sdist_version="0.1.4"
base="$root/build/btcpp4"
prefix="$base/install"
marker="$prefix/.behaviortree_cpp-$version"
out="$root/build/miron-btcpp"
jobs="${MIRON_BUILD_JOBS:-$(nproc 2>/dev/null || echo 2)}"

reason() { echo "btcpp plugin: not built: $*; the BehaviorTree.CPP runner tests will be skipped" >&2; exit 0; }

if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo -n); else sudo=(false); fi
missing=()
command -v cmake >/dev/null 2>&1 || missing+=(cmake)
command -v g++ >/dev/null 2>&1 || missing+=(g++)
command -v make >/dev/null 2>&1 || missing+=(make)
command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)
[ -f /usr/include/zmq.h ] || missing+=(libzmq3-dev)
[ -f /usr/include/pugixml.hpp ] || missing+=(libpugixml-dev)
if [ ${#missing[@]} -gt 0 ]; then
    echo "btcpp plugin: installing ${missing[*]} (apt)" >&2
    export DEBIAN_FRONTEND=noninteractive
    { "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2 \
        || { "${sudo[@]}" apt-get update -qq >&2 && "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2; }; } \
        || reason "apt could not install ${missing[*]}"
fi

if [ ! -f "$marker" ]; then
    start=$(date +%s)
    rm -rf "$base"
    mkdir -p "$base/download"
    pip=()
    if [ -x "$root/build/btcpp4-venv/bin/pip" ]; then
        pip=("$root/build/btcpp4-venv/bin/pip")
    elif python3 -m pip --version >/dev/null 2>&1; then
        pip=(python3 -m pip)
    else
        reason "no pip to download the behaviortreepy $sdist_version sdist"
    fi
    # Only the package itself as source: its build requirements may come as wheels (much faster).
    "${pip[@]}" download -q --disable-pip-version-check --no-deps --no-binary behaviortreepy \
        "behaviortreepy==$sdist_version" -d "$base/download" >&2 \
        || reason "pip could not download the behaviortreepy $sdist_version sdist"
    tar -xzf "$base/download/behaviortreepy-$sdist_version.tar.gz" -C "$base" \
        || reason "the behaviortreepy sdist does not unpack"
    src="$base/behaviortreepy-$sdist_version/BehaviorTree.CPP"
    grep -q "project(behaviortree_cpp VERSION $version" "$src/CMakeLists.txt" \
        || reason "the sdist does not hold BehaviorTree.CPP $version"
    echo "btcpp plugin: building BehaviorTree.CPP $version (once, about a minute on 2 cores)" >&2
    cmake -S "$src" -B "$base/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
        -DBUILD_TESTING=OFF -DBTCPP_EXAMPLES=OFF -DBTCPP_BUILD_TOOLS=OFF -DBTCPP_SQLITE_LOGGING=OFF \
        >"$base/configure.log" 2>&1 || reason "cmake could not configure BehaviorTree.CPP (see $base/configure.log)"
    cmake --build "$base/build" -j "$jobs" >"$base/build.log" 2>&1 \
        || reason "BehaviorTree.CPP did not build (see $base/build.log)"
    cmake --install "$base/build" >"$base/install.log" 2>&1 || reason "BehaviorTree.CPP did not install"
    rm -rf "$base/build" "$base/download"
    touch "$marker"
    echo "btcpp plugin: BehaviorTree.CPP $version installed in build/btcpp4/install in $(( $(date +%s) - start )) s" >&2
fi

cmake -S "$root/cpp/miron_btcpp" -B "$out" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
    >"$out.configure.log" 2>&1 || { cat "$out.configure.log" >&2; reason "cmake could not configure cpp/miron_btcpp"; }
cmake --build "$out" -j "$jobs" >"$out.build.log" 2>&1 \
    || { tail -n 40 "$out.build.log" >&2; reason "cpp/miron_btcpp did not build (see $out.build.log)"; }
echo "btcpp plugin: $out/miron-btcpp-run and $out/libmiron_btcpp.so are up to date" >&2
