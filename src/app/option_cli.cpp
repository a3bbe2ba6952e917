#include "app/option_cli.h"

#include <stdexcept>

namespace penumbra {
namespace {

std::string helpOf(const OptionRow& row) {
    if (row.kind == OptionKind::Integer || row.kind == OptionKind::Real) return row.help + " " + row.rangeText();
    return row.help;
}

}  // namespace

void addOptionRows(CLI::App& cmd, const OptionTable& table, void* settings) {
    for (const OptionRow& r : table.rows) {
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
    }
}

void addRenderOptionRows(CLI::App& cmd, RenderSettings& settings) {
    for (const BoundOptionTable& t : renderOptionTables()) addOptionRows(cmd, *t.table, t.at(settings));
}

}  // namespace penumbra
