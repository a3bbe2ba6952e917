#include "app/dsm_cli.h"

#include <fmt/format.h>

#include "app/option_checks.h"
#include "dsm/dsm_technique.h"

namespace penumbra {

void addDsmOptions(CLI::App& cmd, DsmSettings& dsm, BuiltinOptions& scene) {
    cmd.add_option("--strands", scene.hairStrands, "Hair strands of the built-in `hair` scene")
        ->check(CLI::Range(1, 2'000'000));
    cmd.add_option("--dsm-lights", dsm.lights, "Lights that get a deep shadow map, e.g. 0,2 (default: all shadowed)")
        ->delimiter(',')
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--dsm-res", dsm.resolution, "Deep shadow map resolution (default: --shadow-res)")
        ->check(CLI::Range(16, 16384));
    cmd.add_option("--dsm-nodes", dsm.poolNodes, "Node pool capacity (default: 16 nodes per DSM texel, at most what the device addresses)")
        ->check(CLI::Range(uint64_t(1), DsmSettings::kMaxPoolNodes - 1));
    cmd.add_option("--dsm-max-list", dsm.maxList, "Nodes kept per texel, nearest first")
        ->check(CLI::Range(1, DSM_MAX_LIST_CAP));
    cmd.add_option("--dsm-filter", dsm.filterWidth, "DSM PCF box width in texels (default 1; 0 = bilinear)")
        ->check(finiteRange(0.0, 8.0));
    cmd.add_option("--dsm-depth-test", dsm.depthTest, "Skip DSM fragments hidden behind opaque casters on/off");
    addChoice<DsmLookup>(cmd, "--dsm-lookup", dsm.lookup, {{"search", DsmLookup::Search}, {"links", DsmLookup::Links}},
                         "How a DSM lookup finds its place in each filter tap's list: binary search in the packed "
                         "list, every tap at once, or a walk through the neighbour links from the previous tap");
    cmd.add_option("--dsm-bias", dsm.depthBias, "DSM receiver depth bias in texels")
        ->check(finiteRange(0.0, 64.0));
}

void finishDsmSettings(RenderSettings& s) {
    if (!s.dsm.lights.empty()) s.dsm.enabled = true;
    if ((s.aov == Aov::Transmittance || s.aov == Aov::DsmLists) && !s.dsm.enabled)
        throw std::invalid_argument("--aov transmittance/dsm-lists need deep shadow maps: add --shadow dsm");
}

void reportDsm(Renderer& renderer, bool quiet) {
    if (const CameraTranslucency* t = renderer.find<TranslucencyTechnique>()->translucency()) {
        const OitFrameStats stats = t->readStats(renderer.commands());
        if (!quiet) fmt::print("  {}\n", describeTranslucency(stats));
        for (const std::string& w : translucencyWarnings(stats)) fmt::print(stderr, "penumbra: warning: {}\n", w);
    }
    const DeepShadowMaps& maps = renderer.find<DsmTechnique>()->maps();
    if (!maps.active()) return;
    const DsmFrameStats stats = maps.readStats(renderer.commands());
    if (!quiet) fmt::print("  {}\n", describeDsm(stats));
    for (const std::string& w : dsmWarnings(stats)) fmt::print(stderr, "penumbra: warning: {}\n", w);
}

}  // namespace penumbra
