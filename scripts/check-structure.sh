#!/usr/bin/env bash
# The module structure of src/ (docs/architecture.md): the core, the Vulkan layer, scene and io include no
# technique, service or assembly header; no technique includes another technique's or a shared
# service's header; shared services include no technique; above them, the renderer includes no frame
# preparation or front end, the frame preparation and the public API no front end, and the viewer not
# the command line (it builds on the library). Prints each offending include and exits 1; run by CTest.
set -euo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
cd "$root/src"

# Technique folders: each a module that reaches the others only through core/names.h.
techniques=(shadow dsm rsm lpv lighting sky_light temporal_gi)
# Shared service modules: techniques reach them through core interfaces (core/depth_raster.h) and
# published names (core/names.h), never through their headers; they use only the layers below.
services=(raster voxel)
# The assembly above the techniques, the frame preparation above it (both in the library), and the
# front ends above them.
above=(renderer frame app view eval reference)

status=0
# $1: folder, $2...: folders it must not include from.
forbid() {
    local folder=$1
    shift
    [ -d "$folder" ] || return 0
    local pattern
    pattern="^[[:space:]]*#[[:space:]]*include[[:space:]]*\"($(IFS='|'; echo "$*"))/"
    local hits
    hits=$(grep -rnE "$pattern" "$folder" --include='*.h' --include='*.cpp' || true)
    if [ -n "$hits" ]; then
        echo "check-structure: $folder/ includes a header it must not:"
        echo "$hits" | sed 's/^/  src\//'
        status=1
    fi
}

for below in core vk scene io; do forbid "$below" "${techniques[@]}" "${services[@]}" "${above[@]}"; done
for s in "${services[@]}"; do forbid "$s" "${techniques[@]}" "${above[@]}"; done
for t in "${techniques[@]}"; do
    others=()
    for o in "${techniques[@]}"; do [ "$o" != "$t" ] && others+=("$o"); done
    forbid "$t" "${others[@]}" "${services[@]}" "${above[@]}"
done
forbid renderer frame app view eval reference
forbid frame app view eval reference
forbid view app
forbid api app view eval reference
[ "$status" -eq 0 ] && echo "check-structure: ok (core, vk, scene, io, ${services[*]}, ${techniques[*]}, renderer, frame, api, view)"
exit "$status"
