#!/usr/bin/env bash
# Prepares what a run on the GPU machine needs (see docs/benchmarks.md):
# .gl/ holds the Vulkan loader packages (the machine has none), .device/ the portable penumbra binary,
# the shared libraries it links that the machine lacks, and the test assets. Both folders are ignored.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! ls .gl/libvulkan1_*.deb >/dev/null 2>&1; then
  mkdir -p .gl /tmp/amd64/partial
  o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
  apt-get $o update -qq
  (cd .gl && apt-get $o download -qq libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
fi
# A build directory of its own (build-device), so that the portable flag does not rebuild build/.
cmake -S . -B build-device -DCMAKE_BUILD_TYPE=Release -DPENUMBRA_PORTABLE=ON >/dev/null
cmake --build build-device -j"$(nproc)" --target penumbra
rm -rf .device && mkdir -p .device/lib .device/assets
cp build-device/penumbra .device/
# Every shared library it links except the C runtime and the Vulkan loader (unpacked from .gl).
ldd build-device/penumbra | awk '$3 ~ /^\// {print $3}' | grep -Ev '/(libc|libm|libvulkan|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" .device/lib/; done
[ -d ../shared/assets ] && cp -r ../shared/assets/VC ../shared/assets/sponza .device/assets/
# Packed: Embree alone is 44 MB, and the tree that travels to the GPU machine holds 64 MiB at most.
tar -cJf .device/lib.tar.xz -C .device lib && rm -rf .device/lib
cat > .device/env.sh <<'EOS'
# Sourced first in every device command: unpack the Vulkan loader and the carried libraries.
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
tar -xJf .device/lib.tar.xz -C .device
export LD_LIBRARY_PATH=$PWD/.device/lib
EOS
du -sh .gl .device
