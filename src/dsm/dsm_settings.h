// Deep-shadow-map settings (Lokovic & Veach 2000; the linked-list GPU form of GPU Pro 4 and seed 002).
#pragma once
#include <cstdint>
#include <vector>

namespace penumbra {

// How a lookup finds a receiver's place in a texel's sorted list: by binary search in the packed
// list (each tap on its own), or by walking from the neighbouring tap's node through the resolve's
// neighbour links (Lokovic & Veach's lists as GPU Pro 4 links them; needs the dsm.link pass).
enum class DsmLookup { Search, Links };

struct DsmSettings {
    bool enabled = false;          // `--shadow dsm` or `dom`: hair and blended meshes cast through a DSM
    // `--shadow dom`: Deep Opacity Maps (Yuksel & Keyser 2008) instead of the lists, for comparison:
    // per texel the first depth and DOM_LAYERS layers of accumulated opacity behind it (hair only).
    bool opacityMaps = false;
    std::vector<uint32_t> lights;  // `--dsm-lights`: the lights that get one (empty: every shadowed
                                   // directional or spot light)
    uint32_t resolution = 0;       // texels per side; 0 = the shadow-map resolution
    uint64_t poolNodes = 0;        // node pool capacity; 0 = kAutoNodesPerTexel per DSM texel (at most what
                                   // the device can address, half its memory)
    uint32_t maxList = 50;         // nodes kept per texel, nearest first (1..DSM_MAX_LIST_CAP)
    float filterWidth = 1.0f;      // PCF box width in texels (0 = bilinear, up to 8)
    float depthBias = 2.0f;        // receiver moved this many texels towards the light (self-shadowing)
    float normalOffset = 1.0f;     // and this many along its normal (texels)
    // `--dsm-depth-test`: skip fragments hidden behind opaque casters. Off by default: the conservative
    // neighbourhood test costs the build more than the fewer nodes save in the resolve, since hair
    // hides little of itself behind opaque casters (docs/techniques/dsm.md).
    bool depthTest = false;
    DsmLookup lookup = DsmLookup::Search;  // `--dsm-lookup`

    // 16 per texel: 100k strands of the hair scene make 29M light-space fragments at 2048^2 (7 per
    // texel) before the depth test; 67M nodes are 1.3 GiB, which a large GPU holds easily. Smaller devices
    // get what one storage buffer addresses (lavapipe: 8.4M) and a warning naming the limit.
    static constexpr uint32_t kAutoNodesPerTexel = 16;
    static constexpr uint64_t kMaxPoolNodes = uint64_t(1) << 28;  // 5 GiB of nodes and links
};

}  // namespace penumbra
