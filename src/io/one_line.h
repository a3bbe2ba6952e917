// Messages from third-party parsers (tinygltf, tinyexr) may span lines and quote raw bytes of a
// corrupt file; the CLI prints every error as one printable line.
#pragma once
#include <string>

namespace penumbra {

inline std::string oneLine(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && out.back() != ' ') out += "; ";
        } else {
            out += (c >= 0x20 && c < 0x7f) ? c : '?';
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    return out.empty() ? "unknown error" : out;
}

}  // namespace penumbra
