#!/usr/bin/env bash
# Installs the Debian 12 packages penumbra needs. Idempotent: quiet and fast when all are present.
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslc
  libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libtinyexr-dev libcli11-dev libfmt-dev
  libgtest-dev libembree-dev libspirv-cross-c-shared-dev python3
  libglfw3-dev libimgui-dev xvfb xauth ccache
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}"
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
