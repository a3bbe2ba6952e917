// The option tables are the one place an option is written: every settings member has a row, every
// row round-trips its value, refuses bad values with its flag in the message, shows a changed value
// in the JSON `settings` of bench, and is classified by Renderer::apply's settings diff.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "api/convert.h"
#include "dsm/dsm_options.h"
#include "frame/frame_options.h"
#include "lpv/lpv_options.h"
#include "renderer/render_options.h"
#include "renderer/settings_change.h"
#include "rsm/rsm_options.h"
#include "settings_reflection.h"
#include "shadow/shadow_options.h"

namespace penumbra::test {
namespace {

// A valid value of `row` other than the one `settings` holds.
std::string otherValue(const OptionRow& row, const void* settings) {
    const std::string current = row.value(settings);
    switch (row.kind) {
        case OptionKind::Integer:
        case OptionKind::Real: {
            const double v = std::stod(current.empty() ? "0" : current);
            const double step = row.kind == OptionKind::Integer ? 1.0 : (row.max - row.min) * 0.25;
            const double next = v + step <= row.max ? v + step : v - step;
            return row.kind == OptionKind::Integer ? std::to_string(int64_t(std::clamp(next, row.min, row.max)))
                                                   : formatOptionNumber(std::clamp(next, row.min, row.max));
        }
        case OptionKind::Bool: return current == "on" ? "off" : "on";
        case OptionKind::Choice:
            for (const std::string& c : row.choices)
                if (c != current) return c;
            return current;
        case OptionKind::Text: return "";
    }
    return "";
}

// Non-default examples of the compound rows (their syntax is the module's).
const std::map<std::string, std::string> kTextExamples{
    {"--shadow", "pcss,dsm"}, {"--dsm-lights", "0,2"}, {"--camera", "0,1,3,0,1,0,0,1,0,50"},
    {"--light", "point,0,1,0,5"}, {"--light-shadow", "0=vsm"}, {"--sun-path", "0,30,90,60,4"},
    {"--light-path", "0:0,0,1,0;1,0,2,0"}, {"--camera-keys", "0,0,1,3,0,1,0;1,0,1,4,0,1,0"}, {"--no-motion", "on"},
    {"--sky", "uniform,1,2,3"}, {"--exposure", "2"}, {"--exposure-percentiles", "10,90"},
};

std::string exampleFor(const OptionRow& row, const void* settings) {
    if (row.kind != OptionKind::Text) return otherValue(row, settings);
    const auto it = kTextExamples.find(row.flag);
    return it == kTextExamples.end() ? "" : it->second;
}

std::vector<const OptionTable*> inputTables() { return {&frameInputOptions(), &motionOptions()}; }

TEST(OptionTables, FlagsAndKeysAreUnique) {
    std::set<std::string> flags;
    for (const BoundOptionTable& t : renderOptionTables()) {
        std::set<std::string> keys;
        for (const OptionRow& row : t.table->rows) {
            EXPECT_TRUE(flags.insert(row.flag).second) << row.flag << " is in two rows";
            EXPECT_TRUE(keys.insert(row.key).second) << t.table->module << "." << row.key << " is in two rows";
            EXPECT_FALSE(row.help.empty()) << row.flag;
        }
    }
    for (const OptionTable* t : inputTables())
        for (const OptionRow& row : t->rows) EXPECT_TRUE(flags.insert(row.flag).second) << row.flag;
    // The frame's keys sit beside the modules' objects in the JSON: no key may take a module's name.
    for (const OptionRow& row : frameOptionTable().rows)
        for (const BoundOptionTable& t : renderOptionTables()) EXPECT_NE(row.key, t.table->module) << row.flag;
}

// Each value a row prints reads back as itself: the JSON, the viewer and `set` agree with the CLI.
TEST(OptionTables, EveryRowReadsBackItsOwnValue) {
    RenderSettings rs;
    for (const BoundOptionTable& t : renderOptionTables())
        for (const OptionRow& row : t.table->rows) {
            RenderSettings copy = rs;
            const std::vector<std::string> before = row.get(t.at(rs));
            if (row.clear) row.clear(t.at(copy));
            for (const std::string& v : before) row.set(t.at(copy), v);
            EXPECT_EQ(row.get(t.at(copy)), before) << row.flag;
        }
}

// A row refuses NaN, infinity, text and values outside its range with one message naming its flag.
TEST(OptionTables, NumericRowsRefuseBadValuesNamingTheirFlag) {
    RenderSettings rs;
    size_t numeric = 0;
    for (const BoundOptionTable& t : renderOptionTables())
        for (const OptionRow& row : t.table->rows) {
            if (row.kind != OptionKind::Integer && row.kind != OptionKind::Real) continue;
            ++numeric;
            const std::vector<std::string> bad{"nan", "inf", "-inf", "text", "", "1e400",
                                               formatOptionNumber(row.max + std::max(1.0, row.max)),
                                               formatOptionNumber(row.min - std::max(1.0, std::abs(row.min)) - 1)};
            for (const std::string& v : bad) {
                if (row.special && v == formatOptionNumber(*row.special)) continue;
                try {
                    row.set(t.at(rs), v);
                    ADD_FAILURE() << row.flag << " took '" << v << "'";
                } catch (const std::invalid_argument& e) {
                    const std::string message = e.what();
                    EXPECT_NE(message.find(row.flag), std::string::npos) << message;
                    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
                }
            }
        }
    EXPECT_GT(numeric, 40u);
}

// No silent setting: a non-default value of every row shows in bench's JSON `settings` under the
// row's key, and Renderer::apply's diff names the row's flag with a change class.
TEST(OptionTables, EveryRowShowsInTheJsonAndIsClassified) {
    RenderSettings defaults;
    const nlohmann::json before = renderSettingsJson(defaults);
    for (const BoundOptionTable& t : renderOptionTables())
        for (const OptionRow& row : t.table->rows) {
            RenderSettings changed = defaults;
            const std::string value = exampleFor(row, t.at(defaults));
            ASSERT_FALSE(value.empty()) << row.flag << " has no example value";
            if (row.clear) row.clear(t.at(changed));
            row.set(t.at(changed), value);
            ASSERT_NE(row.value(t.at(changed)), row.value(t.at(defaults))) << row.flag;
            const nlohmann::json after = renderSettingsJson(changed);
            const bool top = t.table->module == "frame";
            const nlohmann::json& was = top ? before.at(row.key) : before.at(t.table->module).at(row.key);
            const nlohmann::json& now = top ? after.at(row.key) : after.at(t.table->module).at(row.key);
            EXPECT_NE(was, now) << row.flag << " does not show in the JSON";
            const SettingsDiff diff = diffSettings(defaults, changed);
            EXPECT_NE(std::find(diff.flags.begin(), diff.flags.end(), row.flag), diff.flags.end())
                << row.flag << " is not classified";
            EXPECT_NE(diff.change, SettingsChange::None) << row.flag;
        }
}

// The public settings (include/penumbra/settings.h) reach every row an engine may set: a non-default
// value survives the way into api::Settings and back. The rows left out are named here, each with why;
// techniques registered from outside (the extension store) are set through the registry, not the API.
TEST(OptionTables, EveryRowReachesThePublicSettings) {
    const std::set<std::string> notPublic{
        "--aov",        // the public Output names the image views; the RSM and shadow-map layers are tools' views
        "--aov-layer",  // the layer of those views
    };
    RenderSettings defaults;
    defaults.lighting.sky.kind = SkyKind::None;  // a program linking the library resolves no sky itself
    for (const BoundOptionTable& t : renderOptionTables())
        for (const OptionRow& row : t.table->rows) {
            const auto* bound = static_cast<const char*>(t.at(defaults));
            const auto* whole = reinterpret_cast<const char*>(&defaults);
            if (notPublic.count(row.flag) || bound < whole || bound >= whole + sizeof(defaults)) continue;
            RenderSettings changed = defaults;
            const std::string value = exampleFor(row, t.at(defaults));
            ASSERT_FALSE(value.empty()) << row.flag << " has no example value";
            if (row.clear) row.clear(t.at(changed));
            row.set(t.at(changed), value);
            const RenderSettings back = api::toInternal(api::fromInternal(changed));
            EXPECT_EQ(row.get(t.at(back)), row.get(t.at(changed))) << row.flag << " does not reach api::Settings";
        }
}

// The byte ranges the rows of every table bind, as offsets in RenderSettings.
std::vector<std::pair<size_t, size_t>> boundRanges() {
    static const RenderSettings probe{};
    std::vector<std::pair<size_t, size_t>> out;
    for (const BoundOptionTable& t : renderOptionTables()) {
        const size_t base = size_t(static_cast<const char*>(t.at(probe)) - reinterpret_cast<const char*>(&probe));
        for (const OptionRow& row : t.table->rows)
            for (const auto& [first, last] : row.members) out.push_back({base + first, base + last});
    }
    return out;
}

// Every member of `s` (at `base` in RenderSettings) overlaps a row's member: a member with no row
// would be ignored by the CLI, the JSON and Renderer::apply.
template <class T>
void expectEveryMemberBound(const T& s, size_t base, const char* name, const void* exempt = nullptr) {
    const auto bound = boundRanges();
    const auto members = memberRanges(s);
    for (size_t i = 0; i < members.size(); ++i) {
        const size_t first = base + members[i].first, last = base + members[i].second;
        if (exempt && members[i].first == size_t(static_cast<const char*>(exempt) - reinterpret_cast<const char*>(&s)))
            continue;
        const bool has = std::any_of(bound.begin(), bound.end(),
                                     [&](const auto& r) { return r.first < last && first < r.second; });
        EXPECT_TRUE(has) << name << " member #" << i << " (bytes " << members[i].first << ".." << members[i].second
                         << ") has no option row";
    }
}

TEST(OptionTables, EverySettingsMemberHasARow) {
    const RenderSettings s{};
    const auto at = [&](const auto& member) {
        return size_t(reinterpret_cast<const char*>(&member) - reinterpret_cast<const char*>(&s));
    };
    // The extension store holds registered techniques' settings, whose own tables bind them.
    expectEveryMemberBound(s, 0, "RenderSettings", &s.extensions);
    expectEveryMemberBound(s.shadow, at(s.shadow), "ShadowSettings");
    expectEveryMemberBound(s.shadow.cascades, at(s.shadow.cascades), "CascadeSettings");
    expectEveryMemberBound(s.rsm, at(s.rsm), "RsmSettings");
    expectEveryMemberBound(s.lpv, at(s.lpv), "LpvSettings");
    expectEveryMemberBound(s.dsm, at(s.dsm), "DsmSettings");
    expectEveryMemberBound(s.lighting.sky, at(s.lighting.sky), "SkySettings");
    EXPECT_EQ(memberCount<RsmSettings>(), memberRanges(s.rsm).size());
}

// The frame inputs parse once: --light and --camera are held parsed beside their text.
TEST(OptionTables, FrameInputsAreParsedWhenGiven) {
    FrameOptions o;
    const OptionTable& t = frameInputOptions();
    t.find("--light")->set(&o, "point,0,1,0,5");
    t.find("--camera")->set(&o, "0,1,3,0,1,0,0,1,0,50");
    ASSERT_EQ(o.parsedLights.size(), 1u);
    EXPECT_EQ(o.parsedLights[0].type, LightType::Point);
    ASSERT_TRUE(o.parsedCamera.has_value());
    EXPECT_FLOAT_EQ(o.parsedCamera->eye.z, 3.0f);
    EXPECT_THROW(t.find("--light")->set(&o, "point,0,1"), std::invalid_argument);
}

}  // namespace
}  // namespace penumbra::test
