// Option tables: the one place where a setting's flag, type, range or choices, default, help text,
// change class, JSON key and viewer group are written. A module (a technique, or a command) owns a
// table over its own settings struct; the CLI, `--help`, the settings-change classification, the
// JSON `settings` of bench/eval/stability and the viewer's panels are generated from the tables.
//
// A row reaches its member through a typed accessor, erased to `void*` so that one table type serves
// every settings struct: the table's `type` says which struct it is written for.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <optional>
#include <string>
#include <type_traits>
#include <typeindex>
#include <utility>
#include <vector>

namespace penumbra {

// What a settings change invalidates.
enum class SettingsChange {
    None,
    PerFrame,   // values read by the next frame: no allocation, no pipeline creation
    Structure,  // which passes run (shadow filter kind, GI mode, DSM on/off, pass counts)
    Sizes,      // what sizes a resource (resolutions, cascade count, image size)
};
const char* settingsChangeName(SettingsChange c);

// The change classes by the short names the option tables use (`using namespace change;`).
namespace change {
inline constexpr SettingsChange kFrame = SettingsChange::PerFrame;
inline constexpr SettingsChange kStructure = SettingsChange::Structure;
inline constexpr SettingsChange kSizes = SettingsChange::Sizes;
inline constexpr SettingsChange kCommand = SettingsChange::None;  // read once by the command that owns it
}  // namespace change

enum class OptionKind {
    Integer,  // whole numbers in [min, max]
    Real,     // finite numbers in [min, max]
    Bool,     // on/off
    Choice,   // one of `choices`, by name
    Text,     // free text, parsed by the row (compound values, lists)
};

// How the viewer shows a row (Auto: from the kind).
enum class Widget { Auto, Field, Checkbox, Combo, Hidden };

struct OptionRow;
using OptionGetter = std::function<std::vector<std::string>(const void*)>;
using OptionSetter = std::function<void(const OptionRow&, void*, const std::string&)>;

struct OptionRow {
    std::string flag;  // "--rsm-samples"
    std::string key;   // JSON key inside the module's object: "samples"
    std::string help;
    OptionKind kind = OptionKind::Real;
    double min = 0.0, max = 0.0;  // Integer and Real
    // A value outside [min, max] with a meaning of its own (e.g. 0 = "the shadow map's"): accepted.
    std::optional<double> special;
    std::string specialMeaning;
    std::vector<std::string> choices;  // Choice: the names, in the order the help lists them
    bool repeatable = false;           // Text: the flag may be given several times (values appended)
    bool bareFlag = false;             // Bool: on when given without a value (`--clamp`)
    std::string placeholder;           // Text: what a value looks like in the help ("N=MODE")
    SettingsChange change = SettingsChange::PerFrame;
    // What a Structure or Sizes change rebuilds, as the assembly's part names; empty: the owning module.
    std::vector<std::string> rebuilds;
    std::string group;  // the viewer's panel (default: the table's title)
    Widget widget = Widget::Auto;

    OptionGetter get;     // the value as the CLI writes it ("300", "0.25", "on", "views"); one per entry
    OptionSetter setter;  // parses and checks one value (repeatable rows append)
    std::function<void(void*)> clear;  // repeatable rows: empties the list before a fresh parse

    // Rows that write several members at different costs (`--shadow pcf,dsm`) say what a change
    // between two settings costs; others take `change` and `rebuilds`.
    std::function<std::pair<SettingsChange, std::vector<std::string>>(const void*, const void*)> classify;

    // The byte ranges [first, second) of the members it binds inside its struct, for the tests that
    // check every member has a row.
    std::vector<std::pair<size_t, size_t>> members;

    // Throws std::invalid_argument with one line naming the flag when `text` is not a valid value.
    void set(void* settings, const std::string& text) const { setter(*this, settings, text); }
    std::string value(const void* settings) const;  // get() joined by ','
    bool differs(const void* a, const void* b) const { return get(a) != get(b); }
    // The row's values in words: "[1, 16384]", "[16, 16384], or 0: the shadow map's", "none|rsm|lpv".
    std::string rangeText() const;

    // Fluent additions for the tables.
    OptionRow& rebuild(std::vector<std::string> parts) { rebuilds = std::move(parts); return *this; }
    OptionRow& orSpecial(double v, std::string meaning) { special = v; specialMeaning = std::move(meaning); return *this; }
    OptionRow& inGroup(std::string g) { group = std::move(g); return *this; }
    OptionRow& shownAs(Widget w) { widget = w; return *this; }
};

struct OptionTable {
    std::string module;  // "rsm": the JSON object and the default rebuild target
    std::string title;   // the viewer's panel and the help's section: "Reflective shadow maps"
    std::type_index type = typeid(void);  // the settings struct the rows are written for
    std::vector<OptionRow> rows;

    const OptionRow* find(const std::string& flag) const;
    // The flag of the row bound to the member at `offset` (messages written outside the table).
    const std::string& flagAt(size_t offset) const;
    // The flag of the row bound to `access(S&)`, e.g. flagOf<RsmSettings>([](auto& s) -> auto& { return s.res; }).
    template <class S, class Access>
    const std::string& flagOf(Access access) const;
};

// Checks the current values of every Integer, Real and Choice row of `table` in `settings` (a struct
// of the table's type) against the rows' ranges: settings built in code meet the CLI's rules.
// Throws std::invalid_argument naming the flag.
void checkRanges(const OptionTable& table, const void* settings);

// Parsing shared by the generated rows (each throws std::invalid_argument naming `row.flag`).
double parseOptionNumber(const OptionRow& row, const std::string& text);
bool parseOptionBool(const OptionRow& row, const std::string& text);
std::string formatOptionNumber(double v);
[[noreturn]] void refuseOption(const OptionRow& row, const std::string& text, const std::string& why);

namespace detail {
template <class S, class Access>
std::pair<size_t, size_t> memberRange(Access access) {
    static S probe{};
    const auto& m = access(probe);
    const auto* base = reinterpret_cast<const char*>(&probe);
    const size_t offset = size_t(reinterpret_cast<const char*>(&m) - base);
    return {offset, offset + sizeof(m)};
}
template <class S>
S& as(void* p) { return *static_cast<S*>(p); }
template <class S>
S& as(const void* p) { return *const_cast<S*>(static_cast<const S*>(p)); }
}  // namespace detail

template <class S, class Access>
const std::string& OptionTable::flagOf(Access access) const {
    return flagAt(detail::memberRange<S>(access).first);
}

// Builds a table over settings struct S. Rows take an accessor `T& (S&)` (a lambda), so nested
// members (`s.cascades.count`) and plain ones are written alike.
template <class S>
class OptionTableBuilder {
public:
    OptionTableBuilder(std::string module, std::string title) {
        table_.module = std::move(module);
        table_.title = std::move(title);
        table_.type = typeid(S);
    }

    template <class Access>
    OptionRow& integer(const char* flag, const char* key, Access access, double min, double max,
                       SettingsChange change, const char* help) {
        OptionRow& row = add(flag, key, access, OptionKind::Integer, change, help);
        row.min = min, row.max = max;
        row.get = [access](const void* s) {
            return std::vector<std::string>{std::to_string(access(detail::as<S>(s)))};
        };
        row.setter = [access](const OptionRow& r, void* s, const std::string& text) {
            using T = std::remove_cvref_t<decltype(access(detail::as<S>(s)))>;
            access(detail::as<S>(s)) = T(parseOptionNumber(r, text));
        };
        return row;
    }

    template <class Access>
    OptionRow& real(const char* flag, const char* key, Access access, double min, double max, SettingsChange change,
                    const char* help) {
        OptionRow& row = add(flag, key, access, OptionKind::Real, change, help);
        row.min = min, row.max = max;
        row.get = [access](const void* s) {
            return std::vector<std::string>{formatOptionNumber(double(access(detail::as<S>(s))))};
        };
        row.setter = [access](const OptionRow& r, void* s, const std::string& text) {
            using T = std::remove_cvref_t<decltype(access(detail::as<S>(s)))>;
            access(detail::as<S>(s)) = T(parseOptionNumber(r, text));
        };
        return row;
    }

    template <class Access>
    OptionRow& boolean(const char* flag, const char* key, Access access, SettingsChange change, const char* help) {
        OptionRow& row = add(flag, key, access, OptionKind::Bool, change, help);
        row.choices = {"on", "off"};
        row.get = [access](const void* s) {
            return std::vector<std::string>{access(detail::as<S>(s)) ? "on" : "off"};
        };
        row.setter = [access](const OptionRow& r, void* s, const std::string& text) {
            access(detail::as<S>(s)) = parseOptionBool(r, text);
        };
        return row;
    }

    template <class Access, class T>
    OptionRow& choice(const char* flag, const char* key, Access access, std::vector<std::pair<std::string, T>> named,
                      SettingsChange change, const char* help) {
        OptionRow& row = add(flag, key, access, OptionKind::Choice, change, help);
        for (const auto& [name, v] : named) row.choices.push_back(name);
        row.get = [access, named](const void* s) {
            const T current = access(detail::as<S>(s));
            for (const auto& [name, v] : named)
                if (v == current) return std::vector<std::string>{name};
            return std::vector<std::string>{"?"};
        };
        row.setter = [access, named](const OptionRow& r, void* s, const std::string& text) {
            for (const auto& [name, v] : named)
                if (name == text) return void(access(detail::as<S>(s)) = v);
            refuseOption(r, text, "is not one of " + r.rangeText());
        };
        return row;
    }

    // A row whose value the module parses and prints itself (compound values, lists). `access`
    // names the member it fills, for the coverage tests (return it by reference).
    template <class Access>
    OptionRow& text(const char* flag, const char* key, Access access, std::function<std::vector<std::string>(const S&)> get,
                    std::function<void(S&, const std::string&)> set, SettingsChange change, const char* help) {
        OptionRow& row = add(flag, key, access, OptionKind::Text, change, help);
        row.get = [get](const void* s) { return get(detail::as<S>(s)); };
        row.setter = [set](const OptionRow& r, void* s, const std::string& text) {
            try {
                set(detail::as<S>(s), text);
            } catch (const std::invalid_argument& e) {
                refuseOption(r, text, e.what());
            }
        };
        return row;
    }

    // Another member the last row writes (compound rows).
    template <class Access>
    void alsoWrites(Access access) { table_.rows.back().members.push_back(detail::memberRange<S>(access)); }

    OptionTable build() { return std::move(table_); }

private:
    template <class Access>
    OptionRow& add(const char* flag, const char* key, Access access, OptionKind kind, SettingsChange change,
                   const char* help) {
        OptionRow& row = table_.rows.emplace_back();
        row.flag = flag;
        row.key = key;
        row.help = help;
        row.kind = kind;
        row.change = change;
        row.group = table_.title;
        row.members = {detail::memberRange<S>(access)};
        return row;
    }
    OptionTable table_;
};

}  // namespace penumbra
