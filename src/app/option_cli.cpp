#include "app/option_cli.h"

#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "app/bench.h"
#include "app/cli_app.h"
#include "app/ground_truth_cli.h"
#include "app/stability.h"
#include "frame/option_text.h"

namespace penumbra {
namespace {

// Every table a help text may refer to: the frame pipeline's, the frame inputs' and the commands'.
std::vector<const OptionTable*> referableTables() {
    std::vector<const OptionTable*> tables = frameOptionTables();
    for (const OptionTable* t : {&renderCommandOptions(), &benchCommandOptions(), &globalOptions(),
                                 &referenceSceneOptions(), &referenceCommandOptions(), &compareCommandOptions(),
                                 &evalCommandOptions(), &stabilityCommandOptions()})
        tables.push_back(t);
    return tables;
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

std::string expandOptionReferences(const std::string& help) { return expandOptionReferences(help, referableTables()); }

std::string withFlags(const std::string& message) { return withFlags(message, referableTables()); }

void printWarning(const std::string& message) { fmt::print(stderr, "penumbra: warning: {}\n", withFlags(message)); }

void addOptionRows(CLI::App& cmd, const OptionTable& table, void* settings,
                   const std::function<bool(const OptionRow&)>& only) {
    for (const OptionRow& r : table.rows) {
        if (only && !only(r)) continue;
        const OptionRow* row = &r;  // tables are static: their rows outlive every App
        const std::string help = optionHelp(*row, referableTables());
        auto set = [row, settings](const std::string& v) {
            try {
                row->set(settings, v);
            } catch (const std::invalid_argument& e) {
                throw CLI::ValidationError(e.what());
            }
        };
        CLI::Option* opt = nullptr;
        if (row->bareFlag) {
            opt = cmd.add_flag_function(row->flag, [set](int64_t n) { set(n > 0 ? "on" : "off"); }, help);
        } else if (row->repeatable) {
            opt = cmd.add_option_function<std::vector<std::string>>(
                row->flag,
                [row, settings, set](const std::vector<std::string>& values) {
                    row->clear(settings);
                    for (const std::string& v : values) set(v);
                },
                help);
        } else {
            opt = cmd.add_option_function<std::string>(row->flag, set, help);
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
