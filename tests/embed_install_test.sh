#!/usr/bin/env bash
# penumbra as an installed package: installs the build into a temporary prefix, checks the installed
# files (no path of the build or source tree; penumbra::core links none of CLI11, Embree, GLFW,
# ImGui), builds examples/embed from a copy that sees only the prefix, runs it, and compares its PNG
# with the installed `penumbra render` of the same scene and settings (equal bytes).
#   embed_install_test.sh BUILD_DIR SOURCE_DIR BUILD_TYPE
set -euo pipefail
# scripts/sanitize.sh preloads the sanitizer runtime into the tests: the tools run here (mktemp, cmake,
# the compiler) are not ours to check, and LeakSanitizer fails mktemp, so only the two programs under
# test keep it (as under_test).
preload=${LD_PRELOAD:-}
unset LD_PRELOAD
under_test() { LD_PRELOAD=$preload "$@"; }
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
build_type=${3:-Release}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "embed_install_test: FAIL: $*" >&2; exit 1; }

prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
config=$prefix/lib/cmake/penumbra
[ -f "$config/penumbraConfig.cmake" ] && [ -f "$config/penumbraConfigVersion.cmake" ] || fail "no package config in $config"

# Text files always; the library and the tool too unless built with debug information (which names the sources).
scan=-rl
[[ "$build_type" == Debug || "$build_type" == RelWithDebInfo ]] && scan=-rIl
if grep $scan -e "$build" -e "$source" "$prefix"; then fail "the installed files above name the build or source tree"; fi
link=$(grep -h "INTERFACE_LINK_LIBRARIES" "$config"/penumbraTargets*.cmake)
echo "penumbra::core links: $link"
grep -q "Vulkan::Vulkan" <<<"$link" || fail "the link interface read is not penumbra::core's"
if grep -Eio "cli11|embree|glfw|imgui" <<<"$link"; then fail "penumbra::core's link interface names the above"; fi

# The example as another project has it: a copy outside both trees, the prefix its only way in.
mkdir "$tmp/embed"
cp "$source"/examples/embed/CMakeLists.txt "$source"/examples/embed/main.cpp "$source"/examples/embed/*.gltf "$tmp/embed/"
env -u CMAKE_PREFIX_PATH cmake -S "$tmp/embed" -B "$tmp/embed/build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
found=$(sed -n 's/^penumbra_DIR:PATH=//p' "$tmp/embed/build/CMakeCache.txt")
[ "$found" -ef "$config" ] || fail "find_package found penumbra in '$found', not in the prefix"
cmake --build "$tmp/embed/build" -j2 >/dev/null

for scene in cornell "$tmp/embed/three_quads.gltf"; do
    under_test "$tmp/embed/build/embed" "$scene" "$tmp/embed.png" 96 64
    under_test "$prefix/bin/penumbra" render "$scene" --width 96 --height 64 --shadow pcf --gi rsm --exposure 1 --sky none -q -o "$tmp/cli.png"
    cmp "$tmp/embed.png" "$tmp/cli.png" || fail "$scene: the example's image differs from penumbra render's"
    echo "$scene: equal images ($(stat -c %s "$tmp/cli.png") bytes)"
done
