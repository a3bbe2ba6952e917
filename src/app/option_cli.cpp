#include "app/option_cli.h"

#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "app/bench.h"
#include "app/cli_app.h"
#include "app/frame_options.h"
#include "app/ground_truth_cli.h"
#include "app/stability.h"

namespace penumbra {
namespace {

// Every table a help text may refer to: the frame pipeline's, the frame inputs' and the commands'.
std::vector<const OptionTable*> referableTables() {
    std::vector<const OptionTable*> tables;
    for (const BoundOptionTable& t : renderOptionTables()) tables.push_back(t.table);
    for (const OptionTable* t : {&frameInputOptions(), &motionOptions(), &renderCommandOptions(),
                                 &benchCommandOptions(), &globalOptions(), &referenceSceneOptions(),
                                 &referenceCommandOptions(), &compareCommandOptions(), &evalCommandOptions(),
                                 &stabilityCommandOptions()})
        tables.push_back(t);
    return tables;
}

const std::string& flagOfReference(const std::string& ref) {
    const size_t dot = ref.find('.');
    if (dot != std::string::npos)
        for (const OptionTable* t : referableTables())
            if (t->module == ref.substr(0, dot))
                for (const OptionRow& r : t->rows)
                    if (r.key == ref.substr(dot + 1)) return r.flag;
    throw std::logic_error("help text refers to {" + ref + "}, which is no option row");
}

// The long form of a row's flag ("-o,--output" -> "--output").
std::string longFlag(const std::string& flag) {
    const size_t comma = flag.rfind(',');
    return comma == std::string::npos ? flag : flag.substr(comma + 1);
}

std::string helpOf(const OptionRow& row) {
    const std::string help = expandOptionReferences(row.help);
    if (row.kind == OptionKind::Integer || row.kind == OptionKind::Real) return help + " " + row.rangeText();
    return help;
}

// Which row each option was made from. Keyed by the option's address: an App that is destroyed
// leaves entries behind, so a lookup also checks that the option still carries the row's flag.
std::map<const CLI::Option*, const OptionRow*>& rowsOfOptions() {
    static std::map<const CLI::Option*, const OptionRow*> rows;
    return rows;
}

}  // namespace

const OptionRow* optionRowOf(const CLI::Option* option) {
    const auto found = rowsOfOptions().find(option);
    if (found == rowsOfOptions().end()) return nullptr;
    return option->check_name(longFlag(found->second->flag)) ? found->second : nullptr;
}

std::string expandOptionReferences(const std::string& help) {
    std::string out;
    size_t at = 0;
    for (size_t open = help.find('{'); open != std::string::npos; open = help.find('{', at)) {
        const size_t close = help.find('}', open);
        const std::string ref = close == std::string::npos ? "" : help.substr(open + 1, close - open - 1);
        if (ref.empty() || ref.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_.") != std::string::npos) {
            out += help.substr(at, open + 1 - at);
            at = open + 1;
            continue;
        }
        out += help.substr(at, open - at) + longFlag(flagOfReference(ref));
        at = close + 1;
    }
    return out + help.substr(at);
}

std::string withFlags(const std::string& message) {
    try {
        return expandOptionReferences(message);
    } catch (const std::logic_error&) {
        return message;
    }
}

void printWarning(const std::string& message) { fmt::print(stderr, "penumbra: warning: {}\n", withFlags(message)); }

void addOptionRows(CLI::App& cmd, const OptionTable& table, void* settings,
                   const std::function<bool(const OptionRow&)>& only) {
    for (const OptionRow& r : table.rows) {
        if (only && !only(r)) continue;
        const OptionRow* row = &r;  // tables are static: their rows outlive every App
        auto set = [row, settings](const std::string& v) {
            try {
                row->set(settings, v);
            } catch (const std::invalid_argument& e) {
                throw CLI::ValidationError(e.what());
            }
        };
        CLI::Option* opt = nullptr;
        if (row->bareFlag) {
            opt = cmd.add_flag_function(row->flag, [set](int64_t n) { set(n > 0 ? "on" : "off"); }, helpOf(*row));
        } else if (row->repeatable) {
            opt = cmd.add_option_function<std::vector<std::string>>(
                row->flag,
                [row, settings, set](const std::vector<std::string>& values) {
                    row->clear(settings);
                    for (const std::string& v : values) set(v);
                },
                helpOf(*row));
        } else {
            opt = cmd.add_option_function<std::string>(row->flag, set, helpOf(*row));
        }
        if (!row->bareFlag) {
            opt->type_name(row->kind == OptionKind::Text ? row->rangeText()
                           : row->kind == OptionKind::Integer ? "INT"
                           : row->kind == OptionKind::Real    ? "FLOAT"
                                                              : row->rangeText());
            const std::string current = row->value(settings);
            if (!current.empty()) opt->default_str(current);
        }
        opt->group(row->group);
        rowsOfOptions()[opt] = row;
    }
}

void addRenderOptionRows(CLI::App& cmd, RenderSettings& settings) {
    for (const BoundOptionTable& t : renderOptionTables()) addOptionRows(cmd, *t.table, t.at(settings));
}

}  // namespace penumbra
