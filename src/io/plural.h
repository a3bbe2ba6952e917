// A count and its noun for messages: "1 light", "3 lights".
#pragma once
#include <cstddef>
#include <string>

namespace penumbra {

inline std::string plural(size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

}  // namespace penumbra
