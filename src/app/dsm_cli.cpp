#include "app/dsm_cli.h"

#include <fmt/format.h>


namespace penumbra {

void reportDsm(Renderer& renderer, bool quiet) {
    if (const CameraTranslucency* t = renderer.translucency()) {
        const OitFrameStats stats = t->readStats(renderer.commands());
        if (!quiet) fmt::print("  {}\n", describeTranslucency(stats));
        for (const std::string& w : translucencyWarnings(stats)) fmt::print(stderr, "penumbra: warning: {}\n", w);
    }
    if (!renderer.deepShadows().active()) return;
    const DsmFrameStats stats = renderer.deepShadows().readStats(renderer.commands());
    if (!quiet) fmt::print("  {}\n", describeDsm(stats));
    for (const std::string& w : dsmWarnings(stats)) fmt::print(stderr, "penumbra: warning: {}\n", w);
}

}  // namespace penumbra
