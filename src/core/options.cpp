#include "core/options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {

const char* settingsChangeName(SettingsChange c) {
    switch (c) {
        case SettingsChange::None: return "none";
        case SettingsChange::PerFrame: return "per-frame";
        case SettingsChange::Structure: return "structure";
        case SettingsChange::Sizes: return "sizes";
    }
    return "?";
}

std::string formatOptionNumber(double v) {
    // The shortest text that reads back as the same float: settings hold floats, JSON and help show them.
    return fmt::format("{}", float(v));
}

void refuseOption(const OptionRow& row, const std::string& text, const std::string& why) {
    throw std::invalid_argument(fmt::format("{} {}: {}", row.flag, text.empty() ? "''" : text, why));
}

double parseOptionNumber(const OptionRow& row, const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    // Whole text, finite: strtod takes "nan", "inf" and hex floats, which no setting wants.
    const bool number = !text.empty() && end == begin + text.size() && errno != ERANGE && std::isfinite(v) &&
                        text.find_first_of("xXnN") == std::string::npos;
    if (!number) refuseOption(row, text, row.kind == OptionKind::Integer ? "expected a whole number" : "expected a finite number");
    if (row.special && v == *row.special) return v;
    if (row.kind == OptionKind::Integer && v != std::floor(v)) refuseOption(row, text, "expected a whole number");
    if (v < row.min || v > row.max) refuseOption(row, text, "is outside " + row.rangeText());
    return v;
}

bool parseOptionBool(const OptionRow& row, const std::string& text) {
    for (const char* on : {"on", "true", "1", "yes"})
        if (text == on) return true;
    for (const char* off : {"off", "false", "0", "no"})
        if (text == off) return false;
    refuseOption(row, text, "expected on or off");
}

std::string OptionRow::value(const void* settings) const {
    std::string out;
    for (const std::string& v : get(settings)) out += (out.empty() ? "" : ",") + v;
    return out;
}

std::string OptionRow::rangeText() const {
    switch (kind) {
        case OptionKind::Integer:
        case OptionKind::Real: {
            auto text = [this](double v) {
                return kind == OptionKind::Integer ? fmt::format("{}", int64_t(v)) : formatOptionNumber(v);
            };
            std::string r = fmt::format("[{}, {}]", text(min), text(max));
            if (special) r += fmt::format(", or {}: {}", text(*special), specialMeaning);
            return r;
        }
        case OptionKind::Bool:
        case OptionKind::Choice: {
            std::string r;
            for (const std::string& c : choices) r += (r.empty() ? "" : "|") + c;
            return r;
        }
        case OptionKind::Text: return placeholder.empty() ? "TEXT" : placeholder;
    }
    return "";
}

void checkRanges(const OptionTable& table, const void* settings) {
    for (const OptionRow& row : table.rows) {
        const std::string v = row.value(settings);
        if (row.kind == OptionKind::Integer || row.kind == OptionKind::Real) parseOptionNumber(row, v);
        if (row.kind == OptionKind::Choice && v == "?") refuseOption(row, v, "is not one of " + row.rangeText());
    }
}

const OptionRow* OptionTable::find(const std::string& flag) const {
    for (const OptionRow& r : rows)
        if (r.flag == flag) return &r;
    return nullptr;
}

const std::string& OptionTable::flagAt(size_t offset) const {
    for (const OptionRow& r : rows)
        for (const auto& m : r.members)
            if (m.first == offset) return r.flag;
    throw std::logic_error(fmt::format("option table '{}' has no row at offset {}", module, offset));
}

}  // namespace penumbra
