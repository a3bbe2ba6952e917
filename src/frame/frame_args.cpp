#include "frame/frame_args.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <stdexcept>

#include <fmt/format.h>

#include "frame/option_text.h"
#include "renderer/render_options.h"

namespace penumbra {
namespace {

const char* kScene = "scene";

// A bare flag's value as a count: on, true, yes, enable, + count 1; off, false, no, disable, - count
// -1; a whole number counts itself.
long long flagCount(const OptionRow& row, const std::string& text) {
    std::string v = text;
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (v == "on" || v == "true" || v == "yes" || v == "enable" || v == "+") return 1;
    if (v == "off" || v == "false" || v == "no" || v == "disable" || v == "-") return -1;
    long long n = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
    if (ec != std::errc() || end != v.data() + v.size() || v.empty()) refuseOption(row, text, "is not on or off");
    return n;
}

// Every value given for `name`, in order (an option may be given in several entries).
std::vector<std::string> valuesOf(const std::vector<FrameArg>& args, const std::string& name) {
    std::vector<std::string> values;
    for (const FrameArg& a : args)
        if (a.name == name) values.insert(values.end(), a.values.begin(), a.values.end());
    return values;
}

void applyRow(const OptionRow& row, void* settings, const std::vector<std::string>& values) {
    if (row.bareFlag) {
        long long count = 0;
        for (const std::string& v : values) count += flagCount(row, v);
        return row.set(settings, count > 0 ? "on" : "off");
    }
    if (row.repeatable) {
        row.clear(settings);
        for (const std::string& v : values) row.set(settings, v);
        return;
    }
    if (values.size() != 1)
        throw std::invalid_argument(fmt::format("{}: takes one value, given {}", longFlag(row.flag), values.size()));
    row.set(settings, values.front());
}

// Calls visit(name, row, settings) for each option of `frame` (ParsedFrame, const or not) in the
// order of frameOptionRefs; the scene has no row.
template <class Frame, class Visit>
void visitFrameOptions(Frame& frame, Visit visit) {
    visit(kScene, nullptr, &frame.options.scene);
    const auto rows = [&](const OptionTable& table, auto* settings) {
        for (const OptionRow& r : table.rows) visit(longFlag(r.flag), &r, settings);
    };
    rows(frameInputOptions(), &frame.options);
    for (const BoundOptionTable& t : renderOptionTables()) rows(*t.table, t.at(frame.settings));
    rows(motionOptions(), &frame.options);
}

}  // namespace

std::vector<FrameOptionRef> frameOptionRefs(const ParsedFrame& frame) {
    std::vector<FrameOptionRef> refs;
    visitFrameOptions(frame, [&](const std::string& name, const OptionRow* row, const void* settings) {
        refs.push_back({name, row, settings});
    });
    return refs;
}

ParsedFrame parseFrameArgs(const std::vector<FrameArg>& args) {
    ParsedFrame parsed;
    setFrameDefaults(parsed.settings);
    std::vector<std::string> known;
    visitFrameOptions(parsed, [&](const std::string& name, const OptionRow*, void*) { known.push_back(name); });
    for (const FrameArg& a : args)
        if (std::find(known.begin(), known.end(), a.name) == known.end())
            throw std::invalid_argument(fmt::format("unknown option '{}'", a.name));
    visitFrameOptions(parsed, [&](const std::string& name, const OptionRow* row, void* settings) {
        const std::vector<std::string> values = valuesOf(args, name);
        if (values.empty()) return;
        if (row) return applyRow(*row, settings, values);
        if (values.size() != 1) throw std::invalid_argument(fmt::format("one scene, not {}", values.size()));
        parsed.options.scene = values.front();
    });
    checkFrameSettings(parsed.options, parsed.settings);
    return parsed;
}

}  // namespace penumbra
