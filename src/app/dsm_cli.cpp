#include "app/dsm_cli.h"

#include <fmt/format.h>

#include "app/option_cli.h"

#include "dsm/dsm_technique.h"

namespace penumbra {

void reportDsm(Renderer& renderer, bool quiet) {
    if (const CameraTranslucency* t = renderer.find<TranslucencyTechnique>()->translucency()) {
        const OitFrameStats stats = t->readStats(renderer.commands());
        if (!quiet) fmt::print("  {}\n", describeTranslucency(stats));
        for (const std::string& w : translucencyWarnings(stats)) printWarning(w);
    }
    const DeepShadowMaps& maps = renderer.find<DsmTechnique>()->maps();
    if (!maps.active()) return;
    const DsmFrameStats stats = maps.readStats(renderer.commands());
    if (!quiet) fmt::print("  {}\n", describeDsm(stats));
    for (const std::string& w : dsmWarnings(stats)) printWarning(w);
}

}  // namespace penumbra
