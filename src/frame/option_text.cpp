#include "frame/option_text.h"

#include <cstdio>
#include <stdexcept>

#include <fmt/format.h>

#include "frame/frame_options.h"
#include "renderer/render_options.h"

namespace penumbra {
namespace {

const std::string& flagOfReference(const std::string& ref, const std::vector<const OptionTable*>& tables) {
    const size_t dot = ref.find('.');
    if (dot != std::string::npos)
        for (const OptionTable* t : tables)
            if (t->module == ref.substr(0, dot))
                for (const OptionRow& r : t->rows)
                    if (r.key == ref.substr(dot + 1)) return r.flag;
    throw std::logic_error("help text refers to {" + ref + "}, which is no option row");
}

}  // namespace

std::vector<const OptionTable*> frameOptionTables() {
    std::vector<const OptionTable*> tables;
    for (const BoundOptionTable& t : renderOptionTables()) tables.push_back(t.table);
    tables.push_back(&frameInputOptions());
    tables.push_back(&motionOptions());
    return tables;
}

std::string longFlag(const std::string& flag) {
    const size_t comma = flag.rfind(',');
    return comma == std::string::npos ? flag : flag.substr(comma + 1);
}

std::string expandOptionReferences(const std::string& text, const std::vector<const OptionTable*>& tables) {
    std::string out;
    size_t at = 0;
    for (size_t open = text.find('{'); open != std::string::npos; open = text.find('{', at)) {
        const size_t close = text.find('}', open);
        const std::string ref = close == std::string::npos ? "" : text.substr(open + 1, close - open - 1);
        if (ref.empty() || ref.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_.") != std::string::npos) {
            out += text.substr(at, open + 1 - at);
            at = open + 1;
            continue;
        }
        out += text.substr(at, open - at) + longFlag(flagOfReference(ref, tables));
        at = close + 1;
    }
    return out + text.substr(at);
}

std::string withFlags(const std::string& message, const std::vector<const OptionTable*>& tables) {
    try {
        return expandOptionReferences(message, tables);
    } catch (const std::logic_error&) {
        return message;
    }
}

std::string optionHelp(const OptionRow& row, const std::vector<const OptionTable*>& tables) {
    const std::string help = expandOptionReferences(row.help, tables);
    if (row.kind == OptionKind::Integer || row.kind == OptionKind::Real) return help + " " + row.rangeText();
    return help;
}

void printFrameWarning(const std::string& message) {
    fmt::print(stderr, "penumbra: warning: {}\n", withFlags(message, frameOptionTables()));
}

}  // namespace penumbra
