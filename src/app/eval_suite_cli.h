// `penumbra eval --suite` (docs/evaluation.md): the sun-only cases of the five suite scenes and the
// sky cases of the outdoor ones, with their references cached per scene, case and seed.
#pragma once
#include <string>
#include <vector>

#include "app/ground_truth_cli.h"
#include "eval/sky_suite.h"
#include "eval/suite.h"

namespace penumbra {

// The flag of an `eval` row, by the member it writes.
template <class Access>
const std::string& evalFlag(Access access) {
    return evalCommandOptions().flagOf<EvalCliOptions>(access);
}

// `eval --suite` and the frame's camera flag, for messages.
const std::string& suiteFlag();
const std::string& cameraFlag();

// The reference of `f` by o.reference.settings, read from o.referenceDir when its key matches, else
// rendered and stored there (eval_cli.cpp).
GroundTruth groundTruth(const EvalCliOptions& o, const PreparedFrame& f);

struct SuiteRun {
    std::vector<SuiteResult> sun;     // the sun-only cases, in the scenes' order
    std::vector<SkySuiteResult> sky;  // the sky cases
};
// The cases o.suiteCases selects of `scenes` (their sizes and paths as given), in one context.
SuiteRun runSuiteCases(const EvalCliOptions& o, const std::vector<SuiteScene>& scenes, vk::Context& ctx,
                       bool progressLine = false);

// The whole command: checks, the cases, the tables, the JSON.
int runSuite(const EvalCliOptions& o, const vk::ContextOptions& vkOptions, bool dryRun);

}  // namespace penumbra
